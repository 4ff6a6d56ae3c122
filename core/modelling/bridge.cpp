#include "core/modelling/bridge.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

#include "core/support/error.h"

namespace gps {

namespace {

// A run of boundary vertices ordered along the faces' boundary edges (vertices[k] → vertices[k+1] is
// a face's edge); closed when it is a whole loop.
struct BoundaryRun {
  std::vector<int> vertices;
  bool closed = false;
};

// The boundary edges of the faces, a → b with no face on b → a: next[a] = b, previous[b] = a.
struct BoundaryEdges {
  std::vector<int> next, previous;
};

BoundaryEdges boundary_edges(const MeshArrays& a, const DirectedEdges& edges) {
  BoundaryEdges b{std::vector<int>(size_t(a.n_vertices()), -1), std::vector<int>(size_t(a.n_vertices()), -1)};
  for (const auto& face : a.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      const int u = face[k], w = face[(k + 1) % face.size()];
      if (edges.count(directed_key(w, u)) == 0) {
        b.next[size_t(u)] = w;
        b.previous[size_t(w)] = u;
      }
    }
  return b;
}

// The selected vertices split into runs along the boundary edges joining them.
std::vector<BoundaryRun> boundary_runs(const BoundaryEdges& b, const std::vector<int>& selected) {
  std::unordered_map<int, bool> in;  // vertex → visited
  for (int v : selected) {
    if (b.next[size_t(v)] < 0) throw Error("vertex " + std::to_string(v) + " is not on a boundary");
    in[v] = false;
  }
  const auto selected_next = [&](int v, const std::vector<int>& step) {
    const int w = step[size_t(v)];
    return in.count(w) ? w : -1;
  };
  std::vector<BoundaryRun> runs;
  for (int v : selected) {
    if (in[v]) continue;
    int start = v;  // walk back to the run's first vertex (or once around a loop)
    while (selected_next(start, b.previous) >= 0 && selected_next(start, b.previous) != v)
      start = selected_next(start, b.previous);
    BoundaryRun run;
    for (int w = start; w >= 0 && !in[w]; w = selected_next(w, b.next)) {
      in[w] = true;
      run.vertices.push_back(w);
    }
    run.closed = run.vertices.size() >= 3 && selected_next(run.vertices.back(), b.next) == run.vertices.front();
    runs.push_back(std::move(run));
  }
  return runs;
}

// The one run the vertices make, refusing anything else.
BoundaryRun one_run(const BoundaryEdges& b, const std::vector<int>& vertices) {
  std::vector<BoundaryRun> runs = boundary_runs(b, vertices);
  if (runs.size() != 1)
    throw Error("vertex " + std::to_string(runs[1].vertices.front()) + " is not joined to vertex " +
                std::to_string(runs[0].vertices.front()) + " along the boundary: not one loop or chain");
  return runs.front();
}

std::string count_text(size_t n, const std::string& what) { return std::to_string(n) + " " + what; }

Modelled bridge_runs(const MeshArrays& arrays, const BoundaryRun& first, const BoundaryRun& second) {
  MeshArrays a = arrays;
  const std::vector<int>& p = first.vertices;
  const std::vector<int>& q = second.vertices;
  const size_t n = p.size();
  if (first.closed != second.closed) throw Error("cannot bridge a closed boundary loop to an open chain");
  if (n < 2) throw Error("a chain to bridge needs at least 2 vertices");
  // p[i] pairs with q[(s − i) mod n]: the quads then run against both runs' boundary edges.
  size_t best = n - 1;
  if (first.closed) {
    double best_cost = std::numeric_limits<double>::infinity();
    for (size_t s = 0; s < n; ++s) {
      double cost = 0;
      for (size_t i = 0; i < n; ++i)
        cost += (a.means[size_t(p[i])] - a.means[size_t(q[(s + n - i) % n])]).squaredNorm();
      if (cost < best_cost) best_cost = cost, best = s;
    }
  }
  const auto partner = [&](size_t i) { return q[(best + n - i % n) % n]; };
  const size_t quads = first.closed ? n : n - 1;
  for (size_t i = 0; i < quads; ++i) a.faces.push_back({p[(i + 1) % n], p[i], partner(i), partner(i + 1)});
  std::vector<int> selection = p;
  selection.insert(selection.end(), q.begin(), q.end());
  std::sort(selection.begin(), selection.end());
  return {build_mesh(a), selection,
          "bridged two " + std::string(first.closed ? "loops" : "chains") + " of " + count_text(n, "vertices") + ": " +
              count_text(quads, quads == 1 ? "face" : "faces") + " added"};
}

}  // namespace

Modelled bridge(const CovarianceMesh& mesh, const std::vector<int>& loop_a, const std::vector<int>& loop_b) {
  const MeshArrays a = arrays_of(mesh);
  const std::vector<int> sa = sorted_vertices(a, loop_a), sb = sorted_vertices(a, loop_b);
  if (sa.size() != loop_a.size() || sb.size() != loop_b.size()) throw Error("a vertex is listed twice in a loop");
  for (int v : sa)
    if (std::binary_search(sb.begin(), sb.end(), v)) throw Error("vertex " + std::to_string(v) + " is in both loops");
  if (sa.size() != sb.size())
    throw Error("loops of " + std::to_string(sa.size()) + " and " + std::to_string(sb.size()) +
                " vertices: bridge needs equal lengths");
  if (sa.size() < 2) throw Error("a chain to bridge needs at least 2 vertices");
  const BoundaryEdges b = boundary_edges(a, directed_edges(a));
  return bridge_runs(a, one_run(b, sa), one_run(b, sb));
}

Modelled bridge_selected(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  const MeshArrays a = arrays_of(mesh);
  const BoundaryEdges b = boundary_edges(a, directed_edges(a));
  const std::vector<BoundaryRun> runs = boundary_runs(b, sorted_vertices(a, vertices));
  if (runs.size() != 2)
    throw Error("the selection makes " + std::to_string(runs.size()) +
                " boundary loops or chains; bridge needs exactly 2");
  if (runs[0].vertices.size() != runs[1].vertices.size())
    throw Error("loops of " + std::to_string(runs[0].vertices.size()) + " and " +
                std::to_string(runs[1].vertices.size()) + " vertices: bridge needs equal lengths");
  return bridge_runs(a, runs[0], runs[1]);
}

}  // namespace gps
