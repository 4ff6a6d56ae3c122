#include "ui/editing/transform_mode.h"

#include "ui/document/editor_document.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace gps {

namespace {

const char* const kAxisNames[] = {"x", "y", "z"};

// Where the ray through `pixel` meets the plane through `point` normal to `normal` (nullopt: nearly parallel).
std::optional<Vec3> on_plane(const Viewport& view, glm::vec2 pixel, const Vec3& point, const Vec3& normal) {
  const Ray ray = pixel_ray(view.camera, view.width, view.height, pixel);
  const Vec3 origin = to_vec(ray.origin), direction = to_vec(ray.direction);
  const double along = direction.dot(normal);
  if (std::abs(along) < 0.05) return std::nullopt;
  return origin + direction * ((point - origin).dot(normal) / along);
}

}  // namespace

const char* pivot_name(TransformPivot pivot) {
  switch (pivot) {
    case TransformPivot::median:
      return "median point";
    case TransformPivot::active:
      return "active vertex";
    case TransformPivot::individual:
      return "individual origins";
    case TransformPivot::cursor:
      return "3D cursor";
  }
  return "";
}

TransformMode::TransformMode(TransformKind kind, const CovarianceMesh& mesh, std::vector<int> vertices, int active,
                             TransformPivot pivot, const Viewport& view, glm::vec2 cursor, const Vec3& cursor_point)
    : kind_(kind), vertices_(std::move(vertices)), pivot_(pivot), start_cursor_(cursor) {
  for (const int v : vertices_) {
    start_means_.push_back(mesh.mean(size_t(v)));
    centre_ += start_means_.back();
  }
  if (!vertices_.empty()) centre_ /= double(vertices_.size());
  if (pivot_ == TransformPivot::active && active >= 0) centre_ = mesh.mean(size_t(active));
  if (pivot_ == TransformPivot::cursor) centre_ = cursor_point;
  const Vec3 eye = to_vec(view.camera.eye_double()), target = to_vec(view.camera.target);
  view_axis_ = (view.camera.orthographic ? eye - target : eye - centre_).normalized();
  move_cursor(cursor, view);
}

void TransformMode::set_orientations(TransformOrientation first, const Mat3& normal_frame) {
  first_orientation_ = orientation_ = first;
  normal_frame_ = normal_frame;
}

void TransformMode::constrain_axis(int axis, bool exclude) {
  const Constraint wanted = exclude ? Constraint::plane : Constraint::axis;
  if (constraint_ != wanted || axis_ != axis) {
    constraint_ = wanted;
    axis_ = axis;
    orientation_ = first_orientation_;
  } else if (orientation_ == first_orientation_) {
    orientation_ = first_orientation_ == TransformOrientation::global ? TransformOrientation::normal
                                                                      : TransformOrientation::global;
  } else {
    constraint_ = Constraint::none;
  }
}

Mat3 TransformMode::frame() const {
  return orientation_ == TransformOrientation::normal ? normal_frame_ : Mat3(Mat3::Identity());
}

void TransformMode::constrain_direction(const Vec3& direction, const std::string& name) {
  constraint_ = Constraint::direction;
  direction_ = direction.normalized();
  direction_name_ = name;
}

Vec3 TransformMode::axis_direction() const {
  if (constraint_ == Constraint::direction) return direction_;
  if (constraint_ == Constraint::axis || constraint_ == Constraint::plane) return frame().col(axis_);
  return Vec3::Zero();
}

