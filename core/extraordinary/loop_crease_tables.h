#pragma once
// Exact tables of Loop nodes at an irregular corner of a mesh with creases: the construction of
// core/extraordinary/loop_extraordinary_tables.h (powers of one step A, the nets Ā_k of the three regular
// children, limit masks at the vertex; the same layout, so the same evaluation on CPU and GPU), taken
// from the node's neighbourhood by signature (core/extraordinary/neighbourhood_signature.h), whose sharp
// edges and vertices the crease rules read. Darts, crease vertices with other than three triangles on
// a side, and corners all take such a table.
#include <map>
#include <vector>

#include "core/plans/local_mesh.h"
#include "core/reference/loop.h"

namespace gps {

class LoopCreaseTables {
public:
  explicit LoopCreaseTables(LoopBeta beta) : beta_(beta) {}
  /// Offset of the table of triangle (v, a, b) of m (in face order, v its one irregular corner), and
  /// its neighbourhood's points in table order in `points`; −1 where the neighbourhood is not
  /// self-similar (one more level of plan is needed).
  int offset(const LocalMesh& m, int v, int a, int b, std::vector<int>& points);
  std::vector<double> take() { return std::move(tables_); }

private:
  int compute(const std::vector<int>& signature);

  LoopBeta beta_;
  std::map<std::vector<int>, int> offsets_;
  std::vector<double> tables_;
};

}  // namespace gps
