#pragma once
// A point set on a sphere (or a flattened one) in OBJ text, the target the fit tests fit to.
#include <cmath>
#include <sstream>
#include <string>

namespace gps::test {

/// A sphere of radius 1 as an (n × n)-per-face cube of triangles, pushed out to the sphere.
inline std::string sphere_obj(int n, double flatten = 1) {
  std::ostringstream obj;
  int count = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (const int side : {-1, 1}) {
      const int first = count + 1;
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          double p[3];
          p[axis] = side;
          p[(axis + 1) % 3] = -1 + 2.0 * i / n;
          p[(axis + 2) % 3] = -1 + 2.0 * j / n;
          const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
          obj << "v " << p[0] / r << " " << p[1] / r << " " << flatten * p[2] / r << "\n";
          ++count;
        }
      // Faces of one cube side only (not welded to the others): a point set is all the fit reads.
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const int a = first + i * (n + 1) + j;
          if (side > 0)
            obj << "f " << a << " " << a + n + 1 << " " << a + n + 2 << "\nf " << a << " " << a + n + 2 << " " << a + 1
                << "\n";
          else
            obj << "f " << a << " " << a + n + 2 << " " << a + n + 1 << "\nf " << a << " " << a + 1 << " " << a + n + 2
                << "\n";
        }
    }
  return obj.str();
}

}  // namespace gps::test
