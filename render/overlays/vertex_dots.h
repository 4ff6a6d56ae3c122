#pragma once
// A round dot of one colour on each of some vertices (the editor's selected ones), drawn over
// whatever the framebuffer holds, in one draw call: their positions uploaded in a normalised frame
// (as the other overlays) only when they change, so that a frame with a large selection costs the
// GPU a few hundred thousand points rather than a draw list of circles built on the CPU.
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "render/gl/gl_object.h"
#include "render/gl/normalised_frame.h"
#include "render/gl/render_target.h"
#include "render/gl/shader_program.h"
#include "view/camera.h"

namespace gps {

class VertexDots {
public:
  struct Style {
    glm::vec4 colour{1.0f, 170.0f / 255.0f, 40.0f / 255.0f, 1.0f};
    float diameter = 7.0f;  // pixels
  };

  /// Needs a current GL 4.5 context.
  VertexDots();
  VertexDots(const VertexDots&) = delete;
  VertexDots& operator=(const VertexDots&) = delete;

  /// The dots on `vertices` of `mesh`, placed in `frame` (mapped in double). Uploads only where the
  /// placed positions differ from those held. Throws gps::Error naming a vertex `mesh` does not have.
  void set_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const NormalisedFrame& frame);
  size_t count() const { return count_; }

  /// Over what the bound framebuffer holds, in a viewport of width × height pixels, blended, with no
  /// depth test: a dot shows wherever its vertex is in front of the eye and within the depth range.
  void draw(int width, int height, const Camera& camera, const Style& style) const;
  /// The same into the colour attachment of `target`.
  void draw(const RenderTarget& target, const Camera& camera, const Style& style) const;

private:
  ShaderProgram program_;
  GlVertexArray vao_;
  GlBuffer positions_;
  NormalisedFrame frame_;
  std::vector<float> placed_;  // the positions uploaded, three floats per dot
  size_t capacity_ = 0;        // floats the buffer holds
  size_t count_ = 0;
};

}  // namespace gps
