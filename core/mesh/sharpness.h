#pragma once
// Crease sharpness on edges and corner sharpness on vertices: OpenSubdiv's semi-sharp creases
// (DeRose, Kass, Truong 1998) applied to the 9D points (docs/design.md §1 "Creases and corners").
// 0 is smooth; a sharpness s > 0 applies the sharp rules for s levels, the last fractional part
// blending sharp and smooth; kInfiniteSharpness and above are sharp at every level.
#include <string>
#include <vector>

namespace gps {

struct MeshConnectivity;  // core/mesh/mesh_connectivity.h

/// OpenSubdiv's Sdc::Crease::SHARPNESS_INFINITE: from this value on, an edge or vertex is sharp forever.
inline constexpr double kInfiniteSharpness = 10.0;

inline bool is_infinitely_sharp(double s) { return s >= kInfiniteSharpness; }
/// The sharpness one level finer under OpenSubdiv's uniform rule: s − 1, not below 0, infinite stays.
inline double decayed_sharpness(double s) { return is_infinitely_sharp(s) ? s : s > 1.0 ? s - 1.0 : 0.0; }

/// One creased edge between vertices a < b.
struct EdgeCrease {
  int a = 0, b = 0;
  double sharpness = 0.0;
  bool operator==(const EdgeCrease& o) const { return a == o.a && b == o.b && sharpness == o.sharpness; }
};

/// The sharpness of a mesh's edges and vertices, kept sparse: creases sorted by (a, b), each with
/// sharpness > 0; corners per vertex, or empty where no vertex is sharp.
struct Sharpness {
  std::vector<EdgeCrease> creases;
  std::vector<double> corners;

  bool empty() const { return creases.empty() && corners.empty(); }
  /// The sharpness of edge a–b (either order), 0 where it has none.
  double crease(int a, int b) const;
  /// The corner sharpness of vertex v, 0 where it has none.
  double corner(int v) const { return size_t(v) < corners.size() ? corners[size_t(v)] : 0.0; }
  /// Sets edge a–b's sharpness (0 removes it); values above kInfiniteSharpness are kept as given.
  void set_crease(int a, int b, double sharpness);
  /// Sets vertex v's corner sharpness in a mesh of n_vertices vertices.
  void set_corner(int v, double sharpness, int n_vertices);
  /// Drops zero corners (corners becomes empty if all are 0) and zero creases; sorts the creases.
  void normalise();
  bool operator==(const Sharpness& o) const { return creases == o.creases && corners == o.corners; }
};

/// Why a sharpness value cannot be used ("is negative", "is not finite"), or "" if it can.
std::string sharpness_problem(double s);

/// Sharpness per edge of `c` (its edge order) and per vertex, the form the subdivision rules read.
struct CreaseLevel {
  std::vector<double> edges;     // per edge of the connectivity
  std::vector<double> vertices;  // per vertex
  bool empty() const;            // no edge and no vertex is sharp
};

/// The sharpness of `s` laid out on a connectivity; throws gps::Error naming the crease whose two
/// vertices share no edge, or a vertex out of range.
CreaseLevel crease_level(const Sharpness& s, const MeshConnectivity& c, int n_vertices);

}  // namespace gps
