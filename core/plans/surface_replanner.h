#pragma once
// Plans that follow changes of a mesh: a crease dragged in the editor, or a modelling operation that
// changes the topology. A face's plan reads only its piece (the faces that share a vertex with it) and
// the sharpness in it, so only the ranges of faces whose pieces a change reaches are built again
// (core/plans/range_plans.h); the others are kept, renumbered, and the merged tables are those of a
// full re-plan, bit for bit.
#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "core/extraordinary/loop_crease_tables.h"
#include "core/extraordinary/loop_extraordinary_tables.h"
#include "core/extraordinary/quad_extraordinary_tables.h"
#include "core/patches/local_mesh.h"
#include "core/plans/kept_patches.h"
#include "core/plans/patch_adjacency.h"
#include "core/plans/planned_surface.h"
#include "core/plans/range_plans.h"

namespace gps {

/// The faces whose plans read the sharpness of edge e or vertex v of `c`. A face's plan reads only its
/// piece, the faces that share a vertex with it (extract_neighbourhood, the regular nets, the exact
/// nodes' neighbourhoods and the sectors all stay in it, at every level), so these are the faces
/// sharing a vertex with a face that holds e (or v). Sorted, without repeats.
std::vector<int> faces_reading(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<int>& edges,
                               const std::vector<int>& vertices);

/// The faces that share a vertex with one of `faces` (those among them), sorted, without repeats.
std::vector<int> faces_around(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<int>& faces);

/// The last change of a replanner's tables: the tables it went from and to, named by ids unique in the
/// process (0: none), and the patches whose plans it kept, in runs in the new tables' order (empty
/// after a full build; where faces were reordered, the old numbering may not increase).
struct PlanChange {
  long long from = 0, to = 0;
  std::vector<KeptPatches> kept;
  /// The kept patches (ascending) whose adjacency records may differ from those they had, renumbered
  /// (core/plans/kept_patch_records.h): those on faces that share a vertex with a face whose plans were
  /// not kept. Unset: any kept patch's may.
  std::optional<std::vector<int>> relinked;
  /// The stencil rows kept, in runs in the new tables' order (both numberings increase): rows of kept
  /// ranges, the same terms as those rows had, their base vertices renumbered as the change's origin
  /// says (a renderer computes again only the others, and those that read a vertex whose Gaussian
  /// changed).
  std::vector<KeptStencilRows> kept_rows;
  /// Where every kept patch kept its number and the adjacency records followed them (update_patch_adjacency,
  /// core/plans/patch_adjacency.h): the patches (ascending) whose edge records (patch_neighbours) were
  /// written, new ones among them, and those whose corner owners were, where known. Every other
  /// patch's records are those it had: a renderer sends only these. Unset: any may differ.
  std::optional<std::vector<int>> neighbours_written, owners_written;
  /// The leading patches whose plan records (nodes, roots, corner points, edges) are those of the
  /// tables before, bit for bit, and their nodes: a renderer compares only the records past them.
  LeadingRecords same_leading;
};

/// A replanner's tables with the change that made them, as a renderer takes them (shared: a
/// replanner makes new tables for every change and never changes those it handed out).
struct ReplannedTables {
  std::shared_ptr<const SurfaceTables> tables;
  PlanChange change;
};

class SurfaceReplanner {
public:
  /// The faces built together; a change builds again the faces it reaches, and keeps the runs of a
  /// range between them.
  static constexpr int kFacesPerRange = 1024;

  /// The plans of `topology` with `sharpness` under `options`, as build_surface_plans makes them, in
  /// ranges of `faces_per_range` faces (which the tables do not depend on). Throws as it does.
  SurfaceReplanner(const PolygonTopology& topology, const PlanOptions& options, const Sharpness& sharpness,
                   int faces_per_range = kFacesPerRange);
  /// The same for a mesh's faces and sharpness, reading the connectivity it holds.
  SurfaceReplanner(const CovarianceMesh& mesh, const PlanOptions& options, int faces_per_range = kFacesPerRange);

