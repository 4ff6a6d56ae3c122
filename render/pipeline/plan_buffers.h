#pragma once
// The GPU tables of a planned surface (docs/design.md §2): core's plan and stencil tables (built outside
// the renderer, core/plans/planned_surface.h) as shader storage buffers at the bindings of
// render/gl/gpu_layout.h, with the base Gaussians, the plan points the compute passes write and an
// edit's lists of changed vertices and stencil rows. The plan points and base Gaussians are float or
// double (render/gl/point_precision.h).
#include <array>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "render/gl/normalised_frame.h"
#include "core/plans/plan_builder.h"
#include "core/plans/surface_replanner.h"
#include "render/gl/gl_object.h"
#include "render/gl/gpu_layout.h"
#include "render/gl/point_precision.h"

namespace gps {

class PlanBuffers {
public:
  /// Needs a current GL context.
  PlanBuffers();
  PlanBuffers(const PlanBuffers&) = delete;
  PlanBuffers& operator=(const PlanBuffers&) = delete;

  /// Throws gps::Error if a table exceeds the device's storage block size (or `storage_limit` > 0)
  /// with points of `precision`.
  static void check_fits(const SurfaceTables& tables, int n_vertices, int n_faces, long long storage_limit,
                         PointPrecision precision);
  /// The precision of the points and Gaussians that upload_tables and upload_gaussians upload next.
  void set_precision(PointPrecision precision) { precision_ = precision; }
  PointPrecision precision() const { return precision_; }
  /// The points a change of topology carries over: the base vertices, by each vertex's index before it
  /// (`origin`, empty: the same) but for those whose Gaussians are new or changed (changed_gaussians),
  /// and the stencil rows kept (`rows`, PlanChange::kept_rows: rows of the tables before from their
  /// point `old_first_row` on).
  struct CarriedPoints {
    const std::vector<int>& origin;
    const std::vector<int>& changed;
    const std::vector<KeptStencilRows>& rows;
    int old_first_row = 0;
  };
  /// The plan and stencil tables, storage for the plan points (for a full compute pass to write), and
  /// for the corner pass's output, but for the `kept` runs of patches, whose corner-pass output is copied
  /// from the previous tables' (of the same patch shape; kept_runs_fit, render/pipeline/kept_corner_output.h).
  /// With `carried` (points of the same precision and frame before), the points of the base vertices
  /// not among its changed ones, and of the kept rows, are copied from the previous points to where
  /// they went, in runs: the compute pass then maps the changed vertices alone, and the other rows.
  /// `held`: the tables the buffers hold now (the last uploaded), where known: a table whose storage
  /// stays is written only where it differs from them (an operation's change leaves most of the tables
  /// as they were: renumbered past a change where rows or patches are added before theirs, else alike).
  /// `change`: the change that made `tables` from `held`, where known: of the adjacency records, those
  /// of the patches it lists as written (PlanChange::neighbours_written, owners_written) are sent, and
  /// no others compared.
  void upload_tables(const SurfaceTables& tables, const std::vector<KeptPatches>& kept = {},
                     const CarriedPoints* carried = nullptr, const SurfaceTables* held = nullptr,
                     const PlanChange* change = nullptr);
  /// Every base vertex's μ and Σ.
  void upload_gaussians(const FramedGaussians& gaussians);
  /// Every base vertex's μ and Σ after a change of topology, in the precision of the buffer before:
  /// a vertex not among the `changed` (changed_gaussians, which new vertices are among) takes its
  /// `origin`'s values from that buffer, copied on the GPU in runs; the changed ones are uploaded.
  void carry_gaussians(const FramedGaussians& gaussians, const std::vector<int>& origin,
                       const std::vector<int>& changed);
  /// The `changed` vertices' μ and Σ.
  void update_gaussians(const FramedGaussians& gaussians, const std::vector<int>& changed);
  /// An edit's changed vertices and the stencil rows that read them, for the listed compute passes.
  void upload_edit(const std::vector<int>& changed, const std::vector<int>& rows);
  /// The corner pass's items (render/pipeline/corner_limit_pass.h).
  void upload_corner_list(const std::vector<int>& items);
  /// Zeroes the corner pass's output for the plans' corners, ahead of a pass over every evaluation.
  void clear_corner_pass(const PatchPlans& plans);
  /// Binds every buffer at its binding.
  void bind() const;
  /// The plan points as the compute passes left them (gpu::kVec4PerPoint vec4 each; double ones
  /// rounded to float).
  std::vector<float> read_points(int n_points) const;
  /// `read` given the corner pass's output (render/pipeline/corner_limit_pass.h), mapped: two vec4
  /// per patch corner, the limit point and node kind, then the normal; zero at a corner its owner's
  /// slot holds. (The edge midpoints are a buffer of their own, kBindingCurveMidpoints: within one,
  /// a mesh of a million faces passed the largest storage block llvmpipe allows.)
  void read_corner_limits(const std::function<void(const float*)>& read) const;
  /// The corner pass's output: the corner limits (as read_corner_limits gives them), then the curve
  /// midpoints (one vec4 per patch corner).
  std::vector<float> read_corner_pass() const;
  /// The 32-bit words in use at `binding` (a table's ints, or its floats' bits): what its uploads left.
  std::vector<uint32_t> read_words(int binding) const;
  /// GPU memory held, in bytes.
  size_t bytes() const;

private:
  template <size_t... I>
  static std::array<GlBuffer, sizeof...(I)> no_buffers(std::index_sequence<I...>) {
    return {((void)I, GlBuffer::none())...};
  }
  static size_t corner_limit_floats(const PatchPlans& plans);    // two vec4 per patch corner
  static size_t curve_midpoint_floats(const PatchPlans& plans);  // one vec4 per patch corner
  /// False where it allocated new storage (the contents before are gone).
  bool reserve(int binding, size_t bytes);
  /// Whether reserve(binding, bytes) keeps the storage there, and so its contents.
  bool keeps_storage(int binding, size_t bytes) const;
  unsigned swap_in_spare(int binding, size_t bytes);
  template <class Real>
  void upload_gaussians_as(const FramedGaussians& gaussians);
  template <class Real>
  void carry_gaussians_as(const FramedGaussians& gaussians, const std::vector<int>& origin,
                          const std::vector<int>& changed);
  template <class Real>
  void update_gaussians_as(const FramedGaussians& gaussians, const std::vector<int>& changed);
  /// `data` as type T; where `held` (what the buffer holds, as uploaded from it) is given and the
  /// storage stays, only the chunks of elements that differ from it (bit for bit) and those past its end,
  /// or where `listed` is given too, the records of `stride` elements it lists (all the others are held's)
  /// and those past its end. The first `same` elements are known to be held's (not compared).
  template <class T, class Source>
  void upload_as(int binding, const std::vector<Source>& data, const std::vector<Source>* held = nullptr,
                 const std::vector<int>* listed = nullptr, size_t stride = 0, size_t same = 0);
  template <class T>
  void upload(int binding, const std::vector<T>& data) {
    upload_as<T>(binding, data);
  }

  std::array<GlBuffer, gpu::kBindingCount> buffers_;
  size_t sizes_[gpu::kBindingCount] = {};       // bytes in use
  size_t capacities_[gpu::kBindingCount] = {};  // bytes of storage held
  // Per binding, the storage that takes turns with the one bound where a change of topology copies
  // from one to the other (none until then), and its bytes.
  std::array<GlBuffer, gpu::kBindingCount> spares_ = no_buffers(std::make_index_sequence<gpu::kBindingCount>());
  size_t spare_capacities_[gpu::kBindingCount] = {};
  size_t max_block_ = 0;                        // the device's largest storage block, in bytes
  PointPrecision precision_ = PointPrecision::single_float;
};

}  // namespace gps
