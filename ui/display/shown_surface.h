#pragma once
// What the editor shows of its document: the document's mesh, or a modal tool's preview in its place,
// through the mirror modifier; the renderer that draws it, and the plans that follow it from one mesh
// to the next. Every change of the surface shown comes through here and counts a revision: what
// follows the surface (a fit's target points, the patches hidden, the check for non-finite pixels)
// keeps the revision it last followed and compares (changed_since).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/plans/surface_replanner.h"
#include "render/pipeline/surface_renderer.h"
#include "ui/editing/mirror_modifier.h"

namespace gps {

class ShownSurface {
public:
  ShownSurface();  // a current GL context needed
  ShownSurface(const ShownSurface&) = delete;
  ShownSurface& operator=(const ShownSurface&) = delete;

  SurfaceRenderer& renderer() { return *renderer_; }
  const SurfaceRenderer& renderer() const { return *renderer_; }

  /// Gives the renderer `mesh` (the document's or a preview's): with the mirror modifier on, its mirror
  /// planned under `plans` (`surface` then unused); else `surface` (planned for `mesh` itself: a
  /// sharpness change), or plans that follow the mesh shown before (`origin`: each vertex's index in it,
  /// empty where kept). Throws gps::Error as set_mesh does, before anything changes. Returns why the
  /// modifier shows the half alone ("" where it does not).
  std::string show(const CovarianceMesh& mesh, const PlanOptions& plans,
                   std::optional<ReplannedTables> surface = std::nullopt, const std::vector<int>& origin = {});
  /// The Gaussians of the `changed` vertices of `document` (the mesh last shown), on both sides of the
  /// mirror. Where the mirror cannot follow them, the half is shown anew under `plans`; returns why ("").
  /// Throws gps::Error where the half cannot be shown either.
  std::string show_edit(const CovarianceMesh& document, const std::vector<int>& changed, const PlanOptions& plans);

  /// A modal tool's preview, shown in place of the document (show() it first), and the vertices it selects.
  void set_preview(std::shared_ptr<const CovarianceMesh> mesh, std::vector<int> selected);
  void clear_preview();
  const std::shared_ptr<const CovarianceMesh>& preview() const { return preview_; }
  const std::vector<int>& preview_selection() const { return preview_selection_; }
  /// The mesh the user edits on screen: the preview, else `document`.
  const CovarianceMesh& edited(const CovarianceMesh& document) const { return preview_ ? *preview_ : document; }
  /// The mesh the renderer draws for `half`, the mesh last shown: its mirror, else itself.
  const CovarianceMesh& drawn(const CovarianceMesh& half) const {
    return mirror_.mirroring() ? mirror_.mirrored() : half;
  }

  const MirrorModifier& mirror() const { return mirror_; }
  /// The modifier's settings for the next show().
  void set_mirror_settings(const MirrorSettings& settings) { mirror_.settings = settings; }

  /// Counts the new meshes shown (show(), and the half shown where the mirror refused an edit).
  std::uint64_t topology_revision() const { return topology_revision_; }
  /// For a follower that last followed revision `seen`: whether the surface changed since (any
  /// change; topology_changed_since: a new mesh), `seen` brought up to date.
  bool changed_since(std::uint64_t& seen) const { return std::exchange(seen, revision_) != revision_; }
  bool topology_changed_since(std::uint64_t& seen) const {
    return std::exchange(seen, topology_revision_) != topology_revision_;
  }

private:
  std::unique_ptr<SurfaceRenderer> renderer_;
  std::optional<SurfaceReplanner> plans_;  // the plans of the last mesh shown without a mirror
  MirrorModifier mirror_;
  std::shared_ptr<const CovarianceMesh> preview_;
  std::vector<int> preview_selection_;
  std::uint64_t revision_ = 0, topology_revision_ = 0;
};

}  // namespace gps
