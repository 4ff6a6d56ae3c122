#include "core/mesh/mesh_delta.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <utility>

namespace gps {

namespace {

// Adds element i, taken from the source's element `source`, to the runs (extending the last where it
// continues it).
void take(std::vector<TakenRun>& runs, int i, int source) {
  if (!runs.empty()) {
    TakenRun& last = runs.back();
    if (last.first + last.count == i && last.source_first + last.count == source) {
      ++last.count;
      return;
    }
  }
  runs.push_back({i, source, 1});
}

// Per element: the source's element it is, or −1.
std::vector<int> sources_of(const std::vector<TakenRun>& runs, int n) {
  std::vector<int> out(size_t(n), -1);
  for (const TakenRun& r : runs)
    for (int k = 0; k < r.count; ++k) out[size_t(r.first + k)] = r.source_first + k;
  return out;
}

// Whether the delta takes over every vertex and face of `from`, each at its own index: the mesh it tells
// has `from`'s faces, its Gaussians and sharpness aside.
bool keeps_every_element(const CovarianceMesh& from, const MeshDelta& d) {
  const auto whole = [](const std::vector<TakenRun>& runs, int n, size_t n_from) {
    return size_t(n) == n_from && (n == 0 ? runs.empty() : runs.size() == 1 && runs[0] == TakenRun{0, 0, n});
  };
  return whole(d.vertex_runs, d.n_vertices, from.n_vertices()) && whole(d.face_runs, d.n_faces, from.n_faces());
}

template <class T>
bool same_bytes(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <class T>
size_t bytes_of(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

}  // namespace

size_t MeshDelta::bytes() const {
  return sizeof(MeshDelta) + bytes_of(vertex_runs) + bytes_of(own_gaussians) + bytes_of(means) + bytes_of(covariances) +
         bytes_of(face_runs) + bytes_of(own_faces) + bytes_of(own_offsets) + bytes_of(own_corners) +
         bytes_of(sharpness.creases) + bytes_of(sharpness.corners);
}

std::vector<int> delta_vertex_sources(size_t n_from, size_t n_to, const std::vector<int>& origin) {
  const bool given = origin.size() == n_to;
  std::vector<int> sources(n_to, -1);
  std::vector<char> taken(n_from, 0);
  for (size_t v = 0; v < n_to; ++v) {
    const int o = given ? origin[v] : origin.empty() && v < n_from ? int(v) : -1;
    if (o < 0 || size_t(o) >= n_from || taken[size_t(o)]) continue;  // new, not one of `from`'s, or taken twice
    sources[v] = o;
    taken[size_t(o)] = 1;
  }
  return sources;
}

MeshDelta mesh_delta(const CovarianceMesh& from, const CovarianceMesh& to, const std::vector<int>& origin) {
  MeshDelta d;
  d.n_vertices = int(to.n_vertices());
  d.n_faces = int(to.n_faces());
  d.sharpness = to.sharpness;
  const std::vector<int> from_of_to = delta_vertex_sources(from.n_vertices(), to.n_vertices(), origin);
  for (int v = 0; v < d.n_vertices; ++v) {
    const int o = from_of_to[size_t(v)];
    if (o >= 0) take(d.vertex_runs, v, o);
    if (o >= 0 && same_bytes(to.mean(size_t(v)), from.mean(size_t(o))) &&
        same_bytes(to.covariance(size_t(v)), from.covariance(size_t(o))))
      continue;
    d.own_gaussians.push_back(v);
    d.means.push_back(to.mean(size_t(v)));
    d.covariances.push_back(to.covariance(size_t(v)));
  }
  // A face of `to` is taken over where a face of `from` at its first corner's source has its corners
  // (the one after the last face taken is tried first).
  const MeshConnectivity& c = from.connectivity();
  std::vector<char> taken(from.n_faces(), 0);
  const auto same_face = [&](int f, int g) {
    const std::span<const int> a = to.face(size_t(f)), b = from.face(size_t(g));
    if (taken[size_t(g)] || a.size() != b.size()) return false;
    for (size_t k = 0; k < a.size(); ++k)
      if (from_of_to[size_t(a[k])] != b[k]) return false;
    return true;
  };
  // The searches at first corners look at no more faces in all than a few per corner: around a vertex
  // of very many faces, faces are stored rather than searched for.
  size_t budget = 4 * to.n_corners() + 64;
  int next = 0;
  for (int f = 0; f < d.n_faces; ++f) {
    int g = -1;
    if (next < int(from.n_faces()) && same_face(f, next)) g = next;
    if (const int o = from_of_to[size_t(to.face(size_t(f))[0])]; g < 0 && o >= 0)
      for (int i = c.vertex_face_offsets[size_t(o)]; i < c.vertex_face_offsets[size_t(o) + 1] && g < 0 && budget > 0;
           ++i, --budget)
        if (c.vertex_face_corners[size_t(i)] == 0 && same_face(f, c.vertex_faces[size_t(i)]))
          g = c.vertex_faces[size_t(i)];
    if (g >= 0) {
      take(d.face_runs, f, g);
      taken[size_t(g)] = 1;
      next = g + 1;
      continue;
    }
    d.own_faces.push_back(f);
    const std::span<const int> corners = to.face(size_t(f));
    d.own_corners.insert(d.own_corners.end(), corners.begin(), corners.end());
    d.own_offsets.push_back(int(d.own_corners.size()));
  }
  return d;
}

std::vector<int> vertex_sources(const MeshDelta& d) { return sources_of(d.vertex_runs, d.n_vertices); }

CovarianceMesh apply_delta(const CovarianceMesh& from, const MeshDelta& d) {
  if (keeps_every_element(from, d)) {  // the faces and their connectivity shared, not built again
    CovarianceMesh m = from;
    for (size_t i = 0; i < d.own_gaussians.size(); ++i) {
      m.set_mean(size_t(d.own_gaussians[i]), d.means[i]);
      m.set_covariance(size_t(d.own_gaussians[i]), d.covariances[i]);
    }
    m.sharpness = d.sharpness;
    return m;
  }
  MeshOrigins origins{sources_of(d.vertex_runs, d.n_vertices), sources_of(d.face_runs, d.n_faces)};
  std::vector<Vec3> means(size_t(d.n_vertices));
  std::vector<Mat3> covariances(size_t(d.n_vertices));
  std::vector<int> to_of_from(from.n_vertices(), -1);
  for (int v = 0; v < d.n_vertices; ++v)
    if (const int o = origins.vertices[size_t(v)]; o >= 0) {
      means[size_t(v)] = from.mean(size_t(o));
      covariances[size_t(v)] = from.covariance(size_t(o));
      to_of_from[size_t(o)] = v;
    }
  for (size_t i = 0; i < d.own_gaussians.size(); ++i) {
    means[size_t(d.own_gaussians[i])] = d.means[i];
    covariances[size_t(d.own_gaussians[i])] = d.covariances[i];
  }
  PolygonTopology t;
  t.n_vertices = d.n_vertices;
  t.offsets.reserve(size_t(d.n_faces) + 1);
  size_t own = 0;
  for (int f = 0; f < d.n_faces; ++f) {
    if (const int g = origins.faces[size_t(f)]; g >= 0) {
      for (const int v : from.face(size_t(g))) t.verts.push_back(to_of_from[size_t(v)]);
    } else {
      t.verts.insert(t.verts.end(), d.own_corners.begin() + d.own_offsets[own],
                     d.own_corners.begin() + d.own_offsets[own + 1]);
      ++own;
    }
    t.offsets.push_back(int(t.verts.size()));
  }
  CovarianceMesh m =
      make_covariance_mesh(from, std::move(means), std::move(covariances), std::move(t), origins, "restored mesh");
  m.sharpness = d.sharpness;
  return m;
}

namespace {

// The element `i` of the runs' mesh is in the source, or −1 (the runs ascending, as take makes them).
int source_in(const std::vector<TakenRun>& runs, int i) {
  const auto run = std::upper_bound(runs.begin(), runs.end(), i, [](int x, const TakenRun& r) { return x < r.first; });
  if (run == runs.begin()) return -1;
  const TakenRun& r = *std::prev(run);
  return i < r.first + r.count ? r.source_first + (i - r.first) : -1;
}

// Where vertex v is among the delta's own Gaussians, or −1.
int own_index(const MeshDelta& d, int v) {
  const auto at = std::lower_bound(d.own_gaussians.begin(), d.own_gaussians.end(), v);
  return at != d.own_gaussians.end() && *at == v ? int(at - d.own_gaussians.begin()) : -1;
}

// The delta's own Gaussians with `changes` (ascending by vertex, each listed once) merged in: a change
// with a Gaussian sets the vertex's own, one without drops it.
void merge_own(MeshDelta& d, const std::vector<std::pair<int, std::optional<Gaussian>>>& changes) {
  std::vector<int> vertices;
  std::vector<Vec3> means;
  std::vector<Mat3> covariances;
  size_t i = 0;
  const auto keep = [&](int v, const Vec3& mean, const Mat3& covariance) {
    vertices.push_back(v);
    means.push_back(mean);
    covariances.push_back(covariance);
  };
  for (const auto& [v, g] : changes) {
    for (; i < d.own_gaussians.size() && d.own_gaussians[i] < v; ++i)
      keep(d.own_gaussians[i], d.means[i], d.covariances[i]);
    if (i < d.own_gaussians.size() && d.own_gaussians[i] == v) ++i;
    if (g) keep(v, g->mean, g->covariance);
  }
  for (; i < d.own_gaussians.size(); ++i) keep(d.own_gaussians[i], d.means[i], d.covariances[i]);
  d.own_gaussians = std::move(vertices);
  d.means = std::move(means);
  d.covariances = std::move(covariances);
}

bool same_gaussian(const Gaussian& a, const Vec3& mean, const Mat3& covariance) {
  return same_bytes(a.mean, mean) && same_bytes(a.covariance, covariance);
}

}  // namespace

void retell_gaussians(MeshDelta& forward, MeshDelta& back, const CovarianceMesh& now, const std::vector<int>& vertices,
                      const std::vector<Vec3>& was_means, const std::vector<Mat3>& was_covariances) {
  // The vertices changed, each once, with its Gaussian in `after`.
  std::vector<std::pair<int, Gaussian>> changed;
  for (size_t i = 0; i < vertices.size(); ++i) changed.push_back({vertices[i], {was_means[i], was_covariances[i]}});
  std::stable_sort(changed.begin(), changed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  changed.erase(
      std::unique(changed.begin(), changed.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
      changed.end());
  const auto was = [&](int v) -> const Gaussian* {
    const auto at = std::lower_bound(changed.begin(), changed.end(), v,
                                     [](const std::pair<int, Gaussian>& c, int x) { return c.first < x; });
    return at != changed.end() && at->first == v ? &at->second : nullptr;
  };
  // A vertex's Gaussian in `after` and in `before` (back's own, else its source's in `after`).
  const auto in_after = [&](int w) {
    const Gaussian* g = was(w);
    return g ? *g : Gaussian{now.mean(size_t(w)), now.covariance(size_t(w))};
  };
  const auto in_before = [&](int o) {
    if (const int i = own_index(back, o); i >= 0) return Gaussian{back.means[size_t(i)], back.covariances[size_t(i)]};
    return in_after(source_in(back.vertex_runs, o));
  };
  // Forward: a changed vertex's Gaussian is its own where it is not its source's in `before`.
  std::vector<std::pair<int, std::optional<Gaussian>>> forward_changes, back_changes;
  for (const auto& [v, g] : changed) {
    const Vec3& mean = now.mean(size_t(v));
    const Mat3& covariance = now.covariance(size_t(v));
    const int o = source_in(forward.vertex_runs, v);
    const bool own = o < 0 || !same_gaussian(in_before(o), mean, covariance);
    forward_changes.push_back({v, own ? std::optional<Gaussian>({mean, covariance}) : std::nullopt});
  }
  // Back: a vertex of `before` whose source changed has its own Gaussian where it is not the source's now.
  for (const TakenRun& run : back.vertex_runs) {
    const auto first = std::lower_bound(changed.begin(), changed.end(), run.source_first,
                                        [](const std::pair<int, Gaussian>& c, int x) { return c.first < x; });
    for (auto c = first; c != changed.end() && c->first < run.source_first + run.count; ++c) {
      const int o = run.first + (c->first - run.source_first);
      const Gaussian g = in_before(o);
      const bool own = !same_gaussian(g, now.mean(size_t(c->first)), now.covariance(size_t(c->first)));
      back_changes.push_back({o, own ? std::optional<Gaussian>(g) : std::nullopt});
    }
  }
  std::sort(back_changes.begin(), back_changes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  merge_own(forward, forward_changes);
  merge_own(back, back_changes);
}

}  // namespace gps
