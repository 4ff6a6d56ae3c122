// The repair's report in words: what each step changed (its lines), the defect classes with their
// counts and first examples numbered as the file numbers its elements, and the refusal naming the fix.
#include <algorithm>
#include <string>
#include <vector>

#include "core/io/mesh_repair.h"

namespace gps {

namespace {

std::string plural(int n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

bool RepairReport::changed() const {
  for (int d = 0; d < kDefectCount; ++d)
    if (counts[size_t(d)] > 0 && Defect(d) != Defect::unorientable_parts) return true;
  return false;
}

std::vector<std::string> RepairReport::lines() const {
  std::vector<std::string> out;
  const auto n = [&](Defect d) { return count(d); };
  if (n(Defect::coincident_vertices))
    out.push_back("welded " + plural(n(Defect::coincident_vertices), "coincident vertex", "coincident vertices") +
                  " into " + std::to_string(welded_groups));
  if (n(Defect::repeated_corners))
    out.push_back("removed repeated corners from " + plural(n(Defect::repeated_corners), "face", "faces") +
                  (split_faces ? " (" + std::to_string(split_faces) + " split into loops)" : ""));
  if (n(Defect::degenerate_faces))
    out.push_back("dropped " + plural(n(Defect::degenerate_faces), "degenerate face", "degenerate faces") +
                  " (fewer than 3 distinct corners)");
  if (n(Defect::zero_area_faces))
    out.push_back("dropped " + plural(n(Defect::zero_area_faces), "zero-area face", "zero-area faces"));
  if (n(Defect::duplicate_faces))
    out.push_back("dropped " + plural(n(Defect::duplicate_faces), "duplicate face", "duplicate faces"));
  // Where every face on the fins found a partner, the fins are cut between their sheets, no face apart.
  if (n(Defect::fin_edges))
    out.push_back((fin_faces > 0 ? "separated " + plural(fin_faces, "face", "faces") + " from "
                                 : std::string("cut the sheets apart at ")) +
                  plural(n(Defect::fin_edges), "edge", "edges") + " with more than two faces (" +
                  plural(fin_copies, "vertex copy", "vertex copies") + ")");
  if (n(Defect::pinch_vertices))
    out.push_back("split " + plural(n(Defect::pinch_vertices), "pinch vertex", "pinch vertices") + " (" +
                  plural(pinch_copies, "copy", "copies") + " added, one per extra fan)");
  if (n(Defect::flipped_faces))
    out.push_back("flipped " + plural(n(Defect::flipped_faces), "face", "faces") + " to orient each part consistently");
  if (n(Defect::unorientable_parts))
    out.push_back(plural(n(Defect::unorientable_parts), "part cannot", "parts cannot") + " be oriented (Möbius-like)");
  if (n(Defect::isolated_vertices))
    out.push_back("dropped " + plural(n(Defect::isolated_vertices), "isolated vertex", "isolated vertices"));
  if (orphaned_vertices)
    out.push_back("dropped " + plural(orphaned_vertices, "vertex", "vertices") + " left in no face");
  if (dropped_creases)
    out.push_back("dropped " + plural(dropped_creases, "crease", "creases") + " no longer on an edge");
  return out;
}

namespace {

// Per class: its name for a count of one and of more, and what --repair does to one and to more.
struct DefectWords {
  const char *one, *many, *mend_one, *mend_many;
};
constexpr DefectWords kDefectWords[kDefectCount] = {
    {"coincident vertex", "coincident vertices", "--repair welds it", "--repair welds them"},
    {"face with a repeated corner", "faces with a repeated corner", "--repair removes the repeat",
     "--repair removes the repeats"},
    {"degenerate face (fewer than 3 distinct corners)", "degenerate faces (fewer than 3 distinct corners)",
     "--repair drops it", "--repair drops them"},
    {"zero-area face", "zero-area faces", "--repair drops it", "--repair drops them"},
    {"duplicate face (on the vertices of an earlier one)", "duplicate faces (on the vertices of an earlier one)",
     "--repair drops it", "--repair drops them"},
    {"non-manifold edge (a fin: more than two faces)", "non-manifold edges (fins: more than two faces)",
     "--repair gives the extra faces their own vertices", "--repair gives the extra faces their own vertices"},
    {"non-manifold (pinch) vertex", "non-manifold (pinch) vertices", "--repair splits it", "--repair splits them"},
    {"face oriented against its neighbours", "faces oriented against their neighbours", "--repair flips it",
     "--repair flips them"},
    {"part that cannot be oriented (Möbius-like)", "parts that cannot be oriented (Möbius-like)",
     "no repair orients it (delete faces across it to cut it open, then repair)",
     "no repair orients them (delete faces across each to cut it open, then repair)"},
    {"isolated vertex (in no face)", "isolated vertices (in no face)", "--repair drops it", "--repair drops them"},
};

std::string example_text(Defect d, const DefectExample& e, const ElementNumbering& n) {
  switch (d) {
    case Defect::coincident_vertices:
      return n.vertex(e.element) + " at " + n.vertex(e.other);
    case Defect::duplicate_faces:
      return n.face(e.element) + " as " + n.face(e.other);
    case Defect::fin_edges:
      return "the edge of " + n.vertex(e.element) + " and " + n.vertex(e.other) + " with " + std::to_string(e.count) +
             " faces" + (e.welded ? " once coincident vertices are welded" : "");
    case Defect::pinch_vertices:
      return n.vertex(e.element) + " with " + std::to_string(e.count) + " fans" +
             (e.welded ? " once coincident vertices are welded" : "");
    case Defect::unorientable_parts:
      return "the part of " + n.face(e.element);
    case Defect::isolated_vertices:
      return n.vertex(e.element);
    default:
      return n.face(e.element);
  }
}

bool names_vertices(Defect d) {
  return d == Defect::coincident_vertices || d == Defect::fin_edges || d == Defect::pinch_vertices ||
         d == Defect::isolated_vertices;
}

std::string element_name(const char* kind, int index, const ElementNumbering& n,
                         const std::unordered_map<int, int>& lines) {
  const auto line = lines.find(index);
  return std::string(kind) + " " + n.number(index) +
         (line == lines.end() ? "" : " (line " + std::to_string(line->second) + ")");
}

}  // namespace

std::string ElementNumbering::vertex(int v) const { return element_name("vertex", v, *this, vertex_lines); }
std::string ElementNumbering::face(int f) const { return element_name("face", f, *this, face_lines); }

bool is_refused(Defect d) {
  return d != Defect::coincident_vertices && d != Defect::zero_area_faces && d != Defect::isolated_vertices;
}

bool RepairReport::refuses() const {
  for (int d = 0; d < kDefectCount; ++d)
    if (counts[size_t(d)] > 0 && is_refused(Defect(d))) return true;
  return false;
}

std::vector<std::string> RepairReport::problems(const ElementNumbering& numbering, bool refused) const {
  std::vector<std::string> out;
  for (int d = 0; d < kDefectCount; ++d) {
    if (counts[size_t(d)] == 0 || is_refused(Defect(d)) != refused) continue;
    std::string line = kDefectWords[d].many + std::string(": ") + std::to_string(counts[size_t(d)]);
    const char* sep = " (";
    for (const DefectExample& e : examples[size_t(d)])
      line += std::exchange(sep, "; ") + example_text(Defect(d), e, numbering);
    // Of a group of coincident vertices, the ones welded to its lowest are the examples.
    const int instances = counts[size_t(d)] - (Defect(d) == Defect::coincident_vertices ? welded_groups : 0);
    if (instances > int(examples[size_t(d)].size())) line += "; ...";
    out.push_back(line + ")");
  }
  return out;
}

std::string RepairReport::refusal(const ElementNumbering& numbering, bool every_class) const {
  std::string out;
  for (int d = 0; d < kDefectCount; ++d) {
    const int n = counts[size_t(d)];
    if (n == 0 || !(every_class || is_refused(Defect(d)))) continue;
    const DefectWords& w = kDefectWords[d];
    out += (out.empty() ? "" : "; ") + std::to_string(n) + " " + (n == 1 ? w.one : w.many) + ", " +
           (n == 1 ? "" : "the first ") + example_text(Defect(d), examples[size_t(d)].front(), numbering) + "; " +
           (n == 1 ? w.mend_one : w.mend_many);
  }
  return out;
}

void RepairReport::named_elements(std::vector<int>& vertices, std::vector<int>& faces) const {
  for (int d = 0; d < kDefectCount; ++d)
    for (const DefectExample& e : examples[size_t(d)]) {
      auto& list = names_vertices(Defect(d)) ? vertices : faces;
      list.push_back(e.element);
      if (e.other >= 0) list.push_back(e.other);
    }
}

}  // namespace gps
