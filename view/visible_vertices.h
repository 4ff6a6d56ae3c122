#pragma once
// Which control-mesh vertices the camera sees: a software depth buffer of the control mesh at the
// viewport's resolution, without GL, so that a box selection can leave out what the surface hides.
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "view/projection.h"

namespace gps {

/// One flag per vertex: whether the vertex is visible in `view`. The control mesh's faces (fanned
/// into triangles) are rasterised at pixel centres into a depth buffer that keeps the front-most
/// face at each pixel. A vertex is visible when it projects inside the window, in the depth range,
/// and at its pixel either nothing is drawn, one of its own faces is front-most, or it lies no
/// further than a tolerance (a thousandth of the mesh's bounding-box diagonal) behind the front-most
/// face. A vertex all of whose faces turn away from the camera is visible only through an opening (the
/// far rim of a tube's open end): one of its faces is drawn in the 3×3 pixels around it and no other
/// face lies in front of it there by more than the tolerance. Time: linear in the mesh plus the pixels its
/// faces cover.
std::vector<char> visible_vertices(const Viewport& view, const CovarianceMesh& mesh);

}  // namespace gps
