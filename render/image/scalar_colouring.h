#pragma once
// A rendered surface coloured by a scalar field: each covered pixel's colour replaced by a named
// colormap's colour of the scalar there, shaded by the pixel's brightness. No GL.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/mesh/linalg.h"
#include "render/image/image.h"

namespace gps {

/// The colour (sRGB in [0, 1]) of `t` clamped to [0, 1] on the colormap "viridis", "coolwarm" or "gray"
/// (piecewise linear through matplotlib's colours at 0, ¼, ½, ¾ and 1). Throws gps::Error for another name.
std::array<float, 3> colormap_colour(const std::string& colormap, double t);

/// True for a name colormap_colour() knows.
bool is_colormap(const std::string& colormap);

/// `colour` (RGBA) with every pixel that `positions` (the render target's world-position AOV, w ≥ 1
/// where drawn) covers coloured by `scalars_at(its positions)` on `colormap` over [low, high],
/// times its brightness relative to the brightest covered pixel.
void colour_by_scalars(Image& colour, const Image& positions, const std::string& colormap, double low, double high,
                       const std::function<std::vector<double>(const std::vector<Vec3>&)>& scalars_at);

}  // namespace gps
