#include "view/silhouette_framing.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gps {

namespace {

// How far in front of the nearest point the eye stays at least, as a share of the points' extent.
constexpr double kEyeClearance = 0.1;

// The camera's orthonormal frame: right, up and forward (from the eye to the target), which depend
// on its angles and up axis alone.
struct ViewAxes {
  glm::dvec3 right, up, forward;
};

ViewAxes axes_of(const Camera& camera) {
  Camera unit = camera;
  unit.target = decltype(unit.target)(0.0);
  unit.distance = 1.0f;
  const glm::dmat4 v = unit.view_double();
  return {glm::dvec3(v[0][0], v[1][0], v[2][0]), glm::dvec3(v[0][1], v[1][1], v[2][1]),
          -glm::dvec3(v[0][2], v[1][2], v[2][2])};
}

// The points in the camera's axes (x right, y up, z forward), from the world origin.
std::vector<glm::dvec3> in_axes(const ViewAxes& a, const std::vector<glm::dvec3>& points) {
  std::vector<glm::dvec3> out;
  out.reserve(points.size());
  for (const glm::dvec3& p : points) out.emplace_back(glm::dot(p, a.right), glm::dot(p, a.up), glm::dot(p, a.forward));
  return out;
}

// The eye's offset across the view along one axis (`k` 0: x, 1: y) at eye depth `depth`, between
// `low` and `high`, that centres the points' perspective slopes (coordinate / depth) on `mid`: their
// sum of extremes less 2·mid falls as the offset grows, so bisection finds it.
double centred_offset(const std::vector<glm::dvec3>& p, int k, double depth, double low, double high, double mid) {
  const auto excess = [&](double offset) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const glm::dvec3& q : p) {
      const double slope = (q[k] - offset) / std::max(q.z - depth, 1e-300);
      lo = std::min(lo, slope);
      hi = std::max(hi, slope);
    }
    return lo + hi - 2.0 * mid;
  };
  for (int i = 0; i < 80 && low < high; ++i) {
    const double m = 0.5 * (low + high);
    (excess(m) > 0.0 ? low : high) = m;
  }
  return 0.5 * (low + high);
}

}  // namespace

NdcRect ndc_of_pixels(glm::vec2 window, glm::vec2 pixel_min, glm::vec2 pixel_max) {
  const glm::dvec2 size = glm::max(glm::dvec2(window), glm::dvec2(1.0));
  NdcRect r;
  r.lo = glm::dvec2(2.0 * pixel_min.x / size.x - 1.0, 1.0 - 2.0 * pixel_max.y / size.y);
  r.hi = glm::dvec2(2.0 * pixel_max.x / size.x - 1.0, 1.0 - 2.0 * pixel_min.y / size.y);
  return r;
}

Camera frame_silhouette(const Camera& camera, const std::vector<glm::dvec3>& points, double aspect,
                        const NdcRect& region, double margin) {
  if (points.empty()) return camera;
  const ViewAxes axes = axes_of(camera);
  const std::vector<glm::dvec3> p = in_axes(axes, points);
  glm::dvec3 lo = p[0], hi = p[0];
  for (const glm::dvec3& q : p) lo = glm::min(lo, q), hi = glm::max(hi, q);
  const glm::dvec3 centre = 0.5 * (lo + hi);
  Camera framed = camera;
  const auto place = [&](const glm::dvec3& eye, double distance) {
    const glm::dvec3 target = eye + distance * glm::dvec3(0, 0, 1);
    framed.target = decltype(framed.target)(target.x * axes.right + target.y * axes.up + target.z * axes.forward);
    framed.distance = float(distance);
  };
  if (glm::length(hi - lo) <= 0.0) {  // one point: at the target, the distance kept
    place(centre - double(camera.distance) * glm::dvec3(0, 0, 1), double(camera.distance));
    return framed;
  }
  // The region less its margin, as slopes (coordinate / depth) of the view: x scaled by the aspect.
  const double t = std::tan(glm::radians(double(camera.fov_degrees)) * 0.5), keep = 1.0 - margin;
  const glm::dvec2 scale(t * std::max(aspect, 1e-9), t);
  const glm::dvec2 mid = 0.5 * (region.lo + region.hi) * scale;
  const glm::dvec2 half = glm::max(0.5 * (region.hi - region.lo), glm::dvec2(1e-9)) * keep * scale;
  if (camera.orthographic) {
    // The view's half-height h (at the target's depth) shows a half-extent h·(half / t) of the region.
    const double h = std::max((hi.x - lo.x) * 0.5 / (half.x / t), (hi.y - lo.y) * 0.5 / (half.y / t));
    const double distance = h / t;
    place(glm::dvec3(centre.x - mid.x / t * h, centre.y - mid.y / t * h, centre.z - distance), distance);
    return framed;
  }
  // Each side of the region is a plane through the eye; pushed back until every point is inside it,
  // opposite sides meet at the eye's deepest depth for that axis (the sides' slopes are
  // mid ± half: x on the right side ≤ (mid + half)·z, on the left ≥ (mid − half)·z, as offsets from
  // the eye). The axis that asks for the farther eye decides the depth; the other is centred.
  double depth = std::numeric_limits<double>::infinity();
  glm::dvec2 bound_high(std::numeric_limits<double>::infinity()), bound_low = bound_high;
  for (int k = 0; k < 2; ++k) {
    const double high = mid[k] + half[k], low = mid[k] - half[k];
    for (const glm::dvec3& q : p) {
      bound_high[k] = std::min(bound_high[k], high * q.z - q[k]);  // ≥ high·eye_z − eye_k
      bound_low[k] = std::min(bound_low[k], q[k] - low * q.z);     // ≥ eye_k − low·eye_z
    }
    depth = std::min(depth, (bound_high[k] + bound_low[k]) / (high - low));
  }
  // The eye stays in front of the nearest point by a share of the points' extent: a silhouette seen
  // end on (a needle's tip) would otherwise draw the eye onto the surface, where the near plane cuts it.
  depth = std::min(depth, lo.z - kEyeClearance * glm::length(hi - lo));
  glm::dvec3 eye(0.0, 0.0, depth);
  for (int k = 0; k < 2; ++k) {
    const double high = mid[k] + half[k], low = mid[k] - half[k];
    eye[k] = centred_offset(p, k, depth, high * depth - bound_high[k], bound_low[k] + low * depth, mid[k]);
  }
  place(eye, std::max(centre.z - depth, 1e-6 * glm::length(hi - lo)));
  return framed;
}

NdcRect projected_bounds(const Camera& camera, const std::vector<glm::dvec3>& points, double aspect) {
  const glm::dmat4 vp = camera.view_projection_double(float(aspect));
  NdcRect r{glm::dvec2(std::numeric_limits<double>::infinity()), glm::dvec2(-std::numeric_limits<double>::infinity())};
  for (const glm::dvec3& q : points) {
    const glm::dvec4 c = vp * glm::dvec4(q, 1.0);
    const glm::dvec2 ndc = glm::dvec2(c) / c.w;
    r.lo = glm::min(r.lo, ndc);
    r.hi = glm::max(r.hi, ndc);
  }
  return r;
}

}  // namespace gps
