#pragma once
// Points over the surface (the dense target of a fit), each a round dot coloured by its distance
// from the surface on the ramp of render/overlays/distance_ramp.h. Depth-tested against the surface
// drawn into the target, each point moved a little towards the eye first so that those on the
// surface show and those behind it are hidden. Uploaded in a normalised frame, as the other overlays.
#include <vector>

#include "core/mesh/linalg.h"
#include "render/gl/gl_object.h"
#include "render/gl/render_target.h"
#include "render/gl/shader_program.h"
#include "render/gl/normalised_frame.h"
#include "view/camera.h"

namespace gps {

class PointOverlay {
public:
  struct Style {
    double max_distance = 1.0;   // the ramp's red end, in world units
    float point_size = 5.0f;     // pixels
    float towards_eye = 0.004f;  // how far each point moves towards the eye, in frame units (the mesh's diagonal)
  };

  /// Needs a current GL 4.5 context.
  PointOverlay();
  PointOverlay(const PointOverlay&) = delete;
  PointOverlay& operator=(const PointOverlay&) = delete;

  /// The points, in world coordinates, uploaded in `frame` (mapped in double); unmeasured (grey)
  /// until set_distances().
  void set_points(const std::vector<Vec3>& points, const NormalisedFrame& frame);
  /// The points again in another frame (the surface's frame changed), their distances kept.
  void set_frame(const std::vector<Vec3>& points, const NormalisedFrame& frame);
  /// One distance per point (world units), in the points' order; their size must be count().
  void set_distances(const std::vector<float>& distances);
  const NormalisedFrame& frame() const { return frame_; }
  size_t count() const { return count_; }
  bool measured() const { return measured_; }

  /// Over the surface already drawn into `target` (its depth), into the colour attachment only.
  void draw(const RenderTarget& target, const Camera& camera, const Style& style) const;

private:
  void upload_positions(const std::vector<Vec3>& points);
  ShaderProgram program_;
  GlVertexArray vao_;
  GlBuffer positions_, distances_;
  GlTexture ramp_;
  NormalisedFrame frame_;
  size_t count_ = 0;
  bool measured_ = false;
};

}  // namespace gps
