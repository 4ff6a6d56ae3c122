#include "ui/editing/mirror_modifier.h"

#include <algorithm>
#include <cmath>

#include "core/modelling/delete_elements.h"
#include "core/modelling/mirror.h"
#include "core/support/error.h"

namespace gps {

const CovarianceMesh& MirrorModifier::shown(const CovarianceMesh& half, std::string& refusal) {
  mirrored_.reset();
  images_.clear();
  refusal.clear();
  if (!settings.enabled) return half;
  try {
    std::vector<int> images = mirror_images(half, settings.axis, Vec3::Zero(), true);
    mirrored_ = mirror(half, settings.axis, Vec3::Zero(), true).mesh;
    images_ = std::move(images);
    return *mirrored_;
  } catch (const Error& e) {
    refusal = e.what();
    return half;
  }
}

std::optional<PlaneClip> MirrorModifier::clip(const CovarianceMesh& half) const {
  if (!settings.enabled || !settings.clipping) return std::nullopt;
  return PlaneClip{settings.axis, mirror_merge_distance(half)};
}

std::optional<Modelled> MirrorModifier::seam_kept_open(const CovarianceMesh& before, const Modelled& result) const {
  const std::optional<PlaneClip> plane = clip(before);
  if (!plane) return std::nullopt;
  std::vector<int> on_plane;
  for (size_t f = 0; f < result.mesh.n_faces(); ++f) {
    const std::span<const int> corners = result.mesh.face(f);
    if (std::all_of(corners.begin(), corners.end(),
                    [&](int v) { return std::abs(result.mesh.mean(size_t(v))[plane->axis]) <= plane->tolerance; }))
      on_plane.push_back(int(f));
  }
  if (on_plane.empty()) return std::nullopt;
  Modelled out = with_faces_deleted(result, on_plane);
  out.summary = result.summary + "; " + std::to_string(on_plane.size()) + (on_plane.size() == 1 ? " face" : " faces") +
                " on the mirror plane left out (the seam stays open)";
  return out;
}

std::optional<std::vector<int>> MirrorModifier::update(const CovarianceMesh& half, const std::vector<int>& changed,
                                                       std::string& refusal) {
  if (!mirrored_) return changed;
  try {
    if (half.n_vertices() != images_.size()) throw Error("the mesh changed under the mirror");
    return update_mirrored(half, changed, settings.axis, Vec3::Zero(), images_, *mirrored_);
  } catch (const Error& e) {
    refusal = e.what();
    mirrored_.reset();
    images_.clear();
    return std::nullopt;
  }
}

}  // namespace gps
