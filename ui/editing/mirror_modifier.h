#pragma once
// The mirror modifier, as Blender's: the document keeps the half being edited while the editor shows
// it with its mirror image about the plane x, y or z = 0, merged along the seam (core's mirror). An
// edit of the half's Gaussians is shown on both sides by index: mirror() keeps the half's vertices
// first (core/modelling/mirror.h), so the shown mesh's vertex v < n is the document's vertex v.
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/modelling/mesh_arrays.h"
#include "ui/document/editor_document.h"

namespace gps {

/// What the modifier does, kept per file in the editor's settings (the covariance PLY has no place for
/// an editor's settings).
struct MirrorSettings {
  bool enabled = false;
  int axis = 0;          // the plane x (0), y (1) or z (2) = 0
  bool clipping = true;  // vertices on the plane stay on it when moved, so that the seam never opens
  bool operator==(const MirrorSettings&) const = default;
};

class MirrorModifier {
public:
  MirrorSettings settings;

  /// The mesh to show for `half`: its mirror, merged at the seam, when the modifier is on; else (or
  /// where core refuses the seam, whose one-line reason goes to `refusal`) `half` itself.
  const CovarianceMesh& shown(const CovarianceMesh& half, std::string& refusal);
  /// Whether the last shown() gave the mirror.
  bool mirroring() const { return mirrored_.has_value(); }
  /// After an edit of the Gaussians of `changed` vertices of `half` (of the topology last shown): sets
  /// them and their images on the shown mirror; returns its vertices that changed. The vertices merged
  /// stay those that lay on the plane when it was shown; without a mirror, `changed` itself. Where a
  /// merged vertex's Gaussian cannot be made symmetric the mirror is dropped (nullopt, the reason in
  /// `refusal`): the half must be shown again.
  std::optional<std::vector<int>> update(const CovarianceMesh& half, const std::vector<int>& changed,
                                         std::string& refusal);
  /// The clipping the document's edits of `half` keep (none where the modifier or clipping is off):
  /// the vertices within core's merge distance of the plane stay on it.
  std::optional<PlaneClip> clip(const CovarianceMesh& half) const;
  /// With clipping, an operation's `result` (made from `before`) without the faces it laid on the plane
  /// and the vertices only they used: the side of an extruded face's seam edge would close the seam the
  /// mirror merges along, and Blender's extrude leaves it open. Nothing where none lies there (or the
  /// modifier or clipping is off). Throws as delete_faces does, before anything changes.
  std::optional<Modelled> seam_kept_open(const CovarianceMesh& before, const Modelled& result) const;
  /// The shown mirror (mirroring() only).
  const CovarianceMesh& mirrored() const { return *mirrored_; }

private:
  std::optional<CovarianceMesh> mirrored_;
  std::vector<int> images_;  // each vertex's image in mirrored_ (core's mirror_images)
};

}  // namespace gps
