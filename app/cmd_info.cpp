// gpsurf info FILE: counts, valences, creases and covariance ranges of a mesh.
#include <Eigen/Eigenvalues>
#include <iostream>
#include <map>

#include "app/commands.h"
#include "app/repair_arguments.h"
#include "core/mesh/error.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/io/mesh_io.h"
#include "core/plans/planned_surface.h"

namespace gps {

namespace {
// A mesh read_mesh refuses: every problem class the repair finds in it (the same code, on a copy),
// with examples numbered as the file numbers them, and the parts and boundary loops a repair would
// leave; then the refusal itself (exit 1). A file the readers refuse is only refused.
[[noreturn]] void print_problems(const std::string& path, const Error& refusal) {
  bool has_covariances = false;
  PolygonSoup soup;
  try {
    soup = read_polygon_soup(path, has_covariances);
  } catch (const Error&) {
    throw refusal;
  }
  if (soup.faces.n_faces() == 0) throw refusal;  // no surface to diagnose
  const RepairReport report = diagnose_polygon_soup(soup, repair_options_for(path));
  const auto problems = report.problems();
  if (problems.empty()) throw refusal;
  std::cout << "file: " << path << "\nvertices: " << soup.positions.size() << "\nfaces: " << soup.faces.n_faces()
            << "\nproblems (vertices and faces numbered from " << repair_options_for(path).numbering_base
            << " as the file numbers them):\n";
  for (const std::string& line : problems) std::cout << "  " << line << "\n";
  std::cout << "after --repair: " << report.parts << (report.parts == 1 ? " part" : " parts");
  if (report.boundary_loops >= 0)
    std::cout << ", " << report.boundary_loops << (report.boundary_loops == 1 ? " boundary loop" : " boundary loops");
  std::cout << "\n" << std::flush;
  throw refusal;
}

void print_info(const std::string& path, const RepairArguments& repair) {
  const CovarianceMesh m = [&] {
    try {
      return read_mesh_repairing(path, repair);
    } catch (const Error& e) {
      if (repair.import_options().repair) throw;
      print_problems(path, e);
    }
  }();
  const PolygonTopology t = topology_of(m.mesh);
  const MeshConnectivity c = connectivity_of(t);
  std::map<int, int> face_sizes, valences;
  for (int f = 0; f < t.n_faces(); ++f) ++face_sizes[t.face_size(f)];
  // Extraordinary by the rules of the scheme the surface is drawn with: regular interior valence 4
  // and boundary 3 under Catmull-Clark, 6 and 4 under Loop.
  const Scheme scheme = scheme_for(t, PlanOptions{});
  const int regular_interior = scheme == Scheme::loop ? 6 : 4, regular_boundary = scheme == Scheme::loop ? 4 : 3;
  int boundary_edges = 0, extraordinary = 0;
  for (int e = 0; e < c.n_edges(); ++e) boundary_edges += c.is_boundary_edge(e);
  for (int v = 0; v < t.n_vertices; ++v) {
    ++valences[c.valence(v)];
    const VertexRole role = vertex_role(c, v);
    extraordinary += (role == VertexRole::interior && c.valence(v) != regular_interior) ||
                     (role == VertexRole::boundary && c.valence(v) != regular_boundary);
  }
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (const Mat3& s : m.covariances) {
    const Vec3 eigenvalues = Eigen::SelfAdjointEigenSolver<Mat3>(s, Eigen::EigenvaluesOnly).eigenvalues();
    lo = std::min(lo, eigenvalues(0));
    hi = std::max(hi, eigenvalues(2));
  }
  std::cout << "file: " << path << "\nvertices: " << m.n_vertices() << "\nfaces: " << m.n_faces() << " (";
  const char* sep = "";
  for (const auto& [size, count] : face_sizes)
    std::cout << std::exchange(sep, ", ") << count << " with " << size << " sides";
  std::cout << ")\nedges: " << c.n_edges() << "\nboundary edges: " << boundary_edges << "\nvalences:";
  for (const auto& [valence, count] : valences) std::cout << ' ' << valence << ':' << count;
  std::cout << "\nscheme: " << (scheme == Scheme::loop ? "Loop (a mesh of triangles)" : "Catmull-Clark")
            << "\nextraordinary vertices: " << extraordinary << " (by "
            << (scheme == Scheme::loop ? "Loop" : "Catmull-Clark") << "'s rules)\n";
  std::cout << "covariance eigenvalues: " << lo << " .. " << hi << "\n";
  // Creases and corners (docs/design.md §1): semi-sharp ones decay over levels, the others stay sharp.
  int semi_sharp = 0, infinitely_sharp = 0, corners = 0, sharp_corners = 0;
  for (const EdgeCrease& crease : m.sharpness.creases)
    ++(is_infinitely_sharp(crease.sharpness) ? infinitely_sharp : semi_sharp);
  for (const double s : m.sharpness.corners)
    if (s > 0.0) ++(is_infinitely_sharp(s) ? sharp_corners : corners);
  std::cout << "creased edges: " << semi_sharp + infinitely_sharp << " (" << semi_sharp << " semi-sharp, "
            << infinitely_sharp << " infinitely sharp)\ncorners: " << corners + sharp_corners << " (" << corners
            << " semi-sharp, " << sharp_corners << " infinitely sharp)\n";
}
}  // namespace

void add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Print counts, valences, creases and covariance ranges of a mesh");
  auto path = std::make_shared<std::string>();
  auto repair = std::make_shared<RepairArguments>();
  cmd->add_option("file", *path, "mesh file (.ply, .obj, .off, .stl)")->required();
  add_repair_arguments(cmd, *repair);
  cmd->callback([path, repair] { print_info(*path, *repair); });
}

}  // namespace gps
