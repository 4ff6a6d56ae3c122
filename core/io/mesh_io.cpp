#include "core/io/mesh_io.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "core/io/atomic_file.h"
#include "core/support/error.h"
#include "core/mesh/inference.h"
#include "core/io/gltf_io.h"
#include "core/io/mesh_import.h"
#include "core/io/ply_io.h"
#include "core/io/save_target.h"
#include "core/support/quoted_text.h"
#include "core/io/text_file.h"

namespace gps {

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

PolygonSoup read_polygon_soup(const std::string& path, bool& has_covariances) {
  const std::string ext = extension_of(path);
  const bool gltf = ext == ".gltf" || ext == ".glb";
  if (ext != ".ply" && ext != ".obj" && ext != ".off" && ext != ".stl" && !gltf)
    throw Error(escaped(path) + ": unknown mesh format " + quoted_token(ext) +
                " (use .ply, .obj, .off, .stl, .gltf or .glb)");
  std::string data = read_text_file(path, ext == ".ply"   ? HeadCheck(check_ply_head)
                                          : ext == ".stl" ? check_stl_head
                                          : gltf          ? check_gltf_head
                                                          : check_text_head);
  has_covariances = false;
  if (gltf) {
    // A .gltf's buffer files are named relative to its folder.
    const std::string folder = std::filesystem::absolute(path).parent_path().string();
    return parse_gltf_soup(data, path, folder, has_covariances);
  }
  if (ext != ".stl") drop_byte_order_mark(data);  // a binary STL's header is any 80 bytes
  if (ext == ".ply") return parse_ply_soup(std::move(data), path, has_covariances);
  if (ext == ".obj") return parse_obj_soup(std::move(data), path);
  if (ext == ".off") return parse_off_soup(std::move(data), path);
  return parse_stl_soup(std::move(data), path);
}

std::vector<Vec3> read_points(const std::string& path, PolygonTopology* faces) {
  bool has_covariances = false;
  PolygonSoup soup = read_polygon_soup(path, has_covariances);
  if (soup.positions.empty()) throw Error(escaped(path) + ": has no vertices");
  if (faces) *faces = std::move(soup.faces);
  return std::move(soup.positions);
}

RepairOptions repair_options_for(const ImportOptions& options) {
  RepairOptions o;
  o.weld_tolerance = options.weld_tolerance;
  o.progress = options.repair_progress;
  return o;
}

ElementNumbering element_numbering_for(const std::string& path, const RepairReport& report) {
  ElementNumbering numbering;
  if (extension_of(path) != ".obj") return numbering;
  numbering.base = 1;
  std::vector<int> vertices, faces;
  report.named_elements(vertices, faces);
  if (vertices.empty() && faces.empty()) return numbering;
  try {
    find_obj_lines(read_text_file(path, check_text_head), vertices, faces, numbering);
  } catch (const Error&) {  // gone since it was read: the elements are named without their lines
  }
  return numbering;
}

ElementNames file_element_names(const std::string& path) {
  if (extension_of(path) != ".obj") return {};
  return obj_element_names([path] { return read_text_file(path, check_text_head); });
}

CovarianceMesh read_mesh(const std::string& path, const ImportOptions& options, RepairReport* report,
                         std::vector<std::string>* notes) {
  bool has_covariances = false;
  PolygonSoup soup = read_polygon_soup(path, has_covariances);
  if (notes) *notes = std::move(soup.notes);
  return read_mesh_of_soup(std::move(soup), has_covariances, path, options, report);
}

CovarianceMesh read_mesh_of_soup(PolygonSoup&& soup, bool has_covariances, const std::string& path,
                                 const ImportOptions& options, RepairReport* report, const RepairReport* diagnosis) {
  // Every command and the editor draw or measure a surface: Gaussians without faces have none.
  const auto no_faces = [&](const char* after) { return Error(escaped(path) + ": the mesh has no faces" + after); };
  if (soup.faces.n_faces() == 0) throw no_faces("");
  RepairReport done;
  // A repaired soup's elements are no longer the file's: its messages number them from 0.
  const ElementNames names = options.repair ? ElementNames{} : file_element_names(path);
  if (options.repair) {
    done = repair_polygon_soup(soup, repair_options_for(options));
    if (report) *report = done;
    if (soup.faces.n_faces() == 0)
      throw no_faces(options.weld_tolerance > 0
                         ? " left after repair (each was degenerate, of zero area or a duplicate at this weld "
                           "tolerance; a smaller --weld keeps more)"
                         : " left after repair (each was degenerate, of zero area or a duplicate)");
  }
  // A refusal names the defect classes that cause it, as a diagnosis of the file finds them (read
  // again where none was given: only a refused file pays for it), and what --repair does; after a
  // repair, only what it could not mend. Where the faces were built (`built`), the Gaussians were
  // refused: the message stays, followed by every class found.
  const auto refused = [&](const Error& e, bool built) {
    RepairReport found;
    if (options.repair) {
      const size_t d = size_t(Defect::unorientable_parts);
      found.counts[d] = done.counts[d];
      found.examples[d] = done.examples[d];
    } else if (diagnosis) {
      found = *diagnosis;
    } else {
      try {
        bool again = false;
        found = diagnose_polygon_soup(read_polygon_soup(path, again), repair_options_for(options));
      } catch (const Error&) {
        return e;
      }
    }
    if (!built && found.refuses())
      return Error(escaped(path) + ": " + found.refusal(element_numbering_for(path, found)), e.kind());
    if (!options.repair && found.changed())
      return Error(e.what() + std::string(" (") + found.refusal(element_numbering_for(path, found), true) + ")",
                   e.kind());
    return e;
  };
  CovarianceMesh mesh = [&]() -> CovarianceMesh {
    try {
      return mesh_of_soup(std::move(soup), escaped(path), names);
    } catch (const Error& e) {
      throw refused(e, false);
    }
  }();
  if (has_covariances) return mesh;
  try {
    if (options.covariance == ImportOptions::Covariance::infer)
      infer_covariances(mesh, options.bias, names);
    else
      isotropic_covariances(mesh, options.isotropic_scale);
  } catch (const Error& e) {
    throw refused(Error(escaped(path) + ": " + e.what(), e.kind()), true);
  }
  validate_gaussians(mesh, escaped(path), names);
  return mesh;
}

namespace {

// Why the mesh's sharpness would be refused on reading ("crease 0-6 is not an edge of the mesh"), or "".
std::string sharpness_write_problem(const CovarianceMesh& m) {
  const int n = int(m.n_vertices());
  for (const EdgeCrease& c : m.sharpness.creases) {
    const std::string name = "crease " + std::to_string(c.a) + "-" + std::to_string(c.b);
    if (const std::string why = sharpness_problem(c.sharpness); !why.empty()) return name + " " + why;
    if (c.a < 0 || c.b < 0 || c.a >= n || c.b >= n) return name + " names a vertex outside the mesh";
    if (m.find_edge(c.a, c.b) < 0) return name + " is not an edge of the mesh";
  }
  std::vector<std::pair<int, int>> ends;
  for (const EdgeCrease& c : m.sharpness.creases) ends.emplace_back(std::min(c.a, c.b), std::max(c.a, c.b));
  std::sort(ends.begin(), ends.end());
  if (const auto twice = std::adjacent_find(ends.begin(), ends.end()); twice != ends.end())
    return "crease " + std::to_string(twice->first) + "-" + std::to_string(twice->second) + " is named twice";
  if (!m.sharpness.corners.empty() && m.sharpness.corners.size() != m.n_vertices())
    return std::to_string(m.sharpness.corners.size()) + " corner values for " + std::to_string(n) + " vertices";
  for (size_t v = 0; v < m.sharpness.corners.size(); ++v)
    if (const std::string why = sharpness_problem(m.sharpness.corners[v]); !why.empty())
      return "vertex " + std::to_string(v) + " corner sharpness " + why;
  return "";
}

}  // namespace

std::string unsaved_sharpness_note(const std::string& path, const CovarianceMesh& mesh) {
  const std::string ext = extension_of(path);
  if (ext != ".gltf" && ext != ".glb") return "";
  const size_t creases = mesh.sharpness.creases.size(),
               corners = size_t(std::count_if(mesh.sharpness.corners.begin(), mesh.sharpness.corners.end(),
                                              [](double s) { return s > 0.0; }));
  if (creases + corners == 0) return "";
  std::string dropped = creases > 0 ? std::to_string(creases) + (creases == 1 ? " crease" : " creases") : "";
  if (corners > 0)
    dropped += (dropped.empty() ? "" : " and ") + std::to_string(corners) + (corners == 1 ? " corner" : " corners");
  return escaped(path) + ": " + dropped + " not saved (glTF has no place for them; .ply and .obj keep them)";
}

namespace {

// The usage error of a file name whose format write_mesh does not write, or none.
void check_mesh_format(const std::string& path, const std::string& ext) {
  if (ext != ".ply" && ext != ".obj" && ext != ".gltf" && ext != ".glb")
    throw usage_error(escaped(path) + ": cannot write format " + quoted_token(ext) +
                      " (use .ply, .obj, .gltf or .glb)");
}

}  // namespace

void check_mesh_output(const std::string& path) {
  inspect_save_target(path);
  check_mesh_format(path, extension_of(path));
}

void write_mesh(const std::string& path, const CovarianceMesh& mesh, bool binary) {
  const std::string ext = extension_of(path);
  check_mesh_format(path, ext);
  // What gpsurf writes it must read back: refuse values the readers would refuse.
  if (const std::string why = gaussians_problem(mesh); !why.empty())
    throw Error(escaped(path) + ": not written: " + why);
  if (const std::string why = sharpness_write_problem(mesh); !why.empty())
    throw Error(escaped(path) + ": not written: " + why);
  if (ext == ".ply") {
    write_file_atomically(
        path, [&](std::ostream& out) { write_ply(out, mesh, binary); }, binary);
  } else if (ext == ".obj") {
    write_file_atomically(path, [&](std::ostream& out) {
      out.precision(17);
      for (size_t i = 0; i < mesh.n_vertices(); ++i) {
        const Vec3 p = mesh.mean(i);
        out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
      }
      for (size_t f = 0; f < mesh.n_faces(); ++f) {
        out << 'f';
        for (const int v : mesh.face(f)) out << ' ' << v + 1;
        out << '\n';
      }
      // OpenSubdiv's tags, vertices numbered from 0 (core/io/mesh_import.h).
      for (const EdgeCrease& c : mesh.sharpness.creases)
        out << "t crease 2/1/0 " << c.a << ' ' << c.b << ' ' << c.sharpness << '\n';
      for (size_t v = 0; v < mesh.sharpness.corners.size(); ++v)
        if (mesh.sharpness.corners[v] > 0.0) out << "t corner 1/1/0 " << v << ' ' << mesh.sharpness.corners[v] << '\n';
    });
  } else if (ext == ".gltf" || ext == ".glb") {
    // Made whole before the file is opened: a refusal leaves nothing behind.
    std::ostringstream gltf;
    try {
      write_gltf(gltf, gltf_triangles_of(mesh), ext == ".glb");
    } catch (const Error& e) {
      throw Error(escaped(path) + ": " + e.what(), e.kind());
    }
    write_file_atomically(
        path, [&](std::ostream& out) { out << gltf.view(); }, true);
  }
}

}  // namespace gps
