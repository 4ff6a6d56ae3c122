#pragma once
// Simplifying a dense triangle mesh (a scan) into a coarse covariance mesh by edge collapses, each
// coarse vertex carrying the Gaussian of the input region that collapsed into it.
#include <cstddef>

#include "core/mesh/covariance_mesh.h"
#include "core/support/progress.h"

namespace gps {

struct SimplifyOptions {
  size_t target_vertices = 0;                // the vertex count asked for
  double bias = 0.05;                        // thickness of the face discs across their planes (GPS paper Eq. 16)
  double max_normal_deviation_degrees = 45;  // the most a collapse may turn a face's normal
  /// With > 0: no collapse whose merged region's faces would lie further than this from the position
  /// kept, as the rms distance of their planes (the region's quadric error over three times its area:
  /// each face's plane is in the quadrics of its three corners), over the input's bounding-box diagonal.
  double max_error = 0;
  /// Pairs the result's triangles into quads where they make nearly square, flat ones
  /// (core/fitting/triangle_pairing.h): a quad-dominant mesh for Catmull-Clark modelling.
  bool quads = false;
  ProgressReport progress;                   // the fraction of the collapses asked for that are done
};

struct SimplifiedMesh {
  CovarianceMesh mesh;
  size_t input_vertices = 0, input_triangles = 0;
  bool triangulated = false;  // whether the input had faces of more than 3 sides, fanned into triangles
  size_t quads = 0;           // with options.quads, the quads made of pairs of triangles
};

/// Collapses edges of `input` (faces of more than three sides fanned into triangles first) in order
/// of quadric error (Garland and Heckbert 1997, with boundary planes that keep the boundary's shape;
/// near-ties to the collapse that makes the smaller region) until `options.target_vertices` remain
/// or no collapse may be done without changing the topology (genus, boundary loops), making a face
/// non-manifold, turning a face's normal by more than the limit or, with `max_error`, exceeding it. A coarse vertex
/// keeps the position of the input vertex it is; its covariance comes from the input faces of its region, the input
/// vertices collapsed into it (see the .cpp). The input's creases stay creases: a vertex on one
/// collapses only along it, so the coarse creases follow the input's; its corners and the vertices
/// where creases meet or end do not move. Throws gps::Error for a target below 4 vertices, or where
/// a face of more sides has no corner to fan it from that keeps every edge manifold; Cancelled when the progress
/// report asks it to stop.
SimplifiedMesh simplify_mesh(const CovarianceMesh& input, const SimplifyOptions& options);

}  // namespace gps
