#pragma once
// Which vertices an edit of the selection reaches, and how strongly: the selection itself, with
// proportional editing every vertex within a radius of it (weight by a falloff curve of the
// distance to the nearest selected vertex), and with mirror editing the vertex at the mirrored
// position of each of those (matched within a tolerance).
#include <vector>

#include "core/edit/gaussian_change.h"
#include "core/mesh/linalg.h"

namespace gps {

class EditorDocument;

enum class Falloff { smooth, linear, sharp, constant };
constexpr const char* kFalloffNames = "smooth\0linear\0sharp\0constant\0";

/// The weight of a vertex at `t` = distance / radius ∈ [0, 1] (1 at the selection, 0 at the radius):
/// smooth 1 − (3t² − 2t³), linear 1 − t, sharp (1 − t)², constant 1.
double falloff_weight(Falloff falloff, double t);

struct ReachOptions {
  bool proportional = false;
  double radius = 0.5;
  Falloff falloff = Falloff::smooth;
  bool mirror = false;
  int mirror_axis = 0;             // mirror across the plane x (0), y (1) or z (2) = 0
  double mirror_tolerance = 1e-6;  // world distance within which positions match
};

struct ReachedVertex {
  int vertex = -1;
  double weight = 1.0;
  size_t source = 0;      // the selected vertex (index into the selection) whose change it takes
  bool mirrored = false;  // takes that change mirrored
};

/// The reach of an edit of `selected` (vertex indices into `means`, the start positions). The
/// vertices `hidden` marks 1 (the editor's H) are never reached, nor taken as mirror partners.
std::vector<ReachedVertex> edit_reach(const std::vector<Vec3>& means, const std::vector<int>& selected,
                                      const ReachOptions& options, const std::vector<char>* hidden = nullptr);

/// Sets every reached vertex to its start value with its source's change applied at its weight
/// (mirrored where it is the mirror image). Covariances stay SPD.
void apply_reach(EditorDocument& document, const std::vector<ReachedVertex>& reach,
                 const std::vector<GaussianChange>& changes, int mirror_axis);

}  // namespace gps
