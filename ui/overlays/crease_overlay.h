#pragma once
// Drawing the mesh's creases and corners over the 3D view (Dear ImGui draw lists, with the cage):
// creased edges thicker and coloured by their sharpness (crease_colour: grey to magenta at ∞),
// corners as squares in the same colours. As the selection overlay, only what faces the camera, and
// nothing hidden.
#include "core/mesh/covariance_mesh.h"
#include "ui/editing/hidden_elements.h"
#include "view/projection.h"

struct ImDrawList;

namespace gps {

void draw_crease_overlay(ImDrawList& draw, const Viewport& view, const CovarianceMesh& mesh,
                         const HiddenElements* hidden = nullptr);

}  // namespace gps
