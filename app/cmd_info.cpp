// gpsurf info FILE: counts, valences, shape, scheme, creases and covariance ranges of a mesh, and
// every defect the repair finds in it.
#include <Eigen/Eigenvalues>
#include <iostream>
#include <map>

#include "app/commands.h"
#include "app/repair_arguments.h"
#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/io/mesh_io.h"
#include "core/plans/planned_surface.h"

namespace gps {

namespace {

const char* scheme_name(Scheme scheme) { return scheme == Scheme::loop ? "Loop" : "Catmull-Clark"; }

std::string plural(int n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

// Parts, boundary loops and genus of a manifold surface, on one line.
std::string surface_line(const SurfaceCounts& s) {
  return plural(s.parts, "part", "parts") + ", " + plural(s.boundary_loops, "boundary loop", "boundary loops") +
         ", genus " + std::to_string(s.genus);
}

void print_problems(const std::vector<std::string>& lines, const std::string& heading) {
  if (lines.empty()) return;
  std::cout << heading << ":\n";
  for (const std::string& line : lines) std::cout << "  " << line << "\n";
}

// What --repair makes of the file, found by building the soup the repair changed (`done` says how) as
// --repair builds it: the `after --repair:` line with the mesh's counts, shape and scheme, or, where it
// is still refused, what the repair cannot mend (numbered as the file numbers it) or the refusal.
std::string after_repair(PolygonSoup&& repaired, bool has_covariances, const std::string& path, ImportOptions options,
                         const RepairReport& done) {
  if (repaired.faces.n_faces() == 0) return "after --repair: no faces left\n";
  // What read_mesh_of_soup names after a repair: the parts it cannot orient.
  RepairReport unmended;
  const size_t d = size_t(Defect::unorientable_parts);
  unmended.counts[d] = done.counts[d];
  unmended.examples[d] = done.examples[d];
  options.repair = false;  // done
  try {
    const CovarianceMesh m = read_mesh_of_soup(std::move(repaired), has_covariances, path, options, nullptr, &unmended);
    return "after --repair: " + plural(int(m.n_vertices()), "vertex", "vertices") + ", " +
           plural(int(m.n_faces()), "face", "faces") + ", " +
           surface_line(surface_counts(m.topology(), m.connectivity())) + ", scheme " +
           scheme_name(scheme_for(m.topology(), PlanOptions{})) + "\n";
  } catch (const Error& e) {
    const ElementNumbering numbering = element_numbering_for(path, unmended);
    std::vector<std::string> lines = unmended.problems(numbering, true);
    if (lines.empty()) lines.push_back(e.what());
    std::string out =
        "after --repair: refused for (vertices and faces numbered from " + std::to_string(numbering.base) + "):\n";
    for (const std::string& line : lines) out += "  " + line + "\n";
    return out;
  }
}

// Without --repair the file is diagnosed first (the repair's own detection): a mesh
// read_mesh refuses gets every problem class with its count and first examples, numbered as the file
// numbers them, and what a repair would leave, then the refusal itself (exit 1); a mesh that is read
// gets the classes it is read with (coincident, isolated vertices, zero-area faces) after its counts.
void print_info(const std::string& path, const RepairArguments& repair) {
  const ImportOptions options = repair.import_options();
  RepairReport diagnosis;
  std::string repaired;  // the after --repair lines
  const CovarianceMesh m = [&] {
    if (options.repair) return read_mesh_repairing(path, repair);
    bool has_covariances = false;
    PolygonSoup soup = read_polygon_soup(path, has_covariances);
    print_reader_notes(soup.notes);
    const size_t n_vertices = soup.positions.size();
    const int n_faces = soup.faces.n_faces();
    if (n_faces > 0) {  // else refused as it is: no surface to diagnose
      // Diagnosed by running the repair on the soup itself, not a copy (memory follows the file), and
      // building what it made: a soup the repair changed is read again; one it left as it is is the file's.
      diagnosis = repair_polygon_soup(soup, repair_options_for(options));
      if (diagnosis.changed() || diagnosis.count(Defect::unorientable_parts) > 0) {
        repaired = after_repair(std::move(soup), has_covariances, path, options, diagnosis);
        soup = PolygonSoup();
        soup = read_polygon_soup(path, has_covariances);
      }
    }
    try {
      return read_mesh_of_soup(std::move(soup), has_covariances, path, options, nullptr, &diagnosis);
    } catch (const Error&) {
      if (!diagnosis.changed() && diagnosis.count(Defect::unorientable_parts) == 0) throw;
      const ElementNumbering numbering = element_numbering_for(path, diagnosis);
      std::cout << "file: " << path << "\nvertices: " << n_vertices << "\nfaces: " << n_faces << "\n";
      const std::string numbered = " (vertices and faces numbered from " + std::to_string(numbering.base) + ")";
      std::vector<std::string> refused = diagnosis.problems(numbering, true),
                               also = diagnosis.problems(numbering, false);
      // A class read as it is can still be why (a zero-area face that puts a third face on an edge):
      // where no class that refuses was found, those found are the reasons.
      if (refused.empty()) std::swap(refused, also);
      print_problems(refused, "refused for" + numbered);
      print_problems(also, "also");
      std::cout << repaired << std::flush;
      throw;
    }
  }();
  // The counts are read off the mesh's own connectivity: no second adjacency of the size of the mesh.
  std::map<int, int> face_sizes, valences;
  for (size_t f = 0; f < m.n_faces(); ++f) ++face_sizes[m.face_size(f)];
  // Extraordinary by the rules of the scheme the surface is drawn with: regular interior valence 4
  // and boundary 3 under Catmull-Clark, 6 and 4 under Loop (a corner, of one face and two edges, is
  // neither).
  const Scheme scheme = scheme_for(m.topology(), PlanOptions{});
  const int regular_interior = scheme == Scheme::loop ? 6 : 4, regular_boundary = scheme == Scheme::loop ? 4 : 3;
  int boundary_edges = 0, extraordinary = 0;
  for (size_t e = 0; e < m.n_edges(); ++e) boundary_edges += m.is_boundary_edge(e);
  for (size_t v = 0; v < m.n_vertices(); ++v) {
    const int valence = m.valence(v);
    ++valences[valence];
    if (valence == 0) continue;
    extraordinary +=
        m.is_boundary_vertex(v) ? valence != 2 && valence != regular_boundary : valence != regular_interior;
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
  std::cout << ")\nedges: " << m.n_edges() << "\nboundary edges: " << boundary_edges << "\nvalences:";
  for (const auto& [valence, count] : valences) std::cout << ' ' << valence << ':' << count;
  std::cout << "\nsurface: " << surface_line(surface_counts(m.topology(), m.connectivity()))
            << "\nscheme: " << (scheme == Scheme::loop ? "Loop (a mesh of triangles)" : "Catmull-Clark")
            << "\nextraordinary vertices: " << extraordinary << " (by " << scheme_name(scheme) << "'s rules)\n";
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
  if (diagnosis.changed()) {
    const ElementNumbering numbering = element_numbering_for(path, diagnosis);
    // Classes that refuse a mesh can show up here where the weld makes them (an unwelded soup).
    std::vector<std::string> lines = diagnosis.problems(numbering, true);
    for (std::string& line : diagnosis.problems(numbering, false)) lines.push_back(std::move(line));
    print_problems(lines, "read as they are (--repair mends them; vertices and faces numbered from " +
                              std::to_string(numbering.base) + ")");
    std::cout << repaired;
  }
}
}  // namespace

void add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Print counts, valences, creases and covariance ranges of a mesh");
  auto path = std::make_shared<std::string>();
  auto repair = std::make_shared<RepairArguments>();
  cmd->add_option("file", *path, "mesh file (.ply, .obj, .off, .stl, .gltf, .glb)")->required();
  add_repair_arguments(cmd, *repair);
  cmd->callback([path, repair] { print_info(*path, *repair); });
}

}  // namespace gps
