#pragma once
// The crease tool's values (Blender's Shift+E Edge Crease, on OpenSubdiv's sharpness): a horizontal
// drag or a typed number sets the sharpness of the selected edges, or the corner sharpness of the
// selected vertices; kInfiniteSharpness (10) and above is infinitely sharp, shown as "∞". With
// mirror editing on, the mirror images of the edges and vertices take the same sharpness.
#include <array>
#include <string>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/modelling/mesh_arrays.h"
#include "ui/editing/edit_reach.h"
#include "ui/editing/selection.h"

namespace gps {

/// The window pixels a drag must cover to go from smooth to infinitely sharp: a fraction of the
/// viewport's width, so that the whole range fits in a comfortable drag.
float crease_drag_span(float viewport_width);

/// The sharpness after a horizontal drag of `dx` pixels from `start`, in [0, kInfiniteSharpness],
/// rounded to tenths (each distinct value re-plans the surface).
double sharpness_after_drag(double start, float dx, float viewport_width);

/// "∞" from kInfiniteSharpness on, else the value with two decimals ("2.50").
std::string sharpness_text(double sharpness);

/// The colour of a crease or corner of this sharpness, RGBA in [0, 1]: from the cage's grey at 0 to
/// a strong magenta at ∞, linear in between.
std::array<float, 4> crease_colour(double sharpness);

/// The sharpness the edges share, or NaN for a mixed selection (0 for none).
double common_crease(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges);
/// The corner sharpness the vertices share, or NaN for a mixed selection (0 for none).
double common_corner(const CovarianceMesh& mesh, const std::vector<int>& vertices);

/// The edges with, where mirror editing is on, their mirror images that are edges of the mesh too
/// (each once, a < b, sorted).
std::vector<std::array<int, 2>> with_mirrored_edges(const CovarianceMesh& mesh,
                                                    const std::vector<std::array<int, 2>>& edges,
                                                    const ReachOptions& reach);
/// The vertices with, where mirror editing is on, their mirror images (ascending, unique).
std::vector<int> with_mirrored_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices,
                                        const ReachOptions& reach);

/// The mesh with the selected edges (Selection::edges) at `sharpness`, or with `corners` the
/// selected vertices' corner sharpness, their mirror images too where mirror editing is on
/// (core/modelling/crease_edges.h's set_crease and set_corner, which refuse as they do).
Modelled sharpened_selection(const CovarianceMesh& mesh, const Selection& selection, bool corners, double sharpness,
                             const ReachOptions& reach);

}  // namespace gps
