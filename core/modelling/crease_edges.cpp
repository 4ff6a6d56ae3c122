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

std::vector<int> set_crease_in_place(CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                                     double sharpness, std::string& summary) {
  check_sharpness(sharpness);
  std::vector<int> selection;
  for (const auto& [a, b] : edges) {
    check_vertex(mesh.n_vertices(), a);
    check_vertex(mesh.n_vertices(), b);
    if (a == b || mesh.find_edge(a, b) < 0)
      throw Error("edge " + std::to_string(a) + "–" + std::to_string(b) + " is not in the mesh");
    selection.insert(selection.end(), {a, b});
  }
  std::vector<int> distinct;  // each edge once, however often and whichever way round it is listed
  for (const auto& [a, b] : edges) {
    mesh.sharpness.set_crease(a, b, sharpness);
    distinct.push_back(mesh.find_edge(a, b));
  }
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  std::sort(selection.begin(), selection.end());
  selection.erase(std::unique(selection.begin(), selection.end()), selection.end());
  summary = "set the crease of " + count_of(distinct.size(), "edge", "edges") + " to " + sharpness_words(sharpness);
  return selection;
}

Modelled set_crease(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges, double sharpness) {
  Modelled out{mesh, {}, "", {}, {}};
  out.selection = set_crease_in_place(out.mesh, edges, sharpness, out.summary);
  return out;
}

Modelled crease_sharp_edges(const CovarianceMesh& mesh, double degrees, double sharpness) {
  if (!(degrees >= 0 && degrees < 180))
    throw Error("the angle must be from 0 to less than 180 degrees, got " + short_number(degrees));
  check_sharpness(sharpness);
  const std::vector<std::array<int, 2>> sharp = edges_sharper_than(mesh, degrees);
  Modelled out = set_crease(mesh, sharp, sharpness);
  out.summary = "set the crease of " + count_of(sharp.size(), "edge", "edges") + " sharper than " +
                short_number(degrees) + "° to " + sharpness_words(sharpness);
  return out;
}

std::vector<int> set_corner_in_place(CovarianceMesh& mesh, const std::vector<int>& vertices, double sharpness,
                                     std::string& summary) {
  check_sharpness(sharpness);
  std::vector<int> selection = sorted_vertices(mesh.n_vertices(), vertices);
  for (const int v : selection) mesh.sharpness.set_corner(v, sharpness, int(mesh.n_vertices()));
  summary =
      "set the corner of " + count_of(selection.size(), "vertex", "vertices") + " to " + sharpness_words(sharpness);
  return selection;
}

Modelled set_corner(const CovarianceMesh& mesh, const std::vector<int>& vertices, double sharpness) {
  Modelled out{mesh, {}, "", {}, {}};
  out.selection = set_corner_in_place(out.mesh, vertices, sharpness, out.summary);
  return out;
}

}  // namespace gps
