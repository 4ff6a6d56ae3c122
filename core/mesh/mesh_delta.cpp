#include "core/mesh/mesh_delta.h"

#include <cstring>

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

MeshDelta mesh_delta(const CovarianceMesh& from, const CovarianceMesh& to, const std::vector<int>& origin) {
  MeshDelta d;
  d.n_vertices = int(to.n_vertices());
  d.n_faces = int(to.n_faces());
  d.sharpness = to.sharpness;
  const int n_from = int(from.n_vertices());
  const bool given = origin.size() == to.n_vertices();
  std::vector<int> to_of_from(size_t(n_from), -1);
  for (int v = 0; v < d.n_vertices; ++v) {
    int o = given ? origin[size_t(v)] : origin.empty() && v < n_from ? v : -1;
    if (o >= n_from || (o >= 0 && to_of_from[size_t(o)] >= 0)) o = -1;  // not one of `from`'s, or taken twice
    if (o >= 0) {
      take(d.vertex_runs, v, o);
      to_of_from[size_t(o)] = v;
    }
    if (o >= 0 && same_bytes(to.mean(size_t(v)), from.mean(size_t(o))) &&
        same_bytes(to.covariance(size_t(v)), from.covariance(size_t(o))))
      continue;
    d.own_gaussians.push_back(v);
    d.means.push_back(to.mean(size_t(v)));
    d.covariances.push_back(to.covariance(size_t(v)));
  }
  // A face of `to` is taken over where a face of `from` at its first corner's source has its corners
  // (the one after the last face taken is tried first).
  const std::vector<int> from_of_to = sources_of(d.vertex_runs, d.n_vertices);
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

}  // namespace gps
