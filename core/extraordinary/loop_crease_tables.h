#pragma once
// Exact tables of Loop nodes at an irregular corner of a mesh with creases: the construction of
// core/extraordinary/loop_extraordinary_tables.h (powers of one step A, the nets Ā_k of the three regular
// children, limit masks at the vertex; the same layout, so the same evaluation on CPU and GPU), taken
// from the node's neighbourhood by signature (core/extraordinary/neighbourhood_signature.h), whose sharp
// edges and vertices the crease rules read. Darts, crease vertices with other than three triangles on
// a side, and corners all take such a table.
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "core/patches/local_mesh.h"
#include "core/reference/loop.h"

namespace gps {

class LoopCreaseTables {
public:
  explicit LoopCreaseTables(LoopBeta beta) : beta_(beta) {}
  /// The table of triangle (v, a, b) of m (in face order, v its one irregular corner), computed on first
  /// use, and its neighbourhood's points in table order in `points`; null where the neighbourhood is not
  /// self-similar (one more level of plan is needed). Safe to call from several threads.
  std::shared_ptr<const std::vector<double>> table(const LocalMesh& m, int v, int a, int b, std::vector<int>& points);

private:
  std::shared_ptr<const std::vector<double>> compute(const std::vector<int>& signature) const;

  LoopBeta beta_;
  std::mutex mutex_;
  std::map<std::vector<int>, std::shared_ptr<const std::vector<double>>> tables_;
};

}  // namespace gps