void TransformMode::move_cursor(glm::vec2 cursor, const Viewport& view) {
  const auto pixel = [&](const Vec3& p) {
    const auto q = project_to_pixel(view.camera, view.width, view.height, p);
    return q ? glm::vec2(*q) : start_cursor_;
  };
  const glm::vec2 centre = pixel(centre_);
  switch (kind_) {
    case TransformKind::grab: {
      const Vec3 along = axis_direction();
      if (constraint_ == Constraint::axis || constraint_ == Constraint::direction) {
        // The cursor's move along the axis's image on the screen, in world units along the axis.
        const double length = 100.0 * world_per_pixel(view.camera, view.height, centre_);
        const glm::vec2 image = pixel(centre_ + length * along) - centre;
        const float image_length2 = glm::dot(image, image);
        translation_ = image_length2 > 1e-6f
                           ? Vec3(along * (length * glm::dot(cursor - start_cursor_, image) / image_length2))
                           : Vec3(Vec3::Zero());
        break;
      }
      const Vec3 normal = constraint_ == Constraint::plane ? along : view_axis_;
      const auto a = on_plane(view, start_cursor_, centre_, normal), b = on_plane(view, cursor, centre_, normal);
      if (a && b) {
        translation_ = *b - *a;
      } else {  // the plane is seen edge-on: move in the view plane, then drop the normal part
        const auto c = on_plane(view, start_cursor_, centre_, view_axis_),
                   d = on_plane(view, cursor, centre_, view_axis_);
        translation_ = c && d ? Vec3(*d - *c) : Vec3::Zero();
        translation_ -= normal * translation_.dot(normal);
      }
      break;
    }
    case TransformKind::scale:
      factor_ = double(glm::length(cursor - centre)) / std::max(1.0, double(glm::length(start_cursor_ - centre)));
      break;
    case TransformKind::rotate: {
      const glm::vec2 a = start_cursor_ - centre, b = cursor - centre;
      // Pixels run downward: a turn that looks counter-clockwise lowers atan2.
      angle_ = -(std::atan2(double(b.y), double(b.x)) - std::atan2(double(a.y), double(a.x)));
      break;
    }
  }
}

void TransformMode::snap_increment(double distance_step, double factor_step, double angle_step) {
  const auto round_to = [](double value, double step) { return step > 0 ? std::round(value / step) * step : value; };
  switch (kind_) {
    case TransformKind::grab:
      if (constraint_ == Constraint::axis || constraint_ == Constraint::direction) {
        const Vec3 along = axis_direction();
        translation_ = along * round_to(translation_.dot(along), distance_step);
      } else {  // whole steps along each axis of the orientation in use
        const Mat3 f = frame();
        Vec3 steps = f.transpose() * translation_;
        for (int i = 0; i < 3; ++i) steps[i] = round_to(steps[i], distance_step);
        translation_ = f * steps;
      }
      break;
    case TransformKind::scale:
      factor_ = round_to(factor_, factor_step);
      break;
    case TransformKind::rotate:
      angle_ = round_to(angle_ * 180.0 / M_PI, angle_step) * M_PI / 180.0;
      break;
  }
}

void TransformMode::snap_to(const Vec3& point) {
  if (kind_ != TransformKind::grab) return;
  const Vec3 along = axis_direction();
  Vec3 t = point - centre_;
  if (constraint_ == Constraint::axis || constraint_ == Constraint::direction) t = along * t.dot(along);
  if (constraint_ == Constraint::plane) t -= along * t.dot(along);
  translation_ = t;
}

Vec3 TransformMode::pivot(size_t source) const {
  return pivot_ == TransformPivot::individual ? start_means_[source] : centre_;
}

