#pragma once
// The memory of a search structure for distances to triangles (CGAL's AABB tree over the triangles as
// CGAL stores them, with its search tree of distance queries), known before it is built, so that a
// measurement that cannot fit is refused with its figures before the work starts.
namespace gps {

/// The bytes the triangles, their AABB tree and its search tree hold: a measured upper bound per
/// triangle.
double distance_tree_bytes(double triangles);

}  // namespace gps
