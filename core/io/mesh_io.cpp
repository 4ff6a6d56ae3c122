#include "core/io/mesh_io.h"

#include <algorithm>
#include <filesystem>

#include "core/io/atomic_file.h"
#include "core/mesh/error.h"
#include "core/mesh/inference.h"
#include "core/io/mesh_import.h"
#include "core/io/ply_io.h"
#include "core/io/quoted_text.h"
#include "core/io/text_file.h"

namespace gps {

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

CovarianceMesh read_mesh(const std::string& path, const ImportOptions& options) {
  const std::string ext = extension_of(path);
  if (ext != ".ply" && ext != ".obj" && ext != ".off" && ext != ".stl")
    throw Error(escaped(path) + ": unknown mesh format " + quoted_token(ext) + " (use .ply, .obj, .off or .stl)");
  std::string data = read_text_file(path, ext == ".ply"   ? HeadCheck(check_ply_head)
                                          : ext == ".stl" ? check_stl_head
                                                          : check_text_head);
  bool has_covariances = false;
  // Built in place: OpenMesh's meshes have no move, so an assignment would copy the whole mesh.
  CovarianceMesh mesh = [&]() -> CovarianceMesh {
    if (ext == ".ply") return parse_ply(std::move(data), path, has_covariances);
    if (ext == ".obj") return parse_obj(std::move(data), path);
    if (ext == ".off") return parse_off(std::move(data), path);
    return parse_stl(std::move(data), path);
  }();
  // Every command and the editor draw or measure a surface: Gaussians without faces have none.
  if (mesh.n_faces() == 0) throw Error(escaped(path) + ": the mesh has no faces");
  if (has_covariances) return mesh;
  try {
    if (options.covariance == ImportOptions::Covariance::infer)
      infer_covariances(mesh, options.bias);
    else
      isotropic_covariances(mesh, options.isotropic_scale);
  } catch (const Error& e) {
    throw Error(escaped(path) + ": " + e.what(), e.kind());
  }
  validate_gaussians(mesh, escaped(path));
  return mesh;
}

void write_mesh(const std::string& path, const CovarianceMesh& mesh, bool binary) {
  const std::string ext = extension_of(path);
  // What gpsurf writes it must read back: refuse values the readers would refuse.
  if (const std::string why = gaussians_problem(mesh); !why.empty())
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
      for (const auto f : mesh.mesh.faces()) {
        out << 'f';
        for (const auto v : mesh.mesh.fv_range(f)) out << ' ' << v.idx() + 1;
        out << '\n';
      }
    });
  } else {
    throw usage_error(escaped(path) + ": cannot write format " + quoted_token(ext) + " (use .ply or .obj)");
  }
}

}  // namespace gps
