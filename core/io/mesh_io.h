#pragma once
// Reading and writing meshes by file extension (docs/design.md §4).
#include <string>
#include <vector>

#include "core/io/mesh_repair.h"
#include "core/mesh/covariance_mesh.h"

namespace gps {

struct ImportOptions {
  enum class Covariance { infer, isotropic } covariance = Covariance::infer;
  double bias = 0.05;            // for inference (GPS paper Eq. 16)
  double isotropic_scale = 0.5;  // σ = scale × mean edge length at the vertex
  // Repair of the faces as read, before the mesh is built and covariances inferred (core/io/mesh_repair.h).
  bool repair = false;
  double weld_tolerance = 1e-6;  // as a fraction of the bounding-box diagonal
  ProgressReport repair_progress;  // the repair's (RepairOptions::progress)
};

/// Reads .ply (a covariance PLY keeps its covariances; a plain one gets them from `options`),
/// .obj, .off, .stl (covariances from `options`), .gltf and .glb (its "_COVARIANCE", else from
/// `options`). Throws gps::Error naming the file, also for a mesh
/// without faces (every use of a mesh needs its surface). Without `options.repair`, a topology that
/// repair would mend (not manifold, a face using a vertex twice or with all its corners at one point)
/// is refused naming each class, its count, its first example as the file numbers it and what
/// --repair does (RepairReport::refusal); with it, `report` (where given) gets what the repair did.
/// `notes` (where given) gets what the reader read leniently (PolygonSoup::notes), for the caller to show.
CovarianceMesh read_mesh(const std::string& path, const ImportOptions& options = {}, RepairReport* report = nullptr,
                         std::vector<std::string>* notes = nullptr);

/// The polygon soup of a mesh file as read_mesh reads it before repairing or building it;
/// `has_covariances` says whether the file gave them.
PolygonSoup read_polygon_soup(const std::string& path, bool& has_covariances);

/// read_mesh from the soup read_polygon_soup gave for `path` (its notes left to the caller). `diagnosis`, where given,
/// is diagnose_polygon_soup of that soup (gpsurf info has it); else a refused file is read again for one.
CovarianceMesh read_mesh_of_soup(PolygonSoup&& soup, bool has_covariances, const std::string& path,
                                 const ImportOptions& options = {}, RepairReport* report = nullptr,
                                 const RepairReport* diagnosis = nullptr);

/// The vertices of the mesh file at `path` as points, its faces not made into a mesh (it may have none,
/// or not be a manifold, as scans are): for what measures points only (compare's A, fit's target).
/// Throws gps::Error naming the file where it has no vertices. `faces`, where given, gets its faces as
/// read (for the points' normals).
std::vector<Vec3> read_points(const std::string& path, PolygonTopology* faces = nullptr);

/// The repair options read_mesh uses: the tolerance of `options`.
RepairOptions repair_options_for(const ImportOptions& options = {});

/// How messages number the elements of the file at `path`: from 1 in OBJ (with the lines of the
/// elements `report`'s examples name: the file is read again for them), from 0 elsewhere.
ElementNumbering element_numbering_for(const std::string& path, const RepairReport& report);

/// How messages name the elements of the mesh file at `path` as read_mesh builds it without a
/// repair: an OBJ file's from 1 with their lines (the file read again only when a message names
/// one), the others' by index from 0.
ElementNames file_element_names(const std::string& path);

/// Writes .ply (covariances and sharpness kept; ASCII or binary little endian), .obj (positions,
/// faces, and creases and corners as OpenSubdiv's tags) or .gltf/.glb (triangles, vertex normals and
/// covariances in float; core/io/gltf_io.h),
/// atomically: a temporary file beside the target, then a rename.
void write_mesh(const std::string& path, const CovarianceMesh& mesh, bool binary = false);
/// What write_mesh would refuse of `path` whatever the mesh, checked before the work that makes one: a
/// format it does not write (a usage error), a target inspect_save_target refuses (a folder, a
/// read-only file, a folder that does not exist).
void check_mesh_output(const std::string& path);

/// What a save of `mesh` to `path` cannot keep, as a note for the user ("" when it keeps it all):
/// glTF has no place for creases and corners.
std::string unsaved_sharpness_note(const std::string& path, const CovarianceMesh& mesh);

/// The lower-case extension of a path, with the dot (".ply"), or "" when there is none.
std::string extension_of(const std::string& path);

}  // namespace gps
