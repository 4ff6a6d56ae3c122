#pragma once
// One mesh told as a change of another: what it takes over from the other (runs of vertices and of
// faces) and what it has of its own. A modelling operation's result told this way against the mesh
// before it, and the mesh before told against the result, cost memory in proportion to what the
// operation changed: what an undo history keeps instead of the whole meshes.
#include <cstddef>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

/// The elements first .. first + count − 1 of a mesh are those source_first .. of another.
struct TakenRun {
  int first = 0, source_first = 0, count = 0;
  bool operator==(const TakenRun&) const = default;
};

/// A mesh as a change of a source mesh (mesh_delta, apply_delta).
struct MeshDelta {
  int n_vertices = 0;
  /// The vertices that continue one of the source's, in runs; the others are new.
  std::vector<TakenRun> vertex_runs;
  /// The vertices whose Gaussian is not the source's (new ones, moved ones): index, mean, covariance.
  std::vector<int> own_gaussians;
  std::vector<Vec3> means;
  std::vector<Mat3> covariances;
  /// The faces that are one of the source's, corners renumbered, in runs; the others listed with
  /// their corners (faces[i]: the corners own_corners[own_offsets[i] .. own_offsets[i + 1])).
  std::vector<TakenRun> face_runs;
  std::vector<int> own_faces, own_offsets{0}, own_corners;
  int n_faces = 0;
  Sharpness sharpness;

  /// The memory it holds, in bytes.
  size_t bytes() const;
};

/// Per vertex of a mesh of `n_to` vertices, the vertex of a mesh of `n_from` that mesh_delta takes it
/// over from given `origin` (−1 new): vertex_sources of that delta, without making it.
std::vector<int> delta_vertex_sources(size_t n_from, size_t n_to, const std::vector<int>& origin);

/// `to` as a change of `from`, given per vertex of `to` its index in `from` (−1 new; empty: the
/// indices kept where both have the vertex). A face of `to` is taken over where `from` has a face with
/// the same corners renumbered; vertices are told apart by that correspondence, not by position.
MeshDelta mesh_delta(const CovarianceMesh& from, const CovarianceMesh& to, const std::vector<int>& origin);

/// `forward` (a mesh `after` as a change of `before`) and `back` (`before` as a change of `after`), made
/// to tell `now` instead: `after` with the Gaussians of `vertices` changed, `was_means` and
/// `was_covariances` theirs in `after` (a vertex listed twice: its first). What mesh_delta gives each
/// way for `now` (with the vertex sources each already has), at the cost of the vertices changed: an
/// operation and the move that follows it told as one change.
void retell_gaussians(MeshDelta& forward, MeshDelta& back, const CovarianceMesh& now, const std::vector<int>& vertices,
                      const std::vector<Vec3>& was_means, const std::vector<Mat3>& was_covariances);

/// Per vertex of the mesh `delta` tells: its index in the source (−1 new).
std::vector<int> vertex_sources(const MeshDelta& delta);

/// The mesh `delta` tells, made from `from` (the mesh it was told against): byte for byte the mesh it
/// was made from, its connectivity carried over from `from`'s where the faces stay (and `from`'s faces
/// and connectivity shared where every vertex and face stays at its index: a crease's or a move's undo).
CovarianceMesh apply_delta(const CovarianceMesh& from, const MeshDelta& delta);

}  // namespace gps