AffineMap TransformMode::map(size_t source, double weight) const {
  const double typed = typed_value_;
  const bool has_typed = std::isfinite(typed);
  const Vec3 along = axis_direction();
  switch (kind_) {
    case TransformKind::grab: {
      Vec3 t = translation_;
      if (has_typed)
        t = typed * (constraint_ == Constraint::none    ? Vec3(Vec3::UnitX())
                     : constraint_ == Constraint::plane ? Vec3(frame().col((axis_ + 1) % 3))
                                                        : along);
      AffineMap m;
      m.translation = weight * t;
      return m;
    }
    case TransformKind::scale: {
      const double s = 1.0 + ((has_typed ? typed : factor_) - 1.0) * weight;
      Mat3 a = s * Mat3::Identity();
      if (constraint_ == Constraint::axis || constraint_ == Constraint::direction)
        a = Mat3::Identity() + (s - 1.0) * along * along.transpose();
      else if (constraint_ == Constraint::plane)
        a = s * Mat3::Identity() + (1.0 - s) * along * along.transpose();
      return AffineMap::about(pivot(source), a);
    }
    case TransformKind::rotate: {
      Vec3 axis = constraint_ == Constraint::none ? view_axis_ : along;
      double angle = angle_;
      if (has_typed)
        angle = typed * M_PI / 180.0;
      else if (axis.dot(view_axis_) < 0)
        angle = -angle;  // the turn follows the mouse whichever way the axis points
      const Mat3 r = Eigen::AngleAxisd(weight * angle, axis).toRotationMatrix();
      return AffineMap::about(pivot(source), r);
    }
  }
  return {};
}

std::string TransformMode::describe() const {
  std::string constraint;
  const std::string axis =
      (orientation_ == TransformOrientation::normal ? std::string("normal ") : std::string()) + kAxisNames[axis_];
  if (constraint_ == Constraint::axis) constraint = " along " + axis;
  if (constraint_ == Constraint::plane) constraint = " in the plane normal to " + axis;
  if (constraint_ == Constraint::direction) constraint = " along " + direction_name_;
  char amount[128];
  const AffineMap m = map(0);
  // What prints as zero at four decimals, shown without a sign ("-0.0000" from a rounding's −1e-17).
  const auto shown = [](double x) { return std::abs(x) < 5e-5 ? 0.0 : x; };
  switch (kind_) {
    case TransformKind::grab:
      std::snprintf(amount, sizeof amount, "Grab (%.4f, %.4f, %.4f)", shown(m.translation.x()),
                    shown(m.translation.y()), shown(m.translation.z()));
      break;
    case TransformKind::scale: {
      const double typed = typed_value_;
      std::snprintf(amount, sizeof amount, "Scale %.4f", shown(std::isfinite(typed) ? typed : factor_));
      break;
    }
    case TransformKind::rotate:
      std::snprintf(amount, sizeof amount, "Rotate %.2f°",
                    Eigen::AngleAxisd(Eigen::Matrix3d(m.linear)).angle() * 180.0 / M_PI);
      break;
  }
  return std::string(amount) + constraint + (typed_.empty() ? "" : "  [" + typed_ + "]") +
         "  (pivot: " + pivot_name(pivot_) + "; X Y Z constrain, digits type, Enter confirms, Esc cancels)";
}

AffineMap mirrored(const AffineMap& map, int axis) {
  Mat3 m = Mat3::Identity();
  m(axis, axis) = -1.0;
  AffineMap out;
  out.linear = m * map.linear * m;
  out.translation = m * map.translation;
  return out;
}

size_t apply_transform(EditorDocument& document, const TransformMode& transform,
                       const std::vector<ReachedVertex>& reach, int mirror_axis, bool carry_gaussians) {
  size_t clamped = 0;
  for (const ReachedVertex& r : reach) {
    AffineMap map = transform.map(r.source, r.weight);
    if (r.mirrored) map = mirrored(map, mirror_axis);
    const Gaussian start{document.start_mean(r.vertex), document.start_covariance(r.vertex)};
    if (map.linear == Mat3::Identity() || !carry_gaussians) {
      document.set_mean(r.vertex, map.apply(start.mean));
      document.set_covariance(r.vertex, start.covariance);  // a move, or positions only, keeps Σ exactly
      continue;
    }
    const CarriedGaussian carried = carried_gaussian(map, start);
    document.set_mean(r.vertex, carried.gaussian.mean);
    document.set_covariance(r.vertex, carried.gaussian.covariance);
    clamped += carried.clamped;
  }
  return clamped;
}

}  // namespace gps