  Scheme scheme() const { return scheme_; }
  const PlanOptions& options() const { return options_; }
  const PolygonTopology& topology() const { return base_.topology(); }
  /// build_surface_plans(topology, options, sharpness) for the latest topology and sharpness, bit for bit.
  const SurfaceTables& tables() const { return *tables_; }
  /// The same tables, shared (a renderer keeps them without a copy).
  std::shared_ptr<const SurfaceTables> shared_tables() const { return tables_; }
  /// Re-plans for new sharpness of the same topology: builds again only the faces that read a changed
  /// edge or vertex, and the short runs between them (every face where the mesh gains its first
  /// sharpness or loses its last: the plans' depth bound and Loop's builder change then).
  /// Returns the faces that read a change, sorted (empty: nothing changed). Throws gps::Error for a
  /// crease between unjoined vertices, the tables unchanged.
  std::vector<int> set_sharpness(const Sharpness& sharpness);
  /// Re-plans for a new topology. `origin`: per new vertex, the index it had before (−1: new); empty
  /// stands for "every vertex kept its index". A run of a range's faces is kept, renumbered, where its
  /// faces are all still there, consecutive and in order, and no piece of theirs changed (a face added,
  /// removed or changed around one of their vertices, or sharpness there): a whole range, or a run cut
  /// out of one (core/plans/range_plans.h, cut_range); the other faces are built again. The
  /// origin only says where to look: a wrong one costs time, never a wrong table. Everything is built
  /// again when the scheme changes, when sharpness first comes or last goes, or when the origin is not
  /// increasing. The same faces, sharpness and vertices keep the tables as
  /// they are (a change of the Gaussians alone). Returns how many faces were planned. Throws as the
  /// constructor does, the tables unchanged.
  int set_topology(const PolygonTopology& topology, const Sharpness& sharpness, const std::vector<int>& origin = {});
  /// The same for a mesh's faces and sharpness, reading the connectivity it holds. A mesh that shares
  /// the planned mesh's faces (CovarianceMesh::shape), every vertex where it was and sharp before and
  /// after, is re-planned as set_sharpness does.
  int set_topology(const CovarianceMesh& mesh, const std::vector<int>& origin = {});
  /// How many ranges the faces are built in: changes cut the ranges
  /// they reach, and short ones are joined to a neighbour where both fit in one once changes have left
  /// both alone for a while, so there are at most about four times as many as the faces fill, and the
  /// pieces of the last few changes.
  int n_ranges() const { return int(ranges_.size()); }
  /// What the last set_sharpness or set_topology kept (after the constructor: from 0, nothing kept).
  /// A renderer evaluates again only the other patches.
  const PlanChange& last_change() const { return change_; }
  /// The tables and the last change.
  ReplannedTables replanned() const { return {tables_, change_}; }

private:
  // The constructors' work, the base piece of the mesh built.
  SurfaceReplanner(LocalMesh&& base, const PlanOptions& options, const Sharpness& sharpness, int faces_per_range);
  // The plan builders' checks of a topology under `scheme` (valences, depth); throws as they do.
  void check(const PolygonTopology& topology, const MeshConnectivity& connectivity, Scheme scheme) const;
  // Whether `topology` has the base's faces, every vertex where it was (`origin` as set_topology takes it).
  bool same_faces(const PolygonTopology& topology, const std::vector<int>& origin) const;
  // Whether `topology` and `sharpness` are those planned, every vertex where it was (`origin` as
  // set_topology takes it): a change of the Gaussians alone, such as a transform as an operation.
  bool same_surface(const PolygonTopology& topology, const Sharpness& sharpness, const std::vector<int>& origin) const;
  // The change to the same tables under a new id, every patch kept.
  void keep_every_plan();
  // set_topology's work, the new mesh's base piece built and checked under `scheme`.
  int replan(LocalMesh&& base, Scheme scheme, const Sharpness& sharpness, const std::vector<int>& origin);
  // Per old face of `old` the face of base_ with its corners under `new_index` (−1: gone), and back.
  void match_faces(const PolygonTopology& old, const std::vector<int>& new_index, std::vector<int>& new_face,
                   std::vector<int>& old_face) const;
  // The plans of base_ from those of `old`: per old face its new face (−1: gone) and back, which new
  // faces read a change (`dirty`), and per old vertex its new index (`same_base`: each kept its own).
  // Keeps, renumbered, every run of clean faces that fits (see set_topology), builds the others and
  // merges them all. Returns how many faces were planned.
  int keep_runs_and_build(const PolygonTopology& old, const std::vector<int>& new_face,
                          const std::vector<int>& old_face, const std::vector<char>& dirty,
                          const std::vector<int>& new_index, bool same_base, const Sharpness& sharpness);
  // Builds the ranges `which` on all cores, then merges every range into tables_. `old_patch_first`:
  // per range, where its patches started before the change (−1: built now); empty: none kept.
  // `old_face_patch`: per face, where the patches of the face it was started before, where its plan is
  // the same (its piece unchanged; −1 otherwise): a range built again keeps those patches' place in
  // the change (PlanChange::kept). Empty: none.
  // `same_leading`: the first ranges are the tables_' first, unchanged (merge_ranges copies their part).
  void build(const std::vector<int>& which, const Sharpness& sharpness, const std::vector<int>& old_patch_first = {},
             const std::vector<int>& old_face_patch = {}, size_t same_leading = 0);
  // The kept patches whose adjacency records may differ (PlanChange::relinked): those of the faces that
  // share a vertex with a face whose patches are not all kept (built again, or new). Any patch a kept
  // patch's records name, or named before, lies on a face sharing a vertex with its own, and a face
  // that shared one with a face now gone reads a changed vertex: built again.
  std::vector<int> kept_beside_built(const std::vector<KeptPatches>& kept) const;
  // Joins each short range to the one before it, or the one after it to it, where their faces together
  // are at most faces_per_range_ and both were kept whole through the last kSettledChanges changes
  // (append_range): a change cuts the ranges it reaches into pieces, which would otherwise never join
  // again, and every range's rows are merged anew, those it shares with a neighbour once per range.
  // Longer pieces stay as they are (joining them costs a copy of each), and so do those where changes
  // go on (an edit repeated there, or undone and redone, keeps them whole). The tables stay as they are.
  void join_short_ranges();
  // A range of fewer faces is short.
  int short_range_faces() const { return std::max(1, faces_per_range_ / 4); }
  static constexpr int kSettledChanges = 4;
  // Cuts the faces into even ranges and builds them all.
  void build_all(const Sharpness& sharpness);
  // The fewest faces a run cut out of a range that a change reaches keeps (fewer are built again with
  // the faces beside them): cutting many short runs costs more than building them, and leaves ranges
  // of a few faces behind.
  int min_run_faces() const { return std::clamp(faces_per_range_ / 16, 1, 16); }

