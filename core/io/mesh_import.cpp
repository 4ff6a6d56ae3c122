#include "core/io/dropped_attributes.h"
#include "core/io/mesh_import.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <cstring>
#include <numeric>
#include <sstream>
#include <unordered_set>

#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/io/number_text.h"
#include "core/io/text_file.h"
#include "core/support/quoted_text.h"
#include "core/io/text_words.h"

namespace gps {

namespace {

// `source` is already as messages show it (escaped). A soup of vertices only is a set of points
// (compare and fit read one); a mesh refuses it (mesh_of_soup, read_mesh).
PolygonSoup plain_soup(std::vector<Vec3>&& points, PolygonTopology&& faces, const std::string& source) {
  for (size_t i = 0; i < points.size(); ++i)
    if (const std::string why = position_problem(points[i]); !why.empty())
      throw Error(source + ": vertex " + std::to_string(i) + " " + why);
  PolygonSoup soup;
  soup.positions = std::move(points);
  soup.faces = std::move(faces);
  return soup;
}

bool parse_int(std::string_view s, long long& out) {
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && p == s.data() + s.size();
}

// The crease and corner tags of an OBJ file, stored flat as read (4 bytes per vertex index, 8 per
// sharpness): applied once the faces are known, since tags may come before them.
struct SharpTags {
  struct Line {
    int number = 0;
    bool crease = false;
    size_t first_int = 0, items = 0;  // crease: items pairs of ints; corner: items ints
    size_t first_value = 0;
    bool one_value = true;  // one sharpness for all items, else one each
  };
  std::vector<Line> lines;
  std::vector<int32_t> ints;
  std::vector<double> values;
  std::vector<std::string> skipped;  // the other tags' names, each once, as first met
};

// Reads OpenSubdiv's tag line "t crease|corner nint/nfloat/nstring ints floats strings" (regression
// shapes, Far tutorials): crease ints are pairs of vertices (a b a b ...), corner ints vertices, both
// numbered from 0; one float for all or one per pair or vertex. Other tags (holes, boundary rules)
// are skipped. `at` is "source: line N: ". Nothing is sized from the counts: the values are read
// from the line until the counts are met.
void read_sharp_tag(std::string_view line, int number, const std::string& at, SharpTags& tags) {
  const std::string_view name = next_word(line);
  if (name != "crease" && name != "corner") {
    if (const std::string shown = quoted_token(name);
        std::find(tags.skipped.begin(), tags.skipped.end(), shown) == tags.skipped.end() && tags.skipped.size() < 8)
      tags.skipped.push_back(shown);
    return;
  }
  const std::string what(name);
  const std::string_view counts = next_word(line);
  long long n[3] = {0, 0, 0};
  std::string_view rest = counts;
  for (int k = 0; k < 3; ++k) {
    const size_t slash = k < 2 ? rest.find('/') : std::string_view::npos;
    if ((k < 2 && slash == std::string_view::npos) || !parse_int(rest.substr(0, slash), n[k]) || n[k] < 0)
      throw Error(
          at + "the " + what + " tag's counts " + quoted_token(counts) +
          " are not nint/nfloat/nstring (three counts, such as 2/1/0 for a crease: its two vertices, one value)");
    if (k < 2) rest.remove_prefix(slash + 1);
  }
  SharpTags::Line tag;
  tag.number = number;
  tag.crease = name == "crease";
  tag.items = size_t(tag.crease ? n[0] / 2 : n[0]);
  if (n[0] == 0 || (tag.crease && n[0] % 2 != 0))
    throw Error(at + "a crease tag needs pairs of vertices, a corner tag vertices (" + std::to_string(n[0]) +
                " given)");
  if (n[1] != 1 && n[1] != n[0] / (tag.crease ? 2 : 1))
    throw Error(at + "the " + what + " tag has " + std::to_string(n[1]) + " sharpness values for " +
                std::to_string(tag.items) + (tag.crease ? " edges" : " vertices") + " (1 for all or 1 each)");
  tag.one_value = n[1] == 1;
  tag.first_int = tags.ints.size();
  tag.first_value = tags.values.size();
  const auto next = [&] {
    const std::string_view word = next_word(line);
    if (word.empty()) throw Error(at + "the " + what + " tag has fewer values than its counts say");
    return word;
  };
  // A long tag reserves what its line can hold (a word and a space each): no doubling copies it.
  const size_t words_left = line.size() / 2 + 1;
  if (n[0] > 4096) tags.ints.reserve(tags.ints.size() + std::min(size_t(n[0]), words_left));
  if (n[1] > 4096) tags.values.reserve(tags.values.size() + std::min(size_t(n[1]), words_left));
  for (long long k = 0; k < n[0]; ++k) {
    const std::string_view word = next();
    long long v = 0;
    if (!parse_int(word, v)) throw Error(at + quoted_token(word) + " is not a vertex index");
    if (v < 0 || v > INT32_MAX)
      throw Error(at + what + " tag names vertex " + std::to_string(v) + " (tags number vertices from 0)");
    tags.ints.push_back(int32_t(v));
  }
  for (long long k = 0; k < n[1]; ++k) {
    const std::string_view word = next();
    double x = 0;
    if (const std::string why = parse_number(word, x); !why.empty()) throw Error(at + why);
    if (const std::string why = sharpness_problem(x); !why.empty())
      throw Error(at + what + " sharpness " + std::string(word) + " " + why);
    tags.values.push_back(x);
  }
  for (long long k = 0; k < n[2]; ++k) next();  // a crease or corner has no strings: read past
  if (const std::string_view extra = next_word(line); !extra.empty() && extra[0] != '#')
    throw Error(at + "the " + what + " tag has more values than its counts say (" + quoted_token(extra) + ")");
  tags.lines.push_back(tag);
}

// One tag's sharpness of an edge or vertex as read, with its line: for a later tag to be compared with.
struct TaggedSharpness {
  int a = 0, b = 0;  // the edge's ends (a < b), or the vertex twice
  double sharpness = 0.0;
  int line = 0;
};

// The note on tags of one kind that repeat an earlier tag's edge or vertex with another value
// (`repeats` in file order within each edge or vertex), the later kept as in OpenSubdiv's readers;
// "" where none does. A tag repeating the value it repeats is read once, without a note.
std::string repeated_tags_note(const std::vector<TaggedSharpness>& tagged, bool crease, const std::string& source) {
  size_t changed = 0, first = 0;
  for (size_t i = 1; i < tagged.size(); ++i) {
    const bool repeats = tagged[i].a == tagged[i - 1].a && tagged[i].b == tagged[i - 1].b;
    if (!repeats || tagged[i].sharpness == tagged[i - 1].sharpness) continue;
    if (changed++ == 0 || tagged[i].line < tagged[first].line) first = i;
  }
  if (changed == 0) return "";
  const TaggedSharpness &later = tagged[first], &earlier = tagged[first - 1];
  const std::string kind = crease ? "crease" : "corner";
  const std::string element =
      crease ? std::to_string(later.a) + "-" + std::to_string(later.b) : std::to_string(later.a);
  return source + ": line " + std::to_string(later.line) + ": " + kind + " " + element + " repeats line " +
         std::to_string(earlier.line) + "'s with sharpness " + number_as_read(later.sharpness) + " (line " +
         std::to_string(earlier.line) + " gives " + number_as_read(earlier.sharpness) + ")" +
         (changed > 1 ? ", and " + std::to_string(changed - 1) + " more " + kind + " tags repeat one with another value"
                      : std::string()) +
         ": the later is kept";
}

// The sharpness of the tags on the finished soup; a later tag on the same edge or vertex wins, as in
// OpenSubdiv's readers, with a note in `notes` where it changes the value.
Sharpness sharpness_of_tags(const SharpTags& tags, const PolygonSoup& soup, const std::string& source,
                            std::vector<std::string>& notes) {
  Sharpness out;
  if (tags.lines.empty()) return out;
  const int n = int(soup.positions.size());
  const std::vector<uint64_t> edges = soup_edge_keys(soup.faces);
  std::vector<TaggedSharpness> creases, corners;
  for (const SharpTags::Line& t : tags.lines) {
    const std::string kind = t.crease ? "crease" : "corner";
    const auto at = [&] { return source + ": line " + std::to_string(t.number) + ": "; };
    for (size_t i = 0; i < t.items; ++i) {
      const int a = tags.ints[t.first_int + (t.crease ? 2 * i : i)];
      const int b = t.crease ? tags.ints[t.first_int + 2 * i + 1] : a;
      const double s = tags.values[t.first_value + (t.one_value ? 0 : i)];
      for (const int v : {a, b})
        if (v >= n)
          throw Error(at() + kind + " tag names vertex " + std::to_string(v) + ", but there are " + std::to_string(n) +
                      " vertices (tags number them from 0)");
      if (t.crease && (a == b || !std::binary_search(edges.begin(), edges.end(), soup_edge_key(a, b))))
        throw Error(at() + "crease " + std::to_string(a) + "-" + std::to_string(b) +
                    " is not an edge of the mesh (tags number vertices from 0; remove the tag or name an edge)");
      (t.crease ? creases : corners).push_back({std::min(a, b), std::max(a, b), s, t.number});
    }
  }
  // In file order within each edge or vertex after a stable sort: the last one stays.
  for (std::vector<TaggedSharpness>* tagged : {&creases, &corners}) {
    std::stable_sort(tagged->begin(), tagged->end(), [](const TaggedSharpness& x, const TaggedSharpness& y) {
      return x.a != y.a ? x.a < y.a : x.b < y.b;
    });
    if (std::string note = repeated_tags_note(*tagged, tagged == &creases, source); !note.empty())
      notes.push_back(std::move(note));
  }
  for (size_t i = 0; i < creases.size(); ++i)
    if (i + 1 == creases.size() || creases[i + 1].a != creases[i].a || creases[i + 1].b != creases[i].b)
      out.creases.push_back({creases[i].a, creases[i].b, creases[i].sharpness});
  if (!corners.empty()) out.corners.assign(size_t(n), 0.0);
  for (const TaggedSharpness& c : corners) out.corners[size_t(c.a)] = c.sharpness;  // the later overwrites
  out.normalise();
  return out;
}

// The lines of an OBJ text, a line ending in '\\' joined with the next by a space (the format's line
// continuation), numbered by their first line as messages name them.
class ObjLines {
public:
  explicit ObjLines(std::string_view text) : lines_(text) { join(); }
  bool done() const { return done_; }
  std::string_view line() const { return line_; }
  int number() const { return number_; }
  void next() {
    lines_.next();
    join();
  }

private:
  static bool continued(std::string_view line) {
    const size_t last = line.find_last_not_of(" \t");
    return last != std::string_view::npos && line[last] == '\\';
  }
  void join() {
    done_ = lines_.done();
    number_ = lines_.number();
    line_ = lines_.line();
    if (done_ || !continued(line_)) return;
    joined_.clear();
    for (std::string_view part = line_;; part = lines_.line()) {
      if (!continued(part)) {
        joined_ += part;
        break;
      }
      joined_ += part.substr(0, part.find_last_not_of(" \t"));
      joined_ += ' ';
      lines_.next();
      if (lines_.done()) break;
    }
    line_ = joined_;
  }
  LineCursor lines_;
  bool done_ = false;
  int number_ = 0;
  std::string_view line_;
  std::string joined_;
};

}  // namespace

CovarianceMesh parse_obj(std::string data, const std::string& source) {
  return mesh_of_soup(parse_obj_soup(std::move(data), source), escaped(source), obj_element_names(nullptr));
}

CovarianceMesh parse_off(std::string data, const std::string& source) {
  return mesh_of_soup(parse_off_soup(std::move(data), source), escaped(source));
}

CovarianceMesh parse_stl(std::string data, const std::string& source) {
  return mesh_of_soup(parse_stl_soup(std::move(data), source), escaped(source));
}

// Keywords that name groups, objects, smoothing groups and materials: how a surface is organised or
// looks, nothing of its shape.
bool is_obj_grouping_keyword(std::string_view keyword) {
  static constexpr std::string_view kGrouping[] = {"o", "g", "s", "mg", "usemtl", "mtllib", "maplib", "usemap",
                                                   "lod", "shadow_obj", "trace_obj", "bevel", "c_interp", "d_interp"};
  return std::find(std::begin(kGrouping), std::end(kGrouping), keyword) != std::end(kGrouping);
}

// A face corner's texture coordinate and normal (v/vt, v//vn, v/vt/vn): each an index, from 1 or
// negative from the last read, of those read so far, or left out; throws naming the corner otherwise.
template <class At>
void check_obj_corner_references(std::string_view corner, size_t n_texture, size_t n_normals, const At& at) {
  const size_t first = corner.find('/');
  if (first == std::string_view::npos) return;
  std::string_view parts[2] = {corner.substr(first + 1), {}};
  if (const size_t second = parts[0].find('/'); second != std::string_view::npos) {
    parts[1] = parts[0].substr(second + 1);
    parts[0] = parts[0].substr(0, second);
    if (parts[1].find('/') != std::string_view::npos)
      throw Error(at() + quoted_token(corner) + " is not a face corner (v, v/vt, v//vn or v/vt/vn)");
  }
  for (int k = 0; k < 2; ++k) {
    if (parts[k].empty()) continue;
    const char* what = k == 0 ? "texture coordinate" : "normal";
    const size_t count = k == 0 ? n_texture : n_normals;
    long long index = 0;
    if (!parse_int(parts[k], index))
      throw Error(at() + quoted_token(corner) + ": " + quoted_token(parts[k]) + " is not a " + what + " index");
    const long long resolved = index < 0 ? index + (long long)count + 1 : index;
    if (resolved < 1 || resolved > (long long)count)
      throw Error(at() + quoted_token(corner) + ": " + what + " index " + std::to_string(index) + " is out of range (" +
                  std::to_string(count) + " so far)");
  }
}

PolygonSoup parse_obj_soup(std::string data, const std::string& source_path) {
  const std::string source = escaped(source_path);
  if (data.empty()) throw Error(source + ": the file is empty");
  // Two passes over the lines: the first counts the vertices and face corners, so that the arrays are
  // reserved at their exact sizes and the faces are stored flat (an offset per face, an index per corner).
  size_t n_points = 0, n_faces = 0, n_corners = 0;
  for (ObjLines lines(data); !lines.done(); lines.next()) {
    std::string_view line = lines.line();
    const std::string_view keyword = next_word(line);
    if (keyword == "v") ++n_points;
    if (keyword != "f") continue;
    ++n_faces;
    while (!next_word(line).empty()) ++n_corners;
  }
  std::vector<Vec3> points;
  points.reserve(n_points);
  PolygonTopology faces;
  faces.offsets.reserve(n_faces + 1);
  faces.verts.reserve(n_corners);
  SharpTags tags;
  DroppedAttributes dropped;
  std::map<std::string, size_t> unread;  // keyword -> records of a kind a covariance mesh does not hold
  for (ObjLines lines(data); !lines.done(); lines.next()) {
    std::string_view line = lines.line();
    const auto at = [&] { return source + ": line " + std::to_string(lines.number()) + ": "; };
    const std::string_view keyword = next_word(line);
    if (keyword.empty() || keyword[0] == '#') continue;
    if (keyword == "v") {
      Vec3 p;
      std::string_view coordinates[3];
      for (auto& c : coordinates) c = next_word(line);
      if (coordinates[2].empty()) throw Error(at() + "a vertex needs three coordinates");
      for (int k = 0; k < 3; ++k)
        if (const std::string why = parse_number(coordinates[k], p[k]); !why.empty()) throw Error(at() + why);
      if (const std::string why = position_problem(p); !why.empty())
        throw Error(source + ": vertex " + std::to_string(points.size() + 1) + " (line " +
                    std::to_string(lines.number()) + ") " + why);
      // What may follow: a weight, or a colour as MeshLab writes it (numbers, dropped), or a comment.
      int extras = 0;
      for (std::string_view extra = next_word(line); !extra.empty() && extra[0] != '#'; extra = next_word(line)) {
        double value = 0;
        const std::string why = parse_number(extra, value);
        if (!why.empty() || !std::isfinite(value))
          throw Error(at() + (why.empty() ? quoted_token(extra) + " is not a finite number" : why) +
                      " (after the vertex's coordinates: a weight or a colour)");
        ++extras;
      }
      if (extras >= 3) ++dropped.colours;
      points.push_back(p);
    } else if (keyword == "vt" || keyword == "vn") {
      // Dropped, but read as the faces refer to them: u [v [w]] and x y z, numbers.
      const bool texture = keyword == "vt";
      int values = 0;
      for (std::string_view word = next_word(line); !word.empty() && word[0] != '#'; word = next_word(line), ++values) {
        double value = 0;
        if (const std::string why = parse_number(word, value); !why.empty()) throw Error(at() + why);
      }
      if (texture ? values < 1 || values > 3 : values != 3)
        throw Error(at() + (texture ? "a texture coordinate needs 1 to 3 numbers (u v w), got "
                                    : "a normal needs 3 numbers (x y z), got ") +
                    std::to_string(values));
      ++(texture ? dropped.texture_coordinates : dropped.normals);
    } else if (keyword == "t") {
      read_sharp_tag(line, lines.number(), at(), tags);
    } else if (keyword == "f") {
      size_t size = 0;
      for (std::string_view word = next_word(line); !word.empty(); word = next_word(line), ++size) {
        long long index = 0;
        if (!parse_int(word.substr(0, word.find('/')), index))
          throw Error(at() + quoted_token(word) + " is not a vertex index");
        check_obj_corner_references(word, dropped.texture_coordinates, dropped.normals, at);
        const long long written = index;
        if (index < 0) index += (long long)points.size() + 1;  // relative to the end
        if (index < 1 || index > (long long)points.size())
          throw Error(at() + "vertex index " + std::to_string(written) + " is out of range (" +
                      std::to_string(points.size()) + " vertices so far)");
        faces.verts.push_back(int(index - 1));
      }
      if (size < 3) throw Error(at() + "a face needs at least 3 vertices");
      faces.offsets.push_back(int(faces.verts.size()));
      // Each edge of a manifold mesh borders at most two faces, so its corners are at most n(n − 1) for
      // n vertices; past that (one face repeated, say) the faces so far are refused as they stand.
      if (exceeds_manifold_corners(faces.verts.size(), points.size())) {
        faces.offsets.shrink_to_fit();
        faces.verts.shrink_to_fit();
        mesh_of_soup(plain_soup(std::move(points), std::move(faces), source), source,
                     obj_element_names([&data] { return data; }));
        throw Error(source + ": the mesh is not manifold");  // not reached: the check above throws
      }
    } else if (!is_obj_grouping_keyword(keyword)) {
      if (const auto it = unread.find(std::string(keyword)); it != unread.end())
        ++it->second;
      else if (unread.size() < kNamesListed)
        unread.emplace(keyword, 1);
    }
  }
  if (points.empty()) throw Error(source + ": no vertices");
  std::string().swap(data);  // the text is parsed: its bytes are not held while the mesh is built
  PolygonSoup soup = plain_soup(std::move(points), std::move(faces), source);
  soup.sharpness = sharpness_of_tags(tags, soup, source, soup.notes);
  if (!tags.skipped.empty()) dropped.other.push_back(named_list("the tag", "the tags", tags.skipped));
  for (const auto& [keyword, count] : unread)
    dropped.other.push_back(std::to_string(count) + " " + quoted_token(keyword) + (count == 1 ? " record" : " records"));
  if (std::string note = dropped_attributes_note(source, dropped); !note.empty()) soup.notes.push_back(std::move(note));
  return soup;
}

void find_obj_lines(std::string_view data, const std::vector<int>& vertices, const std::vector<int>& faces,
                    ElementNumbering& numbering) {
  if (data.starts_with(kUtf8ByteOrderMark)) data.remove_prefix(kUtf8ByteOrderMark.size());  // as read
  std::unordered_set<int> wanted_vertices(vertices.begin(), vertices.end()), wanted_faces(faces.begin(), faces.end());
  const int last_vertex = vertices.empty() ? -1 : *std::max_element(vertices.begin(), vertices.end());
  const int last_face = faces.empty() ? -1 : *std::max_element(faces.begin(), faces.end());
  int n_vertices = 0, n_faces = 0;
  for (ObjLines lines(data); !lines.done() && (n_vertices <= last_vertex || n_faces <= last_face); lines.next()) {
    std::string_view line = lines.line();
    const std::string_view keyword = next_word(line);
    if (keyword == "v" && wanted_vertices.count(n_vertices++)) numbering.vertex_lines[n_vertices - 1] = lines.number();
    if (keyword == "f" && wanted_faces.count(n_faces++)) numbering.face_lines[n_faces - 1] = lines.number();
  }
}

ElementNames obj_element_names(std::function<std::string()> text) {
  const auto name = [text](int index, bool vertex) {
    ElementNumbering numbering;
    numbering.base = 1;
    try {
      if (text)
        find_obj_lines(text(), vertex ? std::vector<int>{index} : std::vector<int>{},
                       vertex ? std::vector<int>{} : std::vector<int>{index}, numbering);
    } catch (const Error&) {  // gone since it was read: named without its line
    }
    return vertex ? numbering.vertex(index) : numbering.face(index);
  };
  return {[name](int v) { return name(v, true); }, [name](int f) { return name(f, false); }};
}

PolygonSoup parse_off_soup(std::string data, const std::string& source_path) {
  const std::string source = escaped(source_path);
  if (data.empty()) throw Error(source + ": the file is empty");
  WordCursor t(data);
  const auto at = [&](int line) { return source + ": line " + std::to_string(line) + ": "; };
  // The keyword: OFF or a variant (COFF, NOFF, STCNOFF, ...) whose extra vertex values are skipped below.
  if (!t.done() && t.word().size() >= 3 && t.word().ends_with("OFF")) {
    if (t.word().find('4') != std::string_view::npos || t.word().starts_with("n"))
      throw Error(at(t.line()) + quoted_token(t.word()) + " (4D or n-dimensional OFF) is not supported");
    t.next();
  }
  const auto next_int = [&](const char* what) {
    if (t.done()) throw Error(source + ": the file ends early (expected " + what + ")");
    long long v = 0;
    if (!parse_int(t.word(), v) || v < 0)
      throw Error(at(t.line()) + quoted_token(t.word()) + " is not a valid " + what);
    t.next();
    return v;
  };
  const long long nv = next_int("vertex count"), nf = next_int("face count");
  next_int("edge count");
  // Every vertex takes at least 6 characters ("0 0 0\n"), every face at least 8 ("3 0 1 2\n").
  if (nv > (long long)data.size() / 6 || nf > (long long)data.size() / 8)
    throw Error(source + ": the header declares more vertices or faces than the file holds");
  // Values after a vertex's position (a COFF's colour, an NOFF's normal) or a face's corners (its
  // colour) are counted, to say they are dropped.
  size_t vertices_with_more = 0, faces_with_more = 0;
  const auto skip_rest = [&](int line, size_t& count) {
    count += !t.done() && t.line() == line;
    for (; !t.done() && t.line() == line; t.next()) {
      double value = 0;
      if (const std::string why = parse_number(t.word(), value); !why.empty())
        throw Error(at(line) + why + " (the values after a vertex's position or a face's corners are numbers)");
    }
  };
  // Arrays grow as records arrive (never sized from the header): memory follows what the file holds.
  std::vector<Vec3> points;
  for (long long v = 0; v < nv; ++v) {
    Vec3& p = points.emplace_back();
    int line = t.line();
    for (int k = 0; k < 3; ++k) {
      if (t.done()) throw Error(source + ": the file ends early (truncated vertex list)");
      line = t.line();
      if (const std::string why = parse_number(t.word(), p[k]); !why.empty()) throw Error(at(line) + why);
      t.next();
    }
    skip_rest(line, vertices_with_more);  // normals, colours, texture coordinates
  }
  PolygonTopology faces;
  for (long long f = 0; f < nf; ++f) {
    const int line = t.line();
    const long long n = next_int("face size");
    if (n < 3) throw Error(at(line) + "face " + std::to_string(f) + " has fewer than 3 vertices");
    for (long long k = 0; k < n; ++k) {
      const long long index = next_int("vertex index");
      if (index >= nv)
        throw Error(at(line) + "face " + std::to_string(f) + " refers to vertex " + std::to_string(index) +
                    ", but there are " + std::to_string(nv) + " vertices");
      faces.verts.push_back(int(index));
    }
    faces.offsets.push_back(int(faces.verts.size()));
    if (exceeds_manifold_corners(faces.verts.size(), points.size())) {  // as in parse_obj_soup
      faces.offsets.shrink_to_fit();
      faces.verts.shrink_to_fit();
      mesh_of_soup(plain_soup(std::move(points), std::move(faces), source), source);
      throw Error(source + ": the mesh is not manifold");  // not reached: the check above throws
    }
    skip_rest(line, faces_with_more);  // colour values
  }
  // The faces end the data: more after them means the header counts fewer than the file holds.
  if (!t.done())
    throw Error(at(t.line()) + quoted_token(t.word()) + " after the " + std::to_string(nf) +
                (nf == 1 ? " face" : " faces") + " the header counts (it counts fewer than the file holds?)");
  std::string().swap(data);  // the text is parsed: its bytes are not held while the mesh is built
  PolygonSoup soup = plain_soup(std::move(points), std::move(faces), source);
  DroppedAttributes dropped;
  if (vertices_with_more > 0)
    dropped.other.push_back("the values after the position of " + std::to_string(vertices_with_more) +
                            (vertices_with_more == 1 ? " vertex" : " vertices") +
                            " (colours, normals or texture coordinates)");
  if (faces_with_more > 0)
    dropped.other.push_back("the colours of " + std::to_string(faces_with_more) +
                            (faces_with_more == 1 ? " face" : " faces"));
  if (std::string note = dropped_attributes_note(source, dropped); !note.empty()) soup.notes.push_back(std::move(note));
  return soup;
}

void check_text_head(std::string_view head, size_t size) {
  if (size == 0) throw Error("the file is empty");
  if (const size_t nul = head.find('\0'); nul != std::string_view::npos)
    throw Error("byte " + std::to_string(nul + 1) + " is a NUL: not a text file");
}

namespace {

// Whether text begins as an ASCII STL does: "solid", in any case, after a UTF-8 byte order mark and
// white space, as exporters write it.
bool begins_ascii_stl(std::string_view text) {
  if (text.starts_with(kUtf8ByteOrderMark)) text.remove_prefix(kUtf8ByteOrderMark.size());
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  if (text.size() < 5) return false;
  for (size_t i = 0; i < 5; ++i)
    if (std::tolower(static_cast<unsigned char>(text[i])) != "solid"[i]) return false;
  return true;
}

// An ASCII STL keyword in lower case (exporters write some in capitals).
std::string keyword_of(std::string_view word) {
  std::string out(word);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

void check_stl_head(std::string_view head, size_t size) {
  if (size == 0) throw Error("the file is empty");
  if (begins_ascii_stl(head) && head.find('\0') == std::string_view::npos) return;  // ASCII
  if (size < 84) throw Error("binary STL shorter than its 84-byte header (truncated)");
  uint32_t declared = 0;
  std::memcpy(&declared, head.data() + 80, 4);
  if (size != 84 + size_t(declared) * 50)
    throw Error("binary STL of " + std::to_string(size) + " bytes whose header declares " + std::to_string(declared) +
                " triangles (" + std::to_string(84 + size_t(declared) * 50) + " bytes)");
}

PolygonSoup parse_stl_soup(std::string data, const std::string& source_path) {
  const std::string source = escaped(source_path);
  if (data.empty()) throw Error(source + ": the file is empty");
  std::vector<Vec3> corners;
  // Some binary STL headers start with "solid" too: a size matching the triangle count means binary.
  uint32_t declared = 0;
  if (data.size() >= 84) std::memcpy(&declared, data.data() + 80, 4);
  const bool binary_size = data.size() >= 84 && data.size() == 84 + size_t(declared) * 50;
  const bool looks_ascii = !binary_size && begins_ascii_stl(data);
  if (!looks_ascii) {
    if (data.size() < 84) throw Error(source + ": binary STL shorter than its 84-byte header (truncated)");
    uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    if (84 + size_t(n) * 50 > data.size())
      throw Error(source + ": binary STL declares " + std::to_string(n) + " triangles but holds fewer (truncated)");
    corners.reserve(3 * size_t(n));
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        float xyz[3];
        std::memcpy(xyz, data.data() + 84 + i * 50 + 12 + size_t(c) * 12, 12);
        corners.emplace_back(xyz[0], xyz[1], xyz[2]);
      }
  } else {
    std::istringstream in(data);
    int line_number = 0, facet_line = 0, in_facet = 0;
    bool ended = false;
    for (std::string line; std::getline(in, line);) {
      ++line_number;
      const auto words = words_of(line);
      if (words.empty()) continue;
      const std::string keyword = keyword_of(words[0]);
      if (keyword == "facet") {
        facet_line = line_number;
        in_facet = 0;
      } else if (keyword == "endfacet" && in_facet != 3) {
        throw Error(source + ": line " + std::to_string(facet_line) + ": a facet with " + std::to_string(in_facet) +
                    (in_facet == 1 ? " vertex" : " vertices") + " (an STL facet has 3)");
      } else if (keyword == "endsolid") {
        ended = true;
      } else if (keyword == "vertex") {
        Vec3 p;
        if (words.size() != 4)
          throw Error(source + ": line " + std::to_string(line_number) + ": a vertex needs three coordinates");
        for (int k = 0; k < 3; ++k)
          if (const std::string why = parse_number(words[size_t(k + 1)], p[k]); !why.empty())
            throw Error(source + ": line " + std::to_string(line_number) + ": " + why);
        corners.push_back(p);
        ++in_facet;
      }
    }
    if (corners.size() % 3 != 0) throw Error(source + ": a facet does not have three vertices");
    if (!ended) throw Error(source + ": the file ends before its 'endsolid' (truncated)");
  }
  if (corners.empty()) throw Error(source + ": no triangles");
  for (size_t c = 0; c < corners.size(); ++c)  // before welding: NaN would break the sort by position
    if (!corners[c].allFinite())
      throw Error(source + ": triangle " + std::to_string(c / 3) + " has a corner that is not finite");
  std::string().swap(data);  // the file is parsed: its bytes are not held while the mesh is built
  // Welding: the corners sorted by position (ties by their order), so that each corner finds the first
  // corner at its position; positions compare as the ordered map of arrays of them would.
  const auto position_less = [&](int a, int b) {
    const Vec3 &p = corners[size_t(a)], &q = corners[size_t(b)];
    return std::array<double, 3>{p.x(), p.y(), p.z()} < std::array<double, 3>{q.x(), q.y(), q.z()};
  };
  std::vector<int> first(corners.size());  // per corner: the first corner at its position, then its vertex
  {
    std::vector<int> order(corners.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return position_less(a, b) || (!position_less(b, a) && a < b); });
    for (size_t i = 0; i < order.size(); ++i)
      first[size_t(order[i])] =
          i > 0 && !position_less(order[i - 1], order[i]) ? first[size_t(order[i - 1])] : order[i];
  }
  size_t n_points = 0;
  for (size_t c = 0; c < corners.size(); ++c) n_points += first[c] == int(c);
  std::vector<Vec3> points;
  points.reserve(n_points);
  for (size_t c = 0; c < corners.size(); ++c) {  // vertices in the order their first corners come
    if (first[c] == int(c)) {
      first[c] = int(points.size());
      points.push_back(corners[c]);
    } else {
      first[c] = first[size_t(first[c])];
    }
  }
  std::vector<Vec3>().swap(corners);
  PolygonTopology faces;
  for (size_t i = 0; i < first.size(); i += 3) {
    const int a = first[i], b = first[i + 1], c = first[i + 2];
    if (a == b || b == c || a == c) continue;  // welded to fewer than three vertices
    faces.verts.insert(faces.verts.end(), {a, b, c});
    faces.offsets.push_back(int(faces.verts.size()));
  }
  std::vector<int>().swap(first);
  return plain_soup(std::move(points), std::move(faces), source);
}

}  // namespace gps
