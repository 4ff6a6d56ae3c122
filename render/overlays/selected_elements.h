#pragma once
// Selected edges and faces highlighted over whatever the framebuffer holds (the editor's edge and
// face modes): a face filled translucent and outlined, an edge as a wide line, only where it faces
// the camera (a face whose plane faces the eye; an edge of such a face, a boundary edge always). Drawn
// on the GPU from a few buffers: what is selected uploaded when it changes, the vertices' places
// (and the faces' planes) when they move, the facing decided per frame in the vertex shader.
#include <array>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "render/gl/gl_object.h"
#include "render/gl/normalised_frame.h"
#include "render/gl/render_target.h"
#include "render/gl/shader_program.h"
#include "view/camera.h"

namespace gps {

class SelectedElements {
public:
  struct Style {
    glm::vec4 edge{1.0f, 170.0f / 255.0f, 40.0f / 255.0f, 1.0f};
    glm::vec4 face_fill{1.0f, 150.0f / 255.0f, 40.0f / 255.0f, 70.0f / 255.0f};
    glm::vec4 face_outline{1.0f, 190.0f / 255.0f, 80.0f / 255.0f, 1.0f};
    float edge_width = 2.5f, outline_width = 2.0f;  // pixels
  };

  /// Needs a current GL 4.5 context.
  SelectedElements();
  SelectedElements(const SelectedElements&) = delete;
  SelectedElements& operator=(const SelectedElements&) = delete;

  /// The `edges` (by their ends; those that are no edge of `mesh` left out) and `faces` of `mesh`,
  /// placed in `frame`. Uploads only what changed. Throws gps::Error naming a face or vertex `mesh`
  /// does not have.
  void set_elements(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                    const std::vector<int>& faces, const NormalisedFrame& frame);
  /// The triangles filled and the lines drawn (before the facing test).
  size_t triangles() const { return triangles_; }
  size_t lines() const { return edge_lines_ + outline_lines_; }

  /// Over what the bound framebuffer holds, in a viewport of width × height pixels, blended, with no
  /// depth test: the faces' fill, their outlines, then the edges.
  void draw(int width, int height, const Camera& camera, const Style& style) const;
  /// The same into the colour attachment of `target`.
  void draw(const RenderTarget& target, const Camera& camera, const Style& style) const;

private:
  // A buffer seen by the shaders as a texture buffer of `format`, grown as needed.
  struct TexelBuffer {
    explicit TexelBuffer(unsigned format);
    void upload(const void* data, size_t bytes);
    unsigned format;
    GlBuffer buffer;
    GlTexture texture;
    size_t capacity = 0;
  };

  ShaderProgram fill_, lines_;
  GlVertexArray vao_;  // none of its attributes enabled: the shaders read the buffers themselves
  TexelBuffer positions_, planes_, items_;
  NormalisedFrame frame_;
  // What the items were made from; the mesh's vertices they read, and per face they read its corners
  // among those (its plane's, plane_corners_[plane_offsets_[j] .. plane_offsets_[j + 1])).
  std::shared_ptr<const MeshShape> shape_;
  std::vector<std::array<int, 2>> edges_;
  std::vector<int> faces_, vertices_, plane_offsets_{0}, plane_corners_;
  std::vector<float> placed_;  // per vertex read: xyz and 1 in the frame; then per face read its plane
  size_t triangles_ = 0, outline_lines_ = 0, edge_lines_ = 0;
};

}  // namespace gps
