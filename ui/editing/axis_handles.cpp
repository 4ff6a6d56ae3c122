#include "ui/editing/axis_handles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/editing/covariance_presets.h"

namespace gps {

namespace {

constexpr float kDecidePixels = 3.0f;  // cursor motion that decides between scaling and turning
constexpr double kSnapRatio = 0.1, kSnapDegrees = 5.0;

double snapped(double value, double step) { return step * std::round(value / step); }

}  // namespace

HandleFrame handle_frame(const Vec3& centre, const EllipsoidAxes& axes, double k_sigma, const Viewport& view,
                         double min_pixels) {
  HandleFrame f;
  f.centre = centre;
  f.axes = axes;
  const double floor_length = min_pixels * world_per_pixel(view.camera, view.height, f.centre);
  for (int a = 0; a < 3; ++a) f.lengths[a] = std::max(k_sigma * f.axes.sigmas[a], floor_length);
  return f;
}

HandleFrame handle_frame(const CovarianceMesh& mesh, int vertex, double k_sigma, const Viewport& view,
                         double min_pixels) {
  return handle_frame(mesh.mean(size_t(vertex)), ellipsoid_axes(mesh.covariance(size_t(vertex))), k_sigma, view,
                      min_pixels);
}

namespace {

// Ends win over a centre as near (within a pixel): they overlap it when the axes are short. An end
// drawn on the centre dot (its axis points at the viewer, as in an orthographic front view) is not
// offered: its drag could neither scale nor turn, and the dot under it must stay grabbable.
void consider(NearestProjected& nearest, std::vector<Handle>& handles, const HandleFrame& f, int vertex,
              const Viewport& view) {
  constexpr float kMinAxisPixels = 4.0f;
  const auto centre = visible_pixel(view.camera, view.width, view.height, f.centre);
  for (int axis = 0; axis < 3; ++axis)
    for (const int side : {1, -1}) {
      const auto end = visible_pixel(view.camera, view.width, view.height, f.end(axis, side));
      if (centre && end && glm::length(glm::vec2(*end) - glm::vec2(*centre)) < kMinAxisPixels) continue;
      nearest.consider(int(handles.size()), f.end(axis, side), 1);
      handles.push_back(Handle{vertex, axis, side});
    }
  nearest.consider(int(handles.size()), f.centre, 0);
  handles.push_back(Handle{vertex, -1, 1});
}

}  // namespace

std::optional<Handle> hit_handle(const Viewport& view, glm::vec2 pixel, const CovarianceMesh& mesh,
                                 const std::vector<int>& vertices, double k_sigma, float radius) {
  NearestProjected nearest(view.camera, view.width, view.height, pixel, radius, 1.0f);
  std::vector<Handle> handles;
  for (const int v : vertices) consider(nearest, handles, handle_frame(mesh, v, k_sigma, view), v, view);
  if (nearest.best() < 0) return std::nullopt;
  return handles[size_t(nearest.best())];
}

std::optional<Handle> hit_handle(const Viewport& view, glm::vec2 pixel, const HandleFrame& frame, int vertex,
                                 float radius) {
  NearestProjected nearest(view.camera, view.width, view.height, pixel, radius, 1.0f);
  std::vector<Handle> handles;
  consider(nearest, handles, frame, vertex, view);
  if (nearest.best() < 0) return std::nullopt;
  return handles[size_t(nearest.best())];
}

HandleDrag::HandleDrag(const CovarianceMesh& mesh, const std::vector<int>& vertices, const Handle& grabbed,
                       double k_sigma, const Viewport& view, glm::vec2 start_pixel, bool common_frame,
                       const std::optional<Vec3>& pivot)
    : vertices_(vertices), handle_(grabbed), common_frame_(common_frame), k_sigma_(k_sigma), start_pixel_(start_pixel) {
  for (size_t i = 0; i < vertices_.size(); ++i) {
    start_axes_.push_back(ellipsoid_axes(mesh.covariance(size_t(vertices_[i]))));
    if (vertices_[i] == grabbed.vertex) grabbed_index_ = i;
  }
  grabbed_mean_ = mesh.mean(size_t(grabbed.vertex));
  const HandleFrame f = handle_frame(pivot.value_or(grabbed_mean_),
                                     ellipsoid_axes(mesh.covariance(size_t(grabbed.vertex))), k_sigma, view);
  centre_ = f.centre;
  normal_ = vertex_normal(mesh, grabbed.vertex);
  sigma_ = f.axes.sigmas.maxCoeff();
  const Vec3 eye = to_vec(view.camera.eye_double());
  if (grabbed.is_centre()) {
    kind_ = Kind::move;
    plane_origin_ = f.centre;
    // Facing the camera: towards the eye, or in a parallel projection along the view direction.
    plane_normal_ = view.camera.orthographic ? Vec3(eye - to_vec(view.camera.target)).normalized()
                                             : Vec3(eye - f.centre).normalized();
  } else {
    axis_ = double(grabbed.side) * f.axes.axes.col(grabbed.axis);
    length_ = f.lengths[grabbed.axis];
    plane_origin_ = f.end(grabbed.axis, grabbed.side);
    // The plane containing the axis that faces the camera most: normal = view direction minus its
    // component along the axis; an axis pointing at the eye falls back to the camera-facing plane.
    const Vec3 to_eye = (eye - plane_origin_).normalized();
    const Vec3 n = to_eye - to_eye.dot(axis_) * axis_;
    plane_normal_ = n.norm() > 1e-3 ? n.normalized() : to_eye;
  }
  start_point_ = plane_point(view, start_pixel).value_or(plane_origin_);
}

void HandleDrag::constrain(MoveConstraint constraint, int axis) {
  constraint_ = constraint;
  constraint_axis_ = std::clamp(axis, 0, 2);
  typed_.clear();
}

std::optional<Vec3> HandleDrag::plane_point(const Viewport& view, glm::vec2 pixel) const {
  const Ray ray = pixel_ray(view.camera, view.width, view.height, pixel);
  const Vec3 origin = to_vec(ray.origin), direction = to_vec(ray.direction);
  const double facing = direction.dot(plane_normal_);
  if (std::abs(facing) < 1e-9) return std::nullopt;
  const double t = (plane_origin_ - origin).dot(plane_normal_) / facing;
  if (!(t > 0) || !std::isfinite(t)) return std::nullopt;
  return origin + t * direction;
}

// The mean's motion for a centre drag under the constraint.
std::optional<Vec3> HandleDrag::move_motion(const Viewport& view, glm::vec2 pixel, bool snap) const {
  if (constraint_ == MoveConstraint::view_plane) {
    const auto point = plane_point(view, pixel);
    if (!point) return std::nullopt;
    return *point - start_point_;
  }
  const Vec3 d = constraint_ == MoveConstraint::normal ? normal_ : Vec3(Vec3::Unit(constraint_axis_));
  const Ray start_ray = pixel_ray(view.camera, view.width, view.height, start_pixel_);
  const Ray ray = pixel_ray(view.camera, view.width, view.height, pixel);
  if (constraint_ == MoveConstraint::plane) {  // ray ∩ plane through the centre with normal d
    const auto hit = [&](const Ray& r) -> std::optional<Vec3> {
      const double facing = to_vec(r.direction).dot(d);
      if (std::abs(facing) < 1e-9) return std::nullopt;
      return to_vec(r.origin) + (centre_ - to_vec(r.origin)).dot(d) / facing * to_vec(r.direction);
    };
    const auto a = hit(start_ray), b = hit(ray);
    if (!a || !b) return std::nullopt;
    return *b - *a;
  }
  double distance = 0.0;
  if (!typed_.empty()) {
    char* end = nullptr;
    distance = std::strtod(typed_.c_str(), &end);
    if (!std::isfinite(distance)) return std::nullopt;
  } else {  // the point of the line centre + s·d nearest to each ray: s(ray) − s(start ray)
    const auto along_line = [&](const Ray& r) -> std::optional<double> {
      const Vec3 o = to_vec(r.origin), u = to_vec(r.direction), w = centre_ - o;
      const double b = d.dot(u), denominator = 1.0 - b * b;
      if (denominator < 1e-9) return std::nullopt;  // the line points at the eye
      return (b * w.dot(u) - w.dot(d)) / denominator;
    };
    const auto a = along_line(start_ray), b = along_line(ray);
    if (!a || !b) return std::nullopt;
    distance = *b - *a;
    if (snap) distance = snapped(distance, 0.1 * sigma_);
  }
  return distance * d;
}

std::optional<std::vector<GaussianChange>> HandleDrag::update(const Viewport& view, glm::vec2 pixel,
                                                              const DragModifiers& modifiers) {
  change_ = GaussianChange{};
  if (handle_.is_centre()) {
    const auto motion = move_motion(view, pixel, modifiers.snap);
    if (!motion) return std::nullopt;
    change_.translation = *motion;
  } else {
    const auto point = plane_point(view, pixel);
    if (!point) return std::nullopt;
    const Vec3 motion = *point - start_point_;
    const double along = motion.dot(axis_);
    const Vec3 across = motion - along * axis_;
    if (kind_ == Kind::undecided && glm::length(pixel - start_pixel_) > kDecidePixels)
      kind_ = std::abs(along) >= across.norm() ? Kind::scale : Kind::rotate;
    if (modifiers.uniform || kind_ == Kind::scale) {
      double factor = axis_drag_factor(length_, along);
      if (modifiers.snap) factor = std::max(kSnapRatio, snapped(factor, kSnapRatio));
      change_.scale = factor;
      if (!modifiers.uniform) change_.scale_axis = axis_.normalized();
    } else if (kind_ == Kind::rotate) {
      Eigen::AngleAxisd turn(Eigen::Quaterniond::FromTwoVectors(axis_, length_ * axis_ + across));
      if (modifiers.snap) turn.angle() = snapped(turn.angle() * 180.0 / M_PI, kSnapDegrees) * M_PI / 180.0;
      change_.rotation = Eigen::Quaterniond(turn);
    }
  }
  std::vector<GaussianChange> changes(vertices_.size());
  for (size_t i = 0; i < vertices_.size(); ++i) changes[i] = change_for(i);
  return changes;
}

// The grabbed change seen by selected vertex i: in its own frame, its axis of the grabbed rank.
GaussianChange HandleDrag::change_for(size_t i) const {
  GaussianChange c = change_;
  if (!c.scale_axis.isZero() && !common_frame_) c.scale_axis = start_axes_[i].axes.col(handle_.axis);
  return c;
}

HandleFrame HandleDrag::frame(const Viewport& view) const {
  const EllipsoidAxes& start = start_axes_[grabbed_index_];
  EllipsoidAxes now = start;
  const Mat3 a = change_.linear();
  for (int k = 0; k < 3; ++k) {
    const Vec3 axis = a * start.axes.col(k);
    now.sigmas[k] = start.sigmas[k] * axis.norm();
    now.axes.col(k) = axis.normalized();
  }
  return handle_frame(centre_ + change_.translation, now, k_sigma_, view);
}

std::string HandleDrag::describe() const {
  char text[160];
  static const char* kAxisNames[] = {"x", "y", "z"};
  switch (kind_) {
    case Kind::undecided:
      return "drag along the axis to scale, across it to turn";
    case Kind::scale:
    case Kind::rotate:
      if (change_.scale != 1.0 && change_.scale_axis.isZero())
        std::snprintf(text, sizeof text, "scale all σ ×%.3f", change_.scale);
      else if (kind_ == Kind::scale)
        std::snprintf(text, sizeof text, "scale σ%d ×%.3f", handle_.axis + 1, change_.scale);
      else
        std::snprintf(text, sizeof text, "turn %.1f°", Eigen::AngleAxisd(change_.rotation).angle() * 180.0 / M_PI);
      return text;
    case Kind::move: {
      const double distance = change_.translation.norm();
      switch (constraint_) {
        case MoveConstraint::view_plane:
          std::snprintf(text, sizeof text, "move %.4f (X/Y/Z: along an axis, Shift: in a plane, N: normal)", distance);
          break;
        case MoveConstraint::axis:
          std::snprintf(text, sizeof text, "move along %s %s", kAxisNames[constraint_axis_],
                        typed_.empty() ? "" : typed_.c_str());
          break;
        case MoveConstraint::plane:
          std::snprintf(text, sizeof text, "move in the plane normal to %s %.4f", kAxisNames[constraint_axis_],
                        distance);
          break;
        case MoveConstraint::normal:
          std::snprintf(text, sizeof text, "move along the normal %s", typed_.empty() ? "" : typed_.c_str());
          break;
      }
      return text;
    }
  }
  return "";
}

}  // namespace gps
