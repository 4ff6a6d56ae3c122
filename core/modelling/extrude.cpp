#include "core/modelling/extrude.h"

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>

#include "core/support/error.h"
#include "core/support/disjoint_sets.h"
#include "core/modelling/operation_words.h"

namespace gps {

namespace {

const char* const kClosedPart = "extruding every face of a closed part would leave nothing to join";

void check_offset(const Vec3& offset) {
  if (!offset.allFinite()) {
    std::ostringstream s;
    s << "offset (" << offset.x() << ", " << offset.y() << ", " << offset.z() << ") is not finite";
    throw Error(s.str());
  }
}

/// Moves the region by `shift`: inner vertices moved, boundary vertices copied (same covariance).
std::vector<int> move_region(MeshArrays& a, const FaceRegion& r, const Vec3& shift) {
  std::vector<Gaussian> copies;
  for (const auto& s : r.sectors)
    copies.push_back({a.means[size_t(s.vertex)] + shift, a.covariances[size_t(s.vertex)]});
  std::vector<int> selection = detach_region(a, r, copies);
  for (int v : r.inner_vertices) a.means[size_t(v)] += shift;
  selection.insert(selection.end(), r.inner_vertices.begin(), r.inner_vertices.end());
  std::sort(selection.begin(), selection.end());
  return selection;
}

/// Moves the region by `shift` and joins it to where it was, in `a`: the selection, with `summary` saying
/// what was added.
std::vector<int> extrude_region(MeshArrays& a, const FaceRegion& r, const Vec3& shift, std::string& summary) {
  if (r.has_closed_part) throw Error(kClosedPart);
  const int n_vertices = a.n_vertices(), n_faces = a.n_faces();
  const bool triangles = all_triangles(a);
  std::vector<int> selection = move_region(a, r, shift);
  check_gaussians(a, selection);  // the vertices moved and copied: the others were checked before
  if (triangles) split_new_quads(a, n_faces);
  summary = "extruded " + count_of(r.faces.size(), "face", "faces") + ": " +
            count_of(size_t(a.n_vertices() - n_vertices), "vertex", "vertices") + ", " +
            count_of(size_t(a.n_faces() - n_faces), "face", "faces") + " added";
  return selection;
}

Modelled extruded_faces(const CovarianceMesh& mesh, MeshArrays& a, const FaceRegion& r, const Vec3& shift) {
  std::string summary;
  std::vector<int> selection = extrude_region(a, r, shift, summary);
  return modelled(mesh, std::move(a), std::move(selection), std::move(summary));
}

/// Extrudes boundary edges given as directed edges of their faces (unique).
Modelled extruded_edges(const CovarianceMesh& mesh, MeshArrays& a, const std::vector<std::pair<int, int>>& directed,
                        const Vec3& offset) {
  const int n_faces = a.n_faces();
  const bool triangles = all_triangles(a);
  std::set<int> ends;
  for (const auto& [x, y] : directed) ends.insert(x), ends.insert(y);
  std::map<int, int> copy;
  for (int v : ends) copy[v] = a.add_vertex({a.means[size_t(v)] + offset, a.covariances[size_t(v)]});
  // The face has x → y, so the quad runs y → x and its outer edge x′ → y′.
  for (const auto& [x, y] : directed) a.faces.push_back({y, x, copy[x], copy[y]});
  if (triangles) split_new_quads(a, n_faces);
  Modelled out;
  for (const auto& [v, c] : copy) out.selection.push_back(c);
  out.mesh = build_mesh(a, mesh);
  out.vertex_origin = vertex_origin(a);
  out.summary = "extruded " + count_of(directed.size(), "edge", "edges") + ": " +
                count_of(copy.size(), "vertex", "vertices") + ", " +
                count_of(size_t(a.n_faces() - n_faces), "face", "faces") + " added";
  return out;
}

}  // namespace

Vec3 newell_normal(const MeshArrays& a, int f) {
  const auto& face = a.faces[size_t(f)];
  Vec3 n = Vec3::Zero();
  for (size_t k = 0; k < face.size(); ++k)
    n += a.means[size_t(face[k])].cross(a.means[size_t(face[(k + 1) % face.size()])]);
  return n;
}

FaceRegion face_region(const MeshArrays& a, const std::vector<int>& faces) {
  if (faces.empty()) throw Error("no faces are selected");
  FaceRegion r;
  r.faces = sorted_faces(a, faces);
  r.in_region.assign(size_t(a.n_faces()), 0);
  for (int f : r.faces) r.in_region[size_t(f)] = 1;
  // The region's own directed edges: a twin outside the region counts as none (a boundary of the
  // region), so the rest of the mesh is never looked at.
  DirectedEdges edges;
  for (int f : r.faces) {
    const auto& face = a.faces[size_t(f)];
    for (size_t k = 0; k < face.size(); ++k)
      edges.emplace(directed_key(face[k], face[(k + 1) % face.size()]), std::pair<int, int>(f, int(k)));
  }

  // Corners of region faces, numbered face by face; corners at a vertex joined across interior
  // region edges form its sectors, and faces joined across them form the region's pieces.
  std::vector<int> first_corner(r.faces.size() + 1, 0);
  for (size_t i = 0; i < r.faces.size(); ++i)
    first_corner[i + 1] = first_corner[i] + int(a.faces[size_t(r.faces[i])].size());
  std::vector<int> slot(size_t(a.n_faces()), -1);
  for (size_t i = 0; i < r.faces.size(); ++i) slot[size_t(r.faces[i])] = int(i);
  auto corner_id = [&](int f, int k) {
    const int n = int(a.faces[size_t(f)].size());
    return first_corner[size_t(slot[size_t(f)])] + ((k % n) + n) % n;
  };
  LowestRootSets corners(size_t(first_corner.back())), pieces(r.faces.size());
  std::vector<char> on_boundary(size_t(first_corner.back()), 0);
  std::vector<char> boundary_vertex(size_t(a.n_vertices()), 0);
  for (int f : r.faces) {
    const auto& face = a.faces[size_t(f)];
    for (int k = 0; k < int(face.size()); ++k) {
      const int v = face[size_t(k)], w = face[(size_t(k) + 1) % face.size()];
      const auto [g, j] = edges.place(directed_key(w, v));  // g has w → v at corner j, so v is its corner j + 1
      if (g < 0) {
        on_boundary[size_t(corner_id(f, k))] = 1;
        boundary_vertex[size_t(v)] = boundary_vertex[size_t(w)] = 1;
        r.boundary.emplace_back(f, k);
      } else {
        corners.unite(corner_id(f, k), corner_id(g, j + 1));
        pieces.unite(slot[size_t(f)], slot[size_t(g)]);
      }
    }
  }
  std::vector<char> piece_has_boundary(r.faces.size(), 0);
  for (const auto& [f, k] : r.boundary) piece_has_boundary[size_t(pieces.find(slot[size_t(f)]))] = 1;
  for (size_t i = 0; i < r.faces.size(); ++i)
    if (pieces.find(int(i)) == int(i) && !piece_has_boundary[i]) r.has_closed_part = true;

  std::map<int, size_t> sector_of_root;
  std::set<int> inner;
  for (int f : r.faces) {
    const auto& face = a.faces[size_t(f)];
    for (int k = 0; k < int(face.size()); ++k) {
      const int v = face[size_t(k)];
      if (!boundary_vertex[size_t(v)]) {
        inner.insert(v);
        continue;
      }
      const auto [it, added] = sector_of_root.emplace(corners.find(corner_id(f, k)), r.sectors.size());
      if (added) r.sectors.emplace_back().vertex = v;
      FaceRegion::Sector& s = r.sectors[it->second];
      s.corners.emplace_back(f, k);
      if (on_boundary[size_t(corner_id(f, k))]) s.outgoing = {f, k};
      if (on_boundary[size_t(corner_id(f, k - 1))]) s.incoming = {f, (k + int(face.size()) - 1) % int(face.size())};
    }
  }
  std::stable_sort(r.sectors.begin(), r.sectors.end(),
                   [](const FaceRegion::Sector& x, const FaceRegion::Sector& y) { return x.vertex < y.vertex; });
  r.inner_vertices.assign(inner.begin(), inner.end());
  return r;
}

std::vector<int> detach_region(MeshArrays& a, const FaceRegion& r, const std::vector<Gaussian>& copies) {
  std::vector<std::array<int, 2>> outer;
  for (const auto& [f, k] : r.boundary) {
    const auto& face = a.faces[size_t(f)];
    outer.push_back({face[size_t(k)], face[(size_t(k) + 1) % face.size()]});
  }
  // The region's creases travel with its faces onto the copies; the boundary edges keep theirs
  // at the base too, and each copy takes its vertex's corner (as Blender's extrude copies them).
  std::vector<std::array<int, 2>> region_edges;
  for (int f : r.faces) {
    const auto& face = a.faces[size_t(f)];
    for (size_t k = 0; k < face.size(); ++k)
      if (a.sharpness.crease(face[k], face[(k + 1) % face.size()]) > 0.0) region_edges.push_back({f, int(k)});
  }
  std::vector<double> region_creases;
  for (const auto& [f, k] : region_edges) {
    const auto& face = a.faces[size_t(f)];
    region_creases.push_back(a.sharpness.crease(face[size_t(k)], face[(size_t(k) + 1) % face.size()]));
  }
  std::vector<int> added;
  for (size_t s = 0; s < r.sectors.size(); ++s) {
    added.push_back(a.add_vertex(copies[s]));
    for (const auto& [f, k] : r.sectors[s].corners) a.faces[size_t(f)][size_t(k)] = added.back();
    if (const double corner = a.sharpness.corner(r.sectors[s].vertex); corner > 0.0)
      a.sharpness.set_corner(added.back(), corner, a.n_vertices());
  }
  for (size_t i = 0; i < region_edges.size(); ++i) {
    const auto& face = a.faces[size_t(region_edges[i][0])];
    const size_t k = size_t(region_edges[i][1]);
    a.sharpness.set_crease(face[k], face[(k + 1) % face.size()], region_creases[i]);
  }
  for (size_t i = 0; i < r.boundary.size(); ++i) {
    const auto& face = a.faces[size_t(r.boundary[i].first)];
    const size_t k = size_t(r.boundary[i].second);
    a.faces.push_back({outer[i][0], outer[i][1], face[(k + 1) % face.size()], face[k]});
  }
  return added;
}

std::vector<int> extrude_faces_in(MeshArrays& a, const std::vector<int>& faces, double distance, std::string& summary) {
  if (!std::isfinite(distance)) throw Error("distance " + std::to_string(distance) + " is not finite");
  const FaceRegion r = face_region(a, faces);
  if (r.has_closed_part) throw Error(kClosedPart);
  Vec3 normal = Vec3::Zero();
  double scale = 0;
  for (int f : r.faces) {
    const Vec3 n = newell_normal(a, f);
    normal += n;
    scale += n.norm();
  }
  Vec3 shift = Vec3::Zero();
  if (distance != 0) {
    if (!(normal.norm() > 1e-12 * scale))
      throw Error("the faces' normals cancel out, so there is no direction to extrude along");
    shift = distance * normal.normalized();
  }
  return extrude_region(a, r, shift, summary);
}

Modelled extrude_faces(const CovarianceMesh& mesh, const std::vector<int>& faces, double distance) {
  return modelled_by(
      mesh, [&](MeshArrays& a, std::string& summary) { return extrude_faces_in(a, faces, distance, summary); });
}

Modelled extrude_faces_by(const CovarianceMesh& mesh, const std::vector<int>& faces, const Vec3& offset) {
  check_offset(offset);
  MeshArrays a = arrays_of(mesh);
  return extruded_faces(mesh, a, face_region(a, faces), offset);
}

Modelled extrude_edges(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges, const Vec3& offset) {
  check_offset(offset);
  if (edges.empty()) throw Error("no edges are selected");
  MeshArrays a = arrays_of(mesh);
  const DirectedEdges de(mesh);
  std::vector<std::pair<int, int>> directed;
  std::set<uint64_t> seen;
  for (const auto& [x, y] : edges) {
    if (!has_edge(de, x, y)) throw Error(edge_name(x, y) + " is not in the mesh");
    if (!is_boundary_edge(de, x, y)) throw Error(edge_name(x, y) + " is not on a boundary");
    if (!seen.insert(edge_key(x, y)).second) continue;
    if (de.count(directed_key(x, y)))
      directed.emplace_back(x, y);
    else
      directed.emplace_back(y, x);
  }
  return extruded_edges(mesh, a, directed, offset);
}

Modelled extrude_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const Vec3& offset) {
  check_offset(offset);
  MeshArrays a = arrays_of(mesh);
  std::vector<char> selected(size_t(a.n_vertices()), 0);
  for (int v : sorted_vertices(a, vertices)) selected[size_t(v)] = 1;
  std::vector<int> region;
  for (int f = 0; f < a.n_faces(); ++f) {
    const auto& face = a.faces[size_t(f)];
    if (std::all_of(face.begin(), face.end(), [&](int v) { return selected[size_t(v)]; })) region.push_back(f);
  }
  if (!region.empty()) return extruded_faces(mesh, a, face_region(a, region), offset);

  const DirectedEdges de(mesh);
  std::vector<std::pair<int, int>> directed;
  for (const auto& face : a.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      const int x = face[k], y = face[(k + 1) % face.size()];
      if (selected[size_t(x)] && selected[size_t(y)] && !de.count(directed_key(y, x))) directed.emplace_back(x, y);
    }
  if (directed.empty()) throw Error("select faces or boundary edges to extrude");
  return extruded_edges(mesh, a, directed, offset);
}

}  // namespace gps
