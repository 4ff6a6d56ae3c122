#pragma once
// Plans that follow sharpness changes on one topology (a crease dragged in the editor): a changed edge
// or vertex is read only by the plans of the faces whose piece holds it, so only their ranges are
// built again (core/plans/range_plans.h), and the merged tables are those of a full re-plan, bit for bit.
#include <algorithm>
#include <memory>
#include <vector>

#include "core/extraordinary/loop_crease_tables.h"
#include "core/extraordinary/quad_extraordinary_tables.h"
#include "core/patches/local_mesh.h"
#include "core/plans/planned_surface.h"
#include "core/plans/range_plans.h"

namespace gps {

/// The faces whose plans read the sharpness of edge e or vertex v of `c`. A face's plan reads only its
/// piece, the faces that share a vertex with it (extract_neighbourhood, the regular nets, the exact
/// nodes' neighbourhoods and the sectors all stay in it, at every level), so these are the faces
/// sharing a vertex with a face that holds e (or v). Sorted, without repeats.
std::vector<int> faces_reading(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<int>& edges,
                               const std::vector<int>& vertices);

class SharpnessReplanner {
public:
  /// The faces built together; a change builds again the ranges of the faces it reaches.
  static constexpr int kFacesPerRange = 256;

  /// The plans of `topology` with `sharpness` under `options`, as build_surface_plans makes them, in
  /// ranges of `faces_per_range` faces (which the tables do not depend on). Throws as it does.
  SharpnessReplanner(const PolygonTopology& topology, const PlanOptions& options, const Sharpness& sharpness,
                     int faces_per_range = kFacesPerRange);

  Scheme scheme() const { return scheme_; }
  /// build_surface_plans(topology, options, sharpness) for the latest sharpness, bit for bit.
  const SurfaceTables& tables() const { return tables_; }
  /// Re-plans for new sharpness of the same topology: builds again only the ranges of the faces that
  /// read a changed edge or vertex (every face where the mesh gains its first sharpness or loses its
  /// last: the plans' depth bound and Loop's smooth builder change then). Returns the faces that read
  /// a change, sorted (empty: nothing changed). Throws gps::Error for a crease between unjoined
  /// vertices, the tables unchanged.
  std::vector<int> set_sharpness(const Sharpness& sharpness);

private:
  // Builds the ranges `which` on all cores, then merges every range into tables_.
  void build(const std::vector<int>& which, const Sharpness& sharpness);
  int n_ranges() const;

  PlanOptions options_;
  Scheme scheme_;
  int faces_per_range_;
  LocalMesh base_;  // the topology with the latest sharpness laid out on it
  std::unique_ptr<QuadExtraordinaryTableCache> quad_tables_;
  std::unique_ptr<LoopCreaseTables> loop_tables_;
  std::vector<RangePlans> ranges_;  // empty for Loop without sharpness (its smooth builder)
  SurfaceTables tables_;
};

}  // namespace gps
