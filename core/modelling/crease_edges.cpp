#include "core/modelling/crease_edges.h"

#include <algorithm>
#include <sstream>
#include <string>

#include "core/mesh/crease_by_angle.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"

namespace gps {

namespace {

void check_sharpness(double s) {
  if (const std::string why = sharpness_problem(s); !why.empty()) {
    std::ostringstream text;
    text << "sharpness " << s << " " << why;
    throw Error(text.str());
  }
}

// "2.5", "10 (infinitely sharp)" or "0 (smooth)" for a summary.
std::string sharpness_words(double s) {
  std::ostringstream text;
  text << s << (s <= 0.0 ? " (smooth)" : is_infinitely_sharp(s) ? " (infinitely sharp)" : "");
  return text.str();
}

}  // namespace

Modelled set_crease(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges, double sharpness) {
  check_sharpness(sharpness);
  const MeshArrays arrays = arrays_of(mesh);
  const DirectedEdges directed = directed_edges(arrays);
  Modelled out{mesh, {}, ""};
  for (const auto& [a, b] : edges) {
    check_vertex(arrays, a);
    check_vertex(arrays, b);
    if (a == b || !has_edge(directed, a, b))
      throw Error("edge " + std::to_string(a) + "–" + std::to_string(b) + " is not in the mesh");
    out.mesh.sharpness.set_crease(a, b, sharpness);
    out.selection.insert(out.selection.end(), {a, b});
  }
  std::sort(out.selection.begin(), out.selection.end());
  out.selection.erase(std::unique(out.selection.begin(), out.selection.end()), out.selection.end());
  out.summary = "set the crease of " + count_of(edges.size(), "edge", "edges") + " to " + sharpness_words(sharpness);
  return out;
}

Modelled crease_sharp_edges(const CovarianceMesh& mesh, double degrees, double sharpness) {
  if (!(degrees >= 0 && degrees < 180))
    throw Error("the angle must be from 0 to less than 180 degrees, got " + short_number(degrees));
  check_sharpness(sharpness);
  const std::vector<double> angles = dihedral_angles(mesh);
  std::vector<std::array<int, 2>> sharp;
  for (const auto e : mesh.mesh.edges())
    if (angles[size_t(e.idx())] > degrees) {
      const auto h = mesh.mesh.halfedge_handle(e, 0);
      sharp.push_back({mesh.mesh.from_vertex_handle(h).idx(), mesh.mesh.to_vertex_handle(h).idx()});
    }
  Modelled out = set_crease(mesh, sharp, sharpness);
  out.summary = "set the crease of " + count_of(sharp.size(), "edge", "edges") + " sharper than " +
                short_number(degrees) + "° to " + sharpness_words(sharpness);
  return out;
}

Modelled set_corner(const CovarianceMesh& mesh, const std::vector<int>& vertices, double sharpness) {
  check_sharpness(sharpness);
  const MeshArrays arrays = arrays_of(mesh);
  Modelled out{mesh, sorted_vertices(arrays, vertices), ""};
  for (const int v : out.selection) out.mesh.sharpness.set_corner(v, sharpness, int(mesh.n_vertices()));
  out.summary =
      "set the corner of " + count_of(out.selection.size(), "vertex", "vertices") + " to " + sharpness_words(sharpness);
  return out;
}

}  // namespace gps
