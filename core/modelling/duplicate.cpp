#include "core/modelling/duplicate.h"

#include <algorithm>
#include <map>

#include "core/modelling/extrude.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"

namespace gps {

Modelled duplicate_faces(const CovarianceMesh& mesh, const std::vector<int>& faces, const Vec3& offset) {
  if (!offset.allFinite()) throw Error("the offset has a number that is not finite");
  MeshArrays a = arrays_of(mesh);
  const FaceRegion region = face_region(a, faces);
  const Sharpness before = a.sharpness;

  // The copy of each corner of the region, made vertex by vertex in ascending order: one for an inner
  // vertex, one per sector for a vertex on the region's boundary.
  std::map<int, int> inner_copy;
  std::map<std::pair<int, int>, int> corner_copy;
  std::vector<int> originals;  // of the copies, in order
  size_t s = 0;
  const auto copy = [&](int v) {
    originals.push_back(v);
    Gaussian g = a.gaussian(v);
    g.mean += offset;
    return a.add_vertex(g);
  };
  const auto copy_sector = [&](const FaceRegion::Sector& sector) {
    const int c = copy(sector.vertex);
    for (const auto& corner : sector.corners) corner_copy.emplace(corner, c);
  };
  for (const int v : region.inner_vertices) {
    while (s < region.sectors.size() && region.sectors[s].vertex < v) copy_sector(region.sectors[s++]);
    inner_copy.emplace(v, copy(v));
  }
  while (s < region.sectors.size()) copy_sector(region.sectors[s++]);

  for (const int f : region.faces) {
    const std::vector<int> face = a.faces[size_t(f)];
    std::vector<int> copied;
    for (int k = 0; k < int(face.size()); ++k) {
      const auto inner = inner_copy.find(face[size_t(k)]);
      copied.push_back(inner != inner_copy.end() ? inner->second : corner_copy.at({f, k}));
    }
    for (size_t k = 0; k < face.size(); ++k)
      if (const double crease = before.crease(face[k], face[(k + 1) % face.size()]); crease > 0)
        a.sharpness.set_crease(copied[k], copied[(k + 1) % face.size()], crease);
    a.faces.push_back(std::move(copied));
  }
  const int first_copy = a.n_vertices() - int(originals.size());
  for (size_t i = 0; i < originals.size(); ++i)
    if (const double corner = before.corner(originals[i]); corner > 0)
      a.sharpness.set_corner(first_copy + int(i), corner, a.n_vertices());

  std::vector<int> selection(originals.size());
  for (size_t i = 0; i < selection.size(); ++i) selection[i] = first_copy + int(i);
  Modelled out = modelled(mesh, std::move(a), selection);
  out.summary = "duplicated " + count_of(region.faces.size(), "face", "faces") + ": " +
                count_of(originals.size(), "vertex", "vertices") + " added";
  return out;
}

}  // namespace gps