  PlanOptions options_;
  Scheme scheme_;
  int faces_per_range_;
  LocalMesh base_;       // the topology with the latest sharpness laid out on it
  Sharpness sharpness_;  // as last given
  std::unique_ptr<QuadExtraordinaryTableCache> quad_tables_;
  std::unique_ptr<LoopExtraordinaryTableCache> loop_tables_;  // Loop without sharpness
  std::unique_ptr<LoopCreaseTables> loop_crease_tables_;
  std::vector<RangePlans> ranges_;
  std::vector<int> range_first_;    // range r holds faces [range_first_[r], range_first_[r + 1])
  std::vector<int> range_kept_;     // per range: the changes it was kept whole through since it was built or cut
  std::vector<int> patch_first_;    // range r's first patch in tables_
  PlanChange change_;
  // Never changed once made (shared_tables); not const, so that as retired_ their storage can be reused.
  std::shared_ptr<SurfaceTables> tables_ = std::make_shared<SurfaceTables>();
  std::shared_ptr<SurfaceTables> retired_;  // the tables before tables_, whose storage the next merge reuses
                                            // once nothing else holds them
  size_t tables_leading_ = 0;               // the first ranges tables_ was merged from, unchanged from retired_'s
  AdjacencyWrites adjacency_writes_;        // what tables_' adjacency records changed of retired_'s
};

}  // namespace gps
