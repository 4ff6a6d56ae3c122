#pragma once
// Modelling operations as data, for scripts: a JSON array of objects such as
//   [{"op": "loop_cut", "edge": [0, 1], "cuts": 2}, {"op": "extrude", "faces": [4], "distance": 0.5}]
// applied in order, every index referring to the mesh as it stands before that operation (file
// order for the first). docs/command_line.md lists every operation and its keys.
#include <deque>
#include <functional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

class OperationList {
public:
  /// Reads the operations from JSON text; `source` names the text in errors ("ops.json"). Throws a
  /// usage error naming the operation ("ops.json: ops[2] (extrude): \"distance\" must be a number")
  /// for anything malformed, before any operation is applied.
  static OperationList parse(const std::string& json_text, const std::string& source);

  size_t size() const { return steps_.size(); }
  /// The operations' names in order ("loop_cut", ...).
  std::vector<std::string> names() const;

  /// Applies every operation in order to a copy of `mesh`. On a refusal throws gps::Error naming the
  /// operation and why ("ops.json: ops[1] (merge): ..."); nothing is changed. `summaries` gets one
  /// line per operation applied.
  Modelled apply(const CovarianceMesh& mesh, std::vector<std::string>* summaries = nullptr) const;

private:
  /// Refuses, with its figures, the run of whole-mesh subdivisions starting at step `first` where its
  /// result would not fit the memory budget (core/support/memory_budget.h), before any of them.
  void check_subdivisions(size_t first, const CovarianceMesh& mesh) const;

  /// What a step does: make its result from the mesh; or, for a step made on arrays (an addition, a
  /// deletion, an extrusion or inset of faces) that checks what it makes as the mesh's build would,
  /// change the arrays of a run of such steps, which build their mesh and its connectivity once, after
  /// the last; or, for an operation on Gaussians or sharpness only, change the list's own copy of the
  /// mesh in place at the cost of what it changes. The last two return the selection and set the
  /// summary. One of them held: a list of a million steps holds no empty ones.
  using MakeStep = std::function<Modelled(const CovarianceMesh&)>;
  using AppendStep = std::function<std::vector<int>(MeshArrays&, std::string&)>;
  using InPlaceStep = std::function<std::vector<int>(CovarianceMesh&, std::string&)>;
  struct Step {
    std::string_view name;  // one of operation_names(), which live as long as the program
    std::variant<MakeStep, AppendStep, InPlaceStep> action;
    bool subdivides_whole_mesh = false;
    const AppendStep* append() const { return std::get_if<AppendStep>(&action); }
    const InPlaceStep* in_place() const { return std::get_if<InPlaceStep>(&action); }
  };
  std::deque<Step> steps_;  // grown without copies or spare capacity
  std::string source_;
};

/// The operation names OperationList knows, for help texts.
std::vector<std::string> operation_names();

}  // namespace gps
