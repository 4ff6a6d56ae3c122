#pragma once
// The faces around a vertex in order, as the bevel walks them (core/modelling/bevel.h), and where
// the gap outside a boundary falls among them.
#include <vector>

namespace gps {

/// The faces around a vertex v in order: face i has the corner around[i] → v → around[i + 1] (at
/// corners[i]), and edge i, v–around[i], lies between faces i − 1 and i. Around a boundary vertex the
/// last "face" is the gap outside the boundary (face −1), so that edges 0 and gap() are its two
/// boundary edges.
struct Fan {
  int v = -1;
  std::vector<int> around, faces, corners;
  int size() const { return int(faces.size()); }
  int at(int i) const { return ((i % size()) + size()) % size(); }
  int neighbour(int i) const { return around[size_t(at(i))]; }
  bool open() const { return faces.back() < 0; }
  int gap() const { return size() - 1; }
  bool real(int i) const { return faces[size_t(at(i))] >= 0; }
  bool on_boundary(int edge) const { return open() && (at(edge) == 0 || at(edge) == gap()); }
};

/// Whether the fan faces from bevelled edge s to the next one, t (m of them), take in the gap outside
/// a boundary, and how many real faces lie between s and the gap (`after_s`) and between it and t.
struct GapInRange {
  bool in = false;
  int after_s = 0, before_t = 0;
};

inline GapInRange gap_in_range(const Fan& fan, int s, int m) {
  GapInRange g;
  if (!fan.open() || fan.at(fan.gap() - s) >= m) return g;
  g.in = true;
  g.after_s = fan.at(fan.gap() - s);
  g.before_t = m - g.after_s - 1;
  return g;
}

}  // namespace gps
