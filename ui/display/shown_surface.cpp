#include "ui/display/shown_surface.h"

#include <utility>

namespace gps {

ShownSurface::ShownSurface() : renderer_(std::make_unique<SurfaceRenderer>()) {}

std::string ShownSurface::show(const CovarianceMesh& mesh, const PlanOptions& plans,
                               std::optional<ReplannedTables> surface, const std::vector<int>& origin) {
  MirrorModifier next;
  next.settings = mirror_.settings;
  std::string refusal;
  const CovarianceMesh& shown = next.shown(mesh, refusal);
  if (next.mirroring()) {
    renderer_->set_mesh(shown, plans);
  } else if (surface) {  // a sharpness change: the vertices keep their indices
    renderer_->set_mesh(mesh, std::move(surface->tables), renderer_->frame().following(mesh), surface->change, {});
  } else {  // re-planned where the mesh changed (a wrong origin costs time, never a wrong table)
    if (plans_ && plans_->options() == plans)
      plans_->set_topology(mesh, origin);
    else
      plans_.emplace(mesh, plans);
    renderer_->set_mesh(mesh, plans_->shared_tables(), renderer_->frame().following(mesh), plans_->last_change(),
                        origin);
  }
  mirror_ = std::move(next);
  ++revision_, ++topology_revision_;
  return refusal;
}

std::string ShownSurface::show_edit(const CovarianceMesh& document, const std::vector<int>& changed,
                                    const PlanOptions& plans) {
  std::string refusal;
  if (!mirror_.mirroring()) {
    renderer_->update_vertices(document, changed);
  } else if (const auto shown = mirror_.update(document, changed, refusal)) {
    renderer_->update_vertices(mirror_.mirrored(), *shown);
  } else {  // the half alone, as the modifier shows it where it refuses the seam
    renderer_->set_mesh(document, plans);
    ++topology_revision_;
  }
  ++revision_;
  return refusal;
}

void ShownSurface::set_preview(std::shared_ptr<const CovarianceMesh> mesh, std::vector<int> selected) {
  preview_ = std::move(mesh);
  preview_selection_ = std::move(selected);
}

void ShownSurface::clear_preview() {
  preview_.reset();
  preview_selection_.clear();
}

}  // namespace gps
