#include "core/modelling/split_faces.h"

#include <algorithm>
#include <tuple>

#include "core/modelling/extrude.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"

namespace gps {

namespace {

// Whether each vertex is a corner of one of the region's faces.
std::vector<char> used_by(const MeshArrays& a, const FaceRegion& region) {
  std::vector<char> used(size_t(a.n_vertices()), 0);
  for (const int f : region.faces)
    for (const int v : a.faces[size_t(f)]) used[size_t(v)] = 1;
  return used;
}

}  // namespace

Modelled split_faces(const CovarianceMesh& mesh, const std::vector<int>& faces) {
  MeshArrays a = arrays_of(mesh);
  const FaceRegion split = face_region(a, faces);
  if (int(split.faces.size()) == a.n_faces())
    throw Error("every face is selected: there is nothing to split them from");
  // The other faces around the split faces' vertices: all of the rest that the cut reaches (a vertex's
  // sectors of the rest are those of the rest's faces around it).
  const std::vector<char> used_by_split = used_by(a, split);
  const MeshConnectivity& c = mesh.connectivity();
  std::vector<int> others;
  for (const int f : split.faces)
    for (const int v : a.faces[size_t(f)])
      for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
        if (const int g = c.vertex_faces[size_t(i)]; !split.in_region[size_t(g)]) others.push_back(g);
  std::sort(others.begin(), others.end());
  others.erase(std::unique(others.begin(), others.end()), others.end());
  const FaceRegion rest = others.empty() ? FaceRegion{} : face_region(a, others);
  const std::vector<char> used_by_rest = used_by(a, rest);

  // The creases of every face's edges, by (face, corner), to be set again on the edges as renumbered.
  std::vector<std::tuple<int, size_t, double>> creased;
  for (int f = 0; f < a.n_faces(); ++f) {
    const std::vector<int>& face = a.faces[size_t(f)];
    for (size_t k = 0; k < face.size(); ++k)
      if (const double c = a.sharpness.crease(face[k], face[(k + 1) % face.size()]); c > 0)
        creased.emplace_back(f, k, c);
  }

  std::vector<int> originals;  // of the copies, in order
  const auto copy_sector = [&](const FaceRegion::Sector& sector) {
    originals.push_back(sector.vertex);
    const int c = a.add_vertex(a.gaussian(sector.vertex));
    for (const auto& [f, k] : sector.corners) a.faces[size_t(f)][size_t(k)] = c;
  };
  for (const FaceRegion::Sector& s : split.sectors)
    if (used_by_rest[size_t(s.vertex)]) copy_sector(s);
  if (originals.empty())
    throw Error("the faces share no vertex with the other faces: they are a part of their own already");
  const size_t split_copies = originals.size();
  for (size_t s = 1; s < rest.sectors.size(); ++s)
    if (rest.sectors[s].vertex == rest.sectors[s - 1].vertex && used_by_split[size_t(rest.sectors[s].vertex)])
      copy_sector(rest.sectors[s]);

  for (const auto& [f, k, c] : creased) {
    const std::vector<int>& face = a.faces[size_t(f)];
    a.sharpness.set_crease(face[k], face[(k + 1) % face.size()], c);
  }
  const int first_copy = a.n_vertices() - int(originals.size());
  for (size_t i = 0; i < originals.size(); ++i)
    if (const double corner = a.sharpness.corner(originals[i]); corner > 0)
      a.sharpness.set_corner(first_copy + int(i), corner, a.n_vertices());

  std::vector<int> selection;
  for (const int f : split.faces)
    selection.insert(selection.end(), a.faces[size_t(f)].begin(), a.faces[size_t(f)].end());
  std::sort(selection.begin(), selection.end());
  selection.erase(std::unique(selection.begin(), selection.end()), selection.end());
  std::string summary = "split off " + count_of(split.faces.size(), "face", "faces") + ": " +
                        count_of(split_copies, "vertex", "vertices") + " duplicated along the cut";
  if (originals.size() > split_copies)
    summary +=
        ", " + count_of(originals.size() - split_copies, "more", "more") + " where the other faces met only there";
  return modelled(mesh, std::move(a), selection, summary);
}

}  // namespace gps
