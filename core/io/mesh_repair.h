#pragma once
// Repair of a mesh as people have them, on the polygon soup a reader produced and before it becomes a
// CovarianceMesh: coincident vertices welded, degenerate, zero-area and duplicate faces dropped, fins
// (edges with more than two faces) and pinch vertices (several fans at one vertex) separated, the
// orientation made consistent per connected part and isolated vertices dropped. Each step is counted
// in a report. The same code diagnoses a soup without changing it (gpsurf info).
//
// The result always makes a CovarianceMesh but for a part that no flipping orients (Möbius-like: its
// faces joined through edges of two faces alone), which is left as it is, counted and named. On a fin
// the faces of one sheet (faces joined through edges of two faces) that close it across the edge stay
// paired, however its faces were flipped; an extra face still joined to the kept ones through its
// other edges is cut from them at one end too, so that no edge of the result has more than two faces.
//
// Vertices that stay keep their Gaussian; a welded vertex keeps the one of its group's lowest index; a
// copy made by separating fans takes its original's. Vertices keep their order (welded and dropped ones
// removed), copies come after them; faces keep their order (dropped ones removed, pieces of a face
// that used a vertex twice in its place). Creases follow their vertices: an edge of the result between
// copies or welds of a creased edge's ends takes its sharpness (the largest where welded creases meet),
// and a crease on no edge of the result is dropped and counted; a vertex takes its group's largest
// corner. Everything runs in time linear in the soup (hash tables), however many vertices crowd into
// the weld tolerance, but for two crowds of vertices just over the tolerance apart.
#include <array>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/io/polygon_soup.h"
#include "core/support/progress.h"

namespace gps {

struct RepairOptions {
  double weld_tolerance = 1e-6;  // vertices closer than this times the bounding-box diagonal are welded
  ProgressReport progress;        // at the start and after each step; Cancelled leaves the soup part-repaired
};

/// How messages name a file's vertices and faces: numbered from `base` (1 in OBJ, 0 in PLY and OFF),
/// with the line each was read on where known (OBJ: only the named elements' lines are looked up).
struct ElementNumbering {
  int base = 0;
  std::unordered_map<int, int> vertex_lines, face_lines;  // by index from 0: the file's line
  std::string vertex(int v) const;                        // "vertex 67 (line 70)"
  std::string face(int f) const;
  std::string number(int v) const { return std::to_string(v + base); }
};

/// The defect classes, in the order the repair treats them.
enum class Defect {
  coincident_vertices,  // vertices within the weld tolerance of another (welded)
  repeated_corners,     // faces that list a vertex twice (the repeats removed, or split into loops)
  degenerate_faces,     // faces left with fewer than 3 distinct corners (dropped)
  zero_area_faces,      // faces thinner than the weld tolerance (dropped)
  duplicate_faces,      // faces on the same vertex set as an earlier face (dropped)
  fin_edges,            // edges with more than two faces (the faces left unpaired get their own copies)
  pinch_vertices,       // vertices where several fans of faces meet (one copy per fan)
  flipped_faces,        // faces oriented against their part (flipped)
  unorientable_parts,   // parts that no flipping can orient (Möbius-like; left as they are)
  isolated_vertices,    // vertices no face of the file uses (dropped)
};
inline constexpr int kDefectCount = 10;

/// Whether a mesh with the defect is refused as read (the others are read as they are: coincident,
/// isolated vertices and zero-area faces).
bool is_refused(Defect d);

/// One instance of a defect, by the indices of the file's elements (from 0).
struct DefectExample {
  int element = -1;  // the vertex (coincident, fin, pinch, isolated) or face (the others)
  int other = -1;    // coincident: the vertex it is welded to; duplicate: the earlier face; fin: the other end
  int count = 0;     // fin: the faces on the edge; pinch: the fans
  bool welded = false;  // fin, pinch: at a vertex coincident vertices were welded into (not so as read)
};

struct RepairReport {
  std::array<int, kDefectCount> counts{};                         // by Defect
  std::array<std::vector<DefectExample>, kDefectCount> examples;  // the first few
  int welded_groups = 0;                                          // the vertices the coincident ones became
  int split_faces = 0;        // faces that used a vertex twice, split into several faces
  int fin_faces = 0;          // faces left unpaired on fin edges, separated from the others there
  int fin_copies = 0;         // vertex copies made for them
  int pinch_copies = 0;       // vertex copies made for the extra fans of pinch vertices
  int parts = 0;              // connected parts of the result
  int boundary_loops = -1;    // of the result; −1 where a part cannot be oriented
  int orphaned_vertices = 0;  // vertices of faces the repair dropped, left in none (dropped)
  int dropped_creases = 0;    // creases of the file on no edge of the result (welded onto one vertex, say)

  int count(Defect d) const { return counts[size_t(d)]; }
  bool changed() const;
  /// Whether a class found makes the mesh refused as read (is_refused).
  bool refuses() const;
  /// One line per step that changed something ("welded 24 coincident vertices into 8").
  std::vector<std::string> lines() const;
  /// One line per defect class found (`refused` ones or the others): its name, count and first
  /// examples (gpsurf info).
  std::vector<std::string> problems(const ElementNumbering& numbering, bool refused) const;
  /// Why the mesh is refused, a phrase per refused class with its count, first example and what
  /// --repair does ("2 pinch vertices (several fans of faces), the first vertex 1 (line 1); --repair
  /// splits them"), joined by "; "; "" where none is. With `every_class`, the others too.
  std::string refusal(const ElementNumbering& numbering, bool every_class = false) const;
  /// The vertices and faces the examples name (for the lines of an ElementNumbering).
  void named_elements(std::vector<int>& vertices, std::vector<int>& faces) const;
};

/// Repairs the soup in place (its positions valid, its face indices in range).
RepairReport repair_polygon_soup(PolygonSoup& soup, const RepairOptions& options = {});

/// What repair_polygon_soup would do, leaving the soup as it is.
RepairReport diagnose_polygon_soup(const PolygonSoup& soup, const RepairOptions& options = {});

}  // namespace gps
