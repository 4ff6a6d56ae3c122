#include "core/fitting/distance_tree_size.h"

namespace gps {

namespace {

// Per triangle: its three corners as CGAL stores them (72 bytes), its primitive and its share of the
// tree's nodes (a bounding box and two links each), and its reference point in the search tree of
// distance queries, with room for the arrays' growth: an upper bound of what it was measured to take.
constexpr double kBytesPerTriangle = 340;

}  // namespace

double distance_tree_bytes(double triangles) { return kBytesPerTriangle * triangles; }

}  // namespace gps
