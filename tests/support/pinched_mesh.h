#pragma once
// Small meshes the repair mends: two pyramids sharing their apex (vertex 1, a pinch vertex), as OBJ;
// and the same as a scan might give it, with duplicate vertices in zero-area faces.
#include <sstream>
#include <string>

namespace gps::test {

constexpr const char* kPinchedObj =
    "v 0 0 0\n"
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
    "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 3 2\nf 1 4 3\nf 1 5 4\nf 1 2 5\nf 2 3 4 5\n"
    "f 1 6 7\nf 1 7 8\nf 1 8 9\nf 1 9 6\nf 6 9 8 7\n";

/// kPinchedObj and 9 zero-area triangles (faces 11-19, lines 47-55), each on an edge of the pyramids: two
/// new vertices at the edge's ends (18 duplicate vertices, 8 positions then 26 coincident vertices in
/// all) and one at its middle (left in no face once the triangle is dropped).
inline std::string pinched_scan_obj() {
  const double p[9][3] = {{0, 0, 0},   {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                          {-1, -1, 1}, {1, -1, 1},   {1, 1, 1},   {-1, 1, 1}};  // kPinchedObj's vertices
  const int edges[9][2] = {{2, 3}, {3, 4}, {4, 5}, {5, 2}, {6, 7}, {7, 8}, {8, 9}, {9, 6}, {2, 6}};
  std::ostringstream v, f;
  int n = 9;
  for (const auto& e : edges) {
    const double* a = p[e[0] - 1];
    const double* b = p[e[1] - 1];
    v << "v " << a[0] << " " << a[1] << " " << a[2] << "\nv " << b[0] << " " << b[1] << " " << b[2] << "\nv "
      << (a[0] + b[0]) / 2 << " " << (a[1] + b[1]) / 2 << " " << (a[2] + b[2]) / 2 << "\n";
    f << "f " << n + 1 << " " << n + 2 << " " << n + 3 << "\n";
    n += 3;
  }
  const std::string pinched = kPinchedObj;
  const size_t faces = pinched.find("f ");  // the pyramids' vertices, the new ones, the pyramids' faces, the new ones
  return pinched.substr(0, faces) + v.str() + pinched.substr(faces) + f.str();
}

}  // namespace gps::test
