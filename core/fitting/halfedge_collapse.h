#pragma once
// Greedy decimation of a triangle mesh by halfedge collapses in order of a caller's priority, each
// collapse keeping the topology, manifoldness, features and face orientations.
#include <cstddef>
#include <functional>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "core/mesh/covariance_mesh.h"
#include "core/support/progress.h"

namespace gps {

struct CollapseMeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
/// The decimation's own triangle mesh: OpenMesh's, with double-precision points.
using CollapseMesh = OpenMesh::TriMesh_ArrayKernelT<CollapseMeshTraits>;

inline Vec3 to_vec3(const OpenMesh::Vec3d& p) { return Vec3(p[0], p[1], p[2]); }
inline OpenMesh::Vec3d to_point(const Vec3& v) { return OpenMesh::Vec3d(v[0], v[1], v[2]); }

struct HalfedgeCollapses {
  /// The priority of collapsing `from` into `into` (which keeps its position), lower first; a
  /// negative one forbids it. Called again for the halfedges around a collapse.
  std::function<float(CollapseMesh::VertexHandle from, CollapseMesh::VertexHandle into)> priority;
  /// Called after each collapse of `from` into `into`.
  std::function<void(CollapseMesh::VertexHandle from, CollapseMesh::VertexHandle into)> collapsed;
  double max_normal_deviation_degrees = 45;  // the most a collapse may turn a face's normal
  ProgressReport progress;                   // the fraction of the collapses asked for that are done
};

/// Collapses halfedges of `mesh` (which has vertex, edge and face status) in order of priority
/// until `target_vertices` remain or no collapse is allowed, as OpenMesh's DecimaterT with its normal
/// flipping module does: a collapse keeps the link condition (the one-rings of its ends share only
/// the vertices opposite its edge), moves no locked vertex, moves a feature vertex only along a
/// feature edge and a boundary vertex only along the boundary, and turns no face's normal by more
/// than the limit. Each vertex's best collapse waits in a heap by priority alone; the tests that look
/// at the one-rings are done when it comes first, where one found forbidden gives way to the vertex's
/// next best (DecimaterT tests every candidate of a vertex whenever it chooses). Leaves the deleted
/// elements for garbage_collection; returns the vertices left. Throws Cancelled when the progress
/// report asks it to stop.
size_t collapse_halfedges(CollapseMesh& mesh, size_t target_vertices, const HalfedgeCollapses& collapses);

}  // namespace gps
