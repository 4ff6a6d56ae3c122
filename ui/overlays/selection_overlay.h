#pragma once
// Drawing the selected edges and faces over the 3D view in the edge and face selection modes
// (Dear ImGui draw lists, under the handles).
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "ui/editing/selection.h"
#include "view/projection.h"

struct ImDrawList;

namespace gps {

/// In edge and face mode: the selected `edges` as lines in the highlight colour, and (face mode) the
/// selected `faces` shaded and outlined. Only what faces the camera is drawn: an edge of at least one
/// camera-facing face, a camera-facing face (a boundary edge always). Nothing in vertex mode (the
/// handle overlay dots the selected vertices).
void draw_selection_overlay(ImDrawList& draw, const Viewport& view, const CovarianceMesh& mesh,
                            const std::vector<EdgeEnds>& edges, const std::vector<int>& faces, SelectMode mode);

}  // namespace gps
