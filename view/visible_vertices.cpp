#include "view/visible_vertices.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gps {

namespace {

// A projected point: window pixel coordinates and NDC depth (affine in the window for both
// projections, so it is interpolated linearly across a triangle).
struct Projected {
  glm::vec3 p{0.0f};
  bool valid = false;
};

// The depth buffer: front-most NDC depth and the face drawn there, per pixel.
class DepthBuffer {
public:
  DepthBuffer(int width, int height)
      : width_(width),
        height_(height),
        depth_(size_t(width) * size_t(height), std::numeric_limits<float>::infinity()),
        face_(size_t(width) * size_t(height), -1) {}

  // Rasterises triangle abc of `face` at pixel centres (x + 0.5, y + 0.5), either winding.
  void draw(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, int face) {
    const float area = edge(a, b, c);
    if (!(std::abs(area) > 0.0f)) return;
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}) - 0.5f)));
    const int x1 = std::min(width_ - 1, int(std::ceil(std::max({a.x, b.x, c.x}) - 0.5f)));
    const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}) - 0.5f)));
    const int y1 = std::min(height_ - 1, int(std::ceil(std::max({a.y, b.y, c.y}) - 0.5f)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const glm::vec3 s(float(x) + 0.5f, float(y) + 0.5f, 0.0f);
        const float wa = edge(b, c, s) / area, wb = edge(c, a, s) / area, wc = edge(a, b, s) / area;
        if (wa < 0.0f || wb < 0.0f || wc < 0.0f) continue;
        const float z = wa * a.z + wb * b.z + wc * c.z;
        const size_t i = size_t(y) * size_t(width_) + size_t(x);
        if (z < depth_[i]) depth_[i] = z, face_[i] = face;
      }
  }
  float depth(int x, int y) const { return depth_[size_t(y) * size_t(width_) + size_t(x)]; }
  int face(int x, int y) const { return face_[size_t(y) * size_t(width_) + size_t(x)]; }

private:
  static float edge(const glm::vec3& a, const glm::vec3& b, const glm::vec3& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
  }
  int width_, height_;
  std::vector<float> depth_;
  std::vector<int> face_;
};

}  // namespace

std::vector<char> visible_vertices(const Viewport& view, const CovarianceMesh& mesh) {
  const size_t n = mesh.n_vertices();
  std::vector<Projected> projected(n);
  for (size_t i = 0; i < n; ++i)
    if (const auto p = visible_pixel(view.camera, view.width, view.height, mesh.mean(i))) projected[i] = {*p, true};

  DepthBuffer buffer(view.width, view.height);
  std::vector<char> has_face(n, 0), faces_camera(n, 0);
  for (size_t f = 0; f < mesh.n_faces(); ++f) {
    const std::span<const int> corners = mesh.face(f);
    bool complete = true;
    for (const int v : corners) complete = complete && projected[size_t(v)].valid;
    for (const int v : corners) has_face[size_t(v)] = 1;
    if (!complete) continue;  // a face crossing the near or far plane hides nothing here
    // Shoelace area in window pixels (y down): a face that faces the camera winds clockwise there.
    double area = 0.0;
    for (size_t k = 0; k < corners.size(); ++k) {
      const glm::vec3& a = projected[size_t(corners[k])].p;
      const glm::vec3& b = projected[size_t(corners[(k + 1) % corners.size()])].p;
      area += double(a.x) * double(b.y) - double(b.x) * double(a.y);
    }
    if (area < 0.0)
      for (const int v : corners) faces_camera[size_t(v)] = 1;
    for (size_t k = 1; k + 1 < corners.size(); ++k)
      buffer.draw(projected[size_t(corners[0])].p, projected[size_t(corners[k])].p, projected[size_t(corners[k + 1])].p,
                  int(f));
  }

  const double tolerance = 1e-3 * bounding_box_diagonal(mesh);
  const Vec3 eye = to_vec(view.camera.eye_double()), target = to_vec(view.camera.target);
  const Vec3 forward = (target - eye).normalized();
  std::vector<char> visible(n, 0);
  for (size_t i = 0; i < n; ++i) {
    if (!projected[i].valid) continue;
    const glm::vec3& p = projected[i].p;
    const int x = int(std::floor(p.x)), y = int(std::floor(p.y));
    if (x < 0 || y < 0 || x >= view.width || y >= view.height) continue;
    const int front_face = buffer.face(x, y);
    const auto own = [&](int face) {
      const MeshConnectivity& c = mesh.connectivity();
      return std::find(c.vertex_faces.begin() + c.vertex_face_offsets[i],
                       c.vertex_faces.begin() + c.vertex_face_offsets[i + 1],
                       face) != c.vertex_faces.begin() + c.vertex_face_offsets[i + 1];
    };
    // The vertex's depth moved towards the camera by the tolerance, against the buffer's.
    const auto nearer =
        project_to_pixel(view.camera, view.width, view.height, Vec3(mesh.mean(i) - tolerance * forward));
    if (has_face[i] && !faces_camera[i]) {
      // All of its faces turn away: seen only through an opening, where one of them is drawn and no
      // other face lies in front of it in the pixels around it (a silhouette's far side has one).
      bool drawn = false, covered = !nearer;
      for (int dy = -1; dy <= 1 && !covered; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int px = x + dx, py = y + dy;
          if (px < 0 || py < 0 || px >= view.width || py >= view.height) continue;
          const bool mine = own(buffer.face(px, py));
          drawn = drawn || mine;
          covered = covered || (!mine && buffer.depth(px, py) < nearer->z);
        }
      visible[i] = drawn && !covered;
      continue;
    }
    visible[i] = front_face < 0 || own(front_face) || (nearer && nearer->z <= buffer.depth(x, y));
  }
  return visible;
}

}  // namespace gps
