#pragma once
// Exact evaluation of Loop patches at an extraordinary vertex (Stam 1998, "Evaluation of Loop
// subdivision surfaces"). Around a triangle (v, a, b) whose corner v is extraordinary and a, b are
// regular, the K points of loop_extraordinary_neighbourhood() at level n + 1 are A times those at level n
// (A: K×K, one Loop step), and the nets of the three regular children are Ā_k times them. A point
// at (s, t) lies, after n halvings toward v, in a regular child k: it is the box spline of the net
// Ā_k Aⁿ C. Stam diagonalises A; we store the products Ā_k Aⁿ for n < kExtraordinaryLevels (powers of a
// matrix whose eigenvalues are at most 1 in size: stable, and exact also where A is not
// diagonalisable, as at some boundary configurations), and A itself for the levels past them (C
// stepped by A first). At v the limit position and tangent masks apply
// (core/extraordinary/extraordinary_corner_masks.h). GPS is linear in 9D, so all of this acts on the dual points.
//
// Table layout (doubles from its offset): blocks b = 3n + k, each 12×K (row j: the weights of the
// K points in net point j), then three rows of K: limit position, tangent along s, tangent along t,
// then A: K rows of K (row r: the weights of the K points in point r one level down).
#include <compare>

#include <Eigen/Core>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "core/reference/loop.h"
#include "core/patches/patch_basis.h"
#include "core/mesh/mesh_connectivity.h"

namespace gps {

/// What A depends on: an interior vertex's valence, or a boundary vertex's face count and the
/// position of the triangle in its fan (counted counter-clockwise from the boundary).
struct LoopExtraordinaryConfiguration {
  bool boundary = false;
  int faces = 0;
  int fan_position = 0;
  auto operator<=>(const LoopExtraordinaryConfiguration&) const = default;
};

/// The tables of every configuration met while building one set of plans, shared by the threads: one
/// per configuration (A and the nets depend on nothing else), computed on first use.
class LoopExtraordinaryTableCache {
public:
  explicit LoopExtraordinaryTableCache(LoopBeta beta) : beta_(beta) {}
  /// The table of `configuration`, on first use computed from the triangle (v, a, b) of `mesh`, a mesh
  /// refined at least once around v (a and b regular, the rings read complete). Safe to call from
  /// several threads.
  std::shared_ptr<const std::vector<double>> table(const LoopExtraordinaryConfiguration& configuration,
                                                   const PolygonTopology& mesh, const MeshConnectivity& connectivity,
                                                   int v, int a, int b);

private:
  std::shared_ptr<const std::vector<double>> compute(const PolygonTopology& mesh, const MeshConnectivity& connectivity,
                                                     int v, int a, int b) const;

  LoopBeta beta_;
  std::mutex mutex_;
  std::map<LoopExtraordinaryConfiguration, std::shared_ptr<const std::vector<double>>> tables_;
};

/// Writes the table of a node (layout above) from one step A (`step`, K×K) and the nets Ā_k of its three
/// regular children (12×K each) into `table`, loop_extraordinary_table_size(K) doubles.
void write_loop_extraordinary_table(const Eigen::MatrixXd (&nets)[3], const Eigen::MatrixXd& step, double* table);

/// Doubles in the table of a node with K points.
inline size_t loop_extraordinary_table_size(int k) { return size_t(36 * kExtraordinaryLevels + 3 + k) * size_t(k); }

}  // namespace gps
