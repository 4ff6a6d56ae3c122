#pragma once
// Exact evaluation of Catmull-Clark patches at an extraordinary vertex (Stam 1998, "Exact
// evaluation of Catmull-Clark subdivision surfaces at arbitrary parameter values"), as
// core/extraordinary/loop_extraordinary_tables.h does for Loop. Around a quad node whose corner 0 is its one irregular
// corner, its K points (the vertices of the faces at its four corners) at level n + 1 are A times
// those at level n, and the B-spline nets of the three regular children are Ā_c times them. A
// point at (s, t) lies, after n halvings toward the vertex, in a regular child c: the bicubic
// B-spline of the net Ā_c Aⁿ C. Instead of Stam's eigen-decomposition we store the products
// Ā_c Aⁿ for n < kExtraordinaryLevels (stable, and exact also where A is not diagonalisable, as at boundary
// vertices), A itself for the levels past them (C stepped by A first), and the limit masks at the
// vertex (core/extraordinary/extraordinary_corner_masks.h). GPS is linear in 9D, so all of this acts on the dual points
// as they are.
//
// A neighbourhood is known by its signature (its faces in a canonical walk, vertices by first
// visit); the table depends on nothing else, so nodes with equal signatures share one. A node is
// evaluated this way only where refining it once gives the corner child the same signature
// (self-similar): any node one level below an irregular vertex, and most base quads.
//
// Table layout (doubles from its offset): blocks b = 3n + c − 1 (quad_extraordinary_locate() in
// core/patches/patch_basis.h), each 16×K (row j: the weights of the K points in net point j, j = i + 4·k as
// in a regular node), then three rows of K: limit position, tangent along s, tangent along t, then
// A: K rows of K (row r: the weights of the K points in point r one level down).
#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "core/extraordinary/neighbourhood_signature.h"
#include "core/patches/local_mesh.h"
#include "core/patches/patch_basis.h"

namespace gps {

/// The neighbourhood of the quad with corners c (in its face's order, c[0] the irregular one)
/// (core/extraordinary/neighbourhood_signature.h).
std::optional<NeighbourhoodSignature> quad_extraordinary_neighbourhood(const LocalMesh& m, const std::array<int, 4>& c);

/// The tables of every signature met while building one set of plans, shared by the threads.
class QuadExtraordinaryTableCache {
public:
  /// The table of `signature`, computed on first use; null where it is not self-similar.
  std::shared_ptr<const std::vector<double>> table(const std::vector<int>& signature);

private:
  std::mutex mutex_;
  std::map<std::vector<int>, std::shared_ptr<const std::vector<double>>> tables_;
};

/// Doubles in the table of a node with K points.
inline size_t quad_extraordinary_table_size(int k) { return size_t(48 * kExtraordinaryLevels + 3 + k) * size_t(k); }

}  // namespace gps
