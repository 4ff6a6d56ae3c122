#include "core/io/ply_io.h"
#include "core/io/ply_scalar_type.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/io/dropped_attributes.h"
#include "core/io/number_text.h"
#include "core/support/quoted_text.h"
#include "core/io/text_file.h"
#include "core/io/text_words.h"

namespace gps {

namespace {

enum class Format { ascii, binary_le, binary_be };

struct Property {
  std::string name;
  PlyScalarType type;
  bool is_list = false;
  PlyScalarType count_type;
};

struct Element {
  std::string name;
  size_t count = 0;
  std::vector<Property> properties;
  int header_line = 0;
};

// What is wrong with a record's reference to vertex `index` (", which is not a whole number", ", but
// there are N vertices"), or "".
std::string vertex_reference_problem(double index, size_t vertex_count) {
  if (index != std::floor(index)) return ", which is not a whole number";
  if (!(index >= 0 && index < double(vertex_count))) return ", but there are " + std::to_string(vertex_count) + " vertices";
  return "";
}

// Reads the body of the file, value by value, in either encoding.
class BodyReader {
public:
  BodyReader(const std::string& data, size_t pos, Format format, int line, const std::string& source)
      : data_(data), pos_(pos), format_(format), line_(line), source_(escaped(source)) {}

  // ASCII records are one line each; call at the start of each record.
  void begin_record() {
    if (format_ != Format::ascii) return;
    tokens_.clear();
    token_index_ = 0;
    while (tokens_.empty()) {
      if (pos_ >= data_.size()) fail("the file ends early (truncated)");
      size_t end = data_.find('\n', pos_);
      if (end == std::string::npos) end = data_.size();
      ++line_;
      std::string_view text(data_.data() + pos_, end - pos_);
      pos_ = end + 1;
      tokens_ = words_of(text);
    }
  }

  // One value; an ASCII integer held to its declared type unless the caller checks it (`by_caller`:
  // a list length, a vertex index), naming it better.
  double read(const PlyScalarType& t, bool by_caller = false) {
    if (format_ == Format::ascii) {
      if (token_index_ >= tokens_.size()) fail("line " + std::to_string(line_) + ": too few values");
      const std::string_view tok = tokens_[token_index_++];
      double value = 0;
      if (const std::string why = parse_number(tok, value); !why.empty())
        fail("line " + std::to_string(line_) + ": " + why);
      if (!by_caller && !t.holds(value))
        fail("line " + std::to_string(line_) + ": " + quoted_token(tok) + " is not " + t.what_it_holds() +
             ", as its property is declared");
      return value;
    }
    if (pos_ + size_t(t.size) > data_.size()) fail("the binary data ends early (truncated)");
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, size_t(t.size));
    pos_ += size_t(t.size);
    if ((format_ == Format::binary_be) == (std::endian::native == std::endian::little))
      for (int i = 0; i < t.size / 2; ++i) std::swap(b[i], b[t.size - 1 - i]);
    if (t.is_float) {
      if (t.size == 4) return double(std::bit_cast<float>(std::array<unsigned char, 4>{b[0], b[1], b[2], b[3]}));
      return std::bit_cast<double>(std::array<unsigned char, 8>{b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]});
    }
    unsigned long long u = 0;
    for (int i = t.size - 1; i >= 0; --i) u = (u << 8) | b[i];
    if (t.is_signed && (u >> (8 * t.size - 1)) & 1) return double((long long)u - (1LL << (8 * t.size)));
    return double(u);
  }

  // A list length: a non-negative integer that fits in the data left (one byte per binary value,
  // two characters per ASCII value), so a corrupt count can neither overflow nor run for long.
  // `element` and `record` name the record in a refusal ("face 3: list length -4 …").
  size_t read_count(const PlyScalarType& t, const std::string& element, size_t record) {
    const double n = read(t, true);
    const size_t limit = format_ == Format::ascii ? tokens_.size() - token_index_ : remaining();
    const auto at = [&] { return where() + element + " " + std::to_string(record) + ": list length "; };
    if (!(n >= 0) || n != std::floor(n)) fail(at() + number_as_read(n) + " is not a count");
    if (!t.holds(n)) fail(at() + number_as_read(n) + " is more than its count type holds (" + t.what_it_holds() + ")");
    if (n > double(limit))
      fail(at() + number_as_read(n) +
           (format_ == Format::ascii ? " exceeds the values on the line" : " exceeds the data left (truncated)"));
    return size_t(n);
  }

  // "line N: " for ASCII data, "" for binary data (which has no lines).
  std::string where() const { return format_ == Format::ascii ? "line " + std::to_string(line_) + ": " : ""; }

  // ASCII data ends with its last record: anything but white space after it is refused. Binary data
  // ends with it too: bytes after it are records the header does not count (its counts short).
  void check_end() {
    if (format_ != Format::ascii) {
      if (pos_ < data_.size())
        fail(std::to_string(data_.size() - pos_) + " bytes after the last element's records (the header counts " +
             "fewer records than the file holds?)");
      return;
    }
    int line = line_ + 1;
    for (size_t i = pos_; i < data_.size(); ++i) {
      if (data_[i] == '\n') {
        ++line;
      } else if (!std::isspace(static_cast<unsigned char>(data_[i]))) {
        const size_t end = data_.find_first_of(" \t\r\n", i);
        fail("line " + std::to_string(line) + ": " +
             quoted_token(std::string_view(data_).substr(i, end == std::string::npos ? end : end - i)) +
             " after the last element's records");
      }
    }
  }

  void end_record() {
    if (format_ == Format::ascii && token_index_ != tokens_.size())
      fail("line " + std::to_string(line_) + ": more values than the header declares");
  }

  int line() const { return line_; }
  size_t remaining() const { return data_.size() - std::min(pos_, data_.size()); }
  [[noreturn]] void fail(const std::string& what) const { throw Error(source_ + ": " + what); }

private:
  const std::string& data_;
  size_t pos_;
  Format format_;
  int line_;
  const std::string source_;
  std::vector<std::string_view> tokens_;
  size_t token_index_ = 0;
};

// One record of element e: its scalar properties into `values` (by property index), lists read past.
void read_scalar_record(BodyReader& body, const Element& e, size_t record, std::vector<double>& values) {
  body.begin_record();
  for (size_t k = 0; k < e.properties.size(); ++k) {
    const Property& p = e.properties[k];
    if (p.is_list) {
      const size_t n = body.read_count(p.count_type, e.name, record);
      for (size_t i = 0; i < n; ++i) body.read(p.type);
    } else {
      values[k] = body.read(p.type);
    }
  }
  body.end_record();
}

// One record of the edge element: its vertices as the file gives them and its crease (16 bytes: a
// file of short records costs a few times its size).
struct CreaseRecord {
  int a = 0, b = 0;
  double sharpness = 0.0;
};

// "edge R (vertices A-B)", as messages name a record of the edge element.
std::string edge_record_name(size_t r, int a, int b) {
  return "edge " + std::to_string(r) + " (vertices " + std::to_string(a) + "-" + std::to_string(b) + ")";
}

// The creases of the edge element's records (numbered as the file numbers them), each on an edge of the
// faces. An edge named again with the same crease is read once; with another crease the later record's
// is kept, as OpenSubdiv's readers keep the later tag, and `note` gets one line naming the first such
// record and how many there are (found by sorting record numbers by edge, 4 bytes each).
template <class Fail, class Note>
Sharpness sharpness_of(const std::vector<CreaseRecord>& records, const PolygonTopology& faces, const Fail& fail,
                       const Note& note) {
  Sharpness out;
  if (records.empty()) return out;
  const auto name = [&](size_t r) { return edge_record_name(r, records[r].a, records[r].b); };
  const auto key = [&](uint32_t r) { return soup_edge_key(records[r].a, records[r].b); };
  {
    const std::vector<uint64_t> edges = soup_edge_keys(faces);
    for (size_t r = 0; r < records.size(); ++r)
      if (!std::binary_search(edges.begin(), edges.end(), key(uint32_t(r))))
        fail(name(r) + " is not an edge of the mesh");
  }
  std::vector<uint32_t> order(records.size());
  for (size_t r = 0; r < records.size(); ++r) order[r] = uint32_t(r);
  std::sort(order.begin(), order.end(),
            [&](uint32_t x, uint32_t y) { return key(x) != key(y) ? key(x) < key(y) : x < y; });
  size_t changed = 0, first = records.size(), before = 0;  // records changing their edge's crease; the earliest
  for (size_t i = 0; i < order.size(); ++i) {
    const bool repeats = i > 0 && key(order[i]) == key(order[i - 1]);
    if (repeats && records[order[i]].sharpness != records[order[i - 1]].sharpness) {
      ++changed;
      if (order[i] < first) {
        first = order[i];
        before = order[i - 1];
      }
    }
    const bool last = i + 1 == order.size() || key(order[i + 1]) != key(order[i]);
    const CreaseRecord& c = records[order[i]];
    if (last && c.sharpness > 0.0) out.creases.push_back({std::min(c.a, c.b), std::max(c.a, c.b), c.sharpness});
  }
  if (changed > 0)
    note(name(first) + " repeats edge " + std::to_string(before) + " with crease " +
         number_as_read(records[first].sharpness) + " (edge " + std::to_string(before) + " has " +
         number_as_read(records[before].sharpness) + ")" +
         (changed > 1 ? ", and " + std::to_string(changed - 1) + " more records repeat an edge with another crease"
                      : std::string()) +
         ": the later is kept");
  return out;
}

}  // namespace

namespace {

// The polygon soup of PLY data; `release`, where given, is the string `data` views, freed once parsed.
PolygonSoup ply_soup(const std::string& data, const std::string& source, bool& file_has_covariances,
                     std::string* release) {
  const std::string shown_source = escaped(source);
  const auto fail = [&](const std::string& what) -> void { throw Error(shown_source + ": " + what); };
  if (data.empty()) fail("the file is empty");
  // Header.
  size_t pos = 0;
  int line = 0;
  std::optional<Format> format;
  int format_line = 0;
  std::vector<Element> elements;
  std::unordered_map<std::string, int> read_once;       // the header lines of the elements read once
  std::unordered_map<std::string, int> property_lines;  // the last element's properties' lines
  bool ended = false;
  while (!ended) {
    if (pos >= data.size()) fail("the header has no end_header line");
    size_t end = data.find('\n', pos);
    if (end == std::string::npos) end = data.size();
    std::string text = data.substr(pos, end - pos);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    pos = end + 1;
    ++line;
    const std::string at = "line " + std::to_string(line) + ": ";
    const auto words = words_of(text);
    if (line == 1) {
      if (words.size() != 1 || words[0] != "ply") fail("not a PLY file (the first line is not 'ply')");
      continue;
    }
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
    if (words[0] == "format") {
      if (format_line > 0) fail(at + "a second format line (the first is line " + std::to_string(format_line) + ")");
      format_line = line;
      if (words.size() != 3) fail(at + "malformed format line");
      if (words[1] == "ascii")
        format = Format::ascii;
      else if (words[1] == "binary_little_endian")
        format = Format::binary_le;
      else if (words[1] == "binary_big_endian")
        format = Format::binary_be;
      else
        fail(at + "unknown format " + quoted_token(words[1]));
    } else if (words[0] == "element") {
      if (words.size() != 3) fail(at + "malformed element line");
      Element e;
      e.name = words[1];
      e.header_line = line;
      // Elements may come in any order, but the vertices and the faces once each.
      if (e.name == "vertex" || e.name == "face" || e.name == "tristrips" || e.name == "edge")
        if (const auto [first, inserted] = read_once.try_emplace(e.name, line); !inserted)
          fail(at + "a second " + e.name + " element (the first is line " + std::to_string(first->second) + ")");
      property_lines.clear();
      unsigned long long count = 0;
      const auto [p, ec] = std::from_chars(words[2].data(), words[2].data() + words[2].size(), count);
      if (ec != std::errc() || p != words[2].data() + words[2].size())
        fail(at + "element count " + quoted_token(words[2]) + " is not a number");
      e.count = size_t(count);
      elements.push_back(e);
    } else if (words[0] == "property") {
      if (elements.empty()) fail(at + "property before any element");
      Property prop;
      if (words.size() == 5 && words[1] == "list") {
        const auto ct = ply_scalar_type(words[2]), it = ply_scalar_type(words[3]);
        if (!ct || !it || ct->is_float) fail(at + "bad list property types");
        prop = {std::string(words[4]), *it, true, *ct};
      } else if (words.size() == 3) {
        const auto t = ply_scalar_type(words[1]);
        if (!t) fail(at + "unknown property type " + quoted_token(words[1]));
        prop = {std::string(words[2]), *t, false, {}};
      } else {
        fail(at + "malformed property line");
      }
      Element& owner = elements.back();
      if (const auto [first, inserted] = property_lines.try_emplace(prop.name, line); !inserted)
        fail(at + "property " + quoted_token(prop.name) + " of element " + quoted_token(owner.name) +
             " appears twice (the first is line " + std::to_string(first->second) + ")");
      owner.properties.push_back(prop);
    } else if (words[0] == "end_header") {
      ended = true;
    } else {
      fail(at + "unexpected header line " + quoted_token(text));
    }
  }
  if (!format) fail("the header has no format line");
  // Face indices are checked against the vertex count the header declares: the face element may
  // come first.
  const auto vertex_element =
      std::find_if(elements.begin(), elements.end(), [](const Element& e) { return e.name == "vertex"; });
  if (vertex_element == elements.end()) fail("the file has no vertex element");
  const size_t vertex_count = std::min<size_t>(vertex_element->count, size_t(std::numeric_limits<int>::max()));

  BodyReader body(data, pos, *format, line, source);
  std::vector<Vec3> means;
  std::vector<Mat3> covariances;
  DroppedAttributes dropped;  // what the vertex element holds that the mesh does not keep
  std::vector<std::string> unread_elements;  // elements of other kinds, read past
  PolygonTopology faces;
  bool has_covariances = false;
  std::vector<double> corners;        // per vertex, where the vertex element has a corner property
  std::vector<CreaseRecord> creases;  // the edge element's records, checked against the faces at the end
  // More corners than a manifold mesh on the vertices has (one face repeated, say): the faces so far
  // are refused as they stand (as parse_obj_soup does), not held to the end of the file.
  const auto refuse_past_manifold = [&](const char* record, size_t index) {
    if (!exceeds_manifold_corners(faces.verts.size(), vertex_count)) return;
    if (means.size() < vertex_count)  // the faces come first
      fail(body.where() + record + " " + std::to_string(index) +
           " makes the mesh non-manifold (more face corners than " + std::to_string(vertex_count) +
           " vertices can have)");
    faces.offsets.shrink_to_fit();
    faces.verts.shrink_to_fit();
    PolygonSoup soup;
    soup.positions = std::move(means);
    soup.covariances = std::move(covariances);
    soup.faces = std::move(faces);
    mesh_of_soup(std::move(soup), shown_source);
    fail("the mesh is not manifold");  // not reached: the check above throws
  };
  for (const Element& e : elements) {
    // Each record needs at least one byte per value (binary) or two characters (ASCII).
    size_t min_record = 0;
    for (const Property& p : e.properties) min_record += p.is_list ? size_t(p.count_type.size) : size_t(p.type.size);
    if (*format == Format::ascii) min_record = 2 * std::max<size_t>(1, e.properties.size());
    if (min_record > 0 && e.count > body.remaining() / min_record)
      fail("line " + std::to_string(e.header_line) + ": element " + quoted_token(e.name) + " declares " +
           std::to_string(e.count) + " records, more than the file holds (truncated)");
    const auto index_of = [&](const char* name) {
      for (size_t i = 0; i < e.properties.size(); ++i)
        if (e.properties[i].name == name && !e.properties[i].is_list) return int(i);
      return -1;
    };
    if (e.name == "vertex") {
      const int ix = index_of("x"), iy = index_of("y"), iz = index_of("z");
      if (ix < 0 || iy < 0 || iz < 0) fail("the vertex element lacks x, y or z");
      const char* cov_names[6] = {"cxx", "cxy", "cxz", "cyy", "cyz", "czz"};
      int ic[6];
      int found = 0;
      for (int k = 0; k < 6; ++k) found += (ic[k] = index_of(cov_names[k])) >= 0;
      if (found != 0 && found != 6) fail("the vertex element has only some of cxx cxy cxz cyy cyz czz");
      has_covariances = found == 6;
      std::vector<std::string> names;
      for (const Property& p : e.properties) names.push_back(p.name);
      count_unread_vertex_properties(names, e.count, dropped);
      const int icorner = index_of("corner");
      // Arrays grow as records arrive (never sized from the header): memory follows what the file holds.
      means.reserve(std::min<size_t>(e.count, 1 << 16));
      if (has_covariances) covariances.reserve(means.capacity());  // else none: identity, made with the mesh
      std::vector<double> values(e.properties.size());
      for (size_t v = 0; v < e.count; ++v) {
        read_scalar_record(body, e, v, values);
        means.emplace_back(values[size_t(ix)], values[size_t(iy)], values[size_t(iz)]);
        if (const std::string why = position_problem(means[v]); !why.empty())
          fail("vertex " + std::to_string(v) + " " + why);
        if (icorner >= 0) {
          const double s = values[size_t(icorner)];
          if (const std::string why = sharpness_problem(s); !why.empty())
            fail(body.where() + "vertex " + std::to_string(v) + " corner sharpness " + number_as_read(s) + " " + why);
          corners.push_back(s);
        }
        if (has_covariances) {
          Mat3& m = covariances.emplace_back();
          double c[6];
          for (int k = 0; k < 6; ++k) c[k] = values[size_t(ic[k])];
          m << c[0], c[1], c[2], c[1], c[3], c[4], c[2], c[4], c[5];
          if (const std::string why = covariance_problem(m); !why.empty())
            fail("vertex " + std::to_string(v) + " " + why);
        }
      }
    } else if (e.name == "face") {
      int list = -1;
      for (size_t i = 0; i < e.properties.size(); ++i)
        if (e.properties[i].is_list &&
            (e.properties[i].name == "vertex_indices" || e.properties[i].name == "vertex_index"))
          list = int(i);
      if (list < 0) fail("the face element has no vertex_indices list");
      std::vector<std::string> unread;
      for (size_t i = 0; i < e.properties.size(); ++i)
        if (int(i) != list) unread.push_back(quoted_token(e.properties[i].name));
      if (!unread.empty() && e.count > 0)
        dropped.other.push_back(named_list("face property", "face properties", unread));
      faces.offsets.reserve(std::min<size_t>(e.count, 1 << 16) + 1);
      for (size_t f = 0; f < e.count; ++f) {
        body.begin_record();
        for (size_t k = 0; k < e.properties.size(); ++k) {
          const Property& p = e.properties[k];
          if (!p.is_list) {
            body.read(p.type);
            continue;
          }
          const size_t n = body.read_count(p.count_type, e.name, f);
          if (int(k) == list && n < 3)
            fail(body.where() + "face " + std::to_string(f) + " has " + std::to_string(n) +
                 " vertices (at least 3 needed)");
          for (size_t i = 0; i < n; ++i) {
            const double index = body.read(p.type, true);
            if (int(k) != list) continue;
            if (const std::string why = vertex_reference_problem(index, vertex_count); !why.empty())
              fail(body.where() + "face " + std::to_string(f) + " refers to vertex " + number_as_read(index) + why);
            faces.verts.push_back(int(index));
          }
        }
        faces.offsets.push_back(int(faces.verts.size()));
        refuse_past_manifold("face", f);
        body.end_record();
      }
    } else if (e.name == "edge" && index_of("crease") >= 0) {
      // Creases (docs/design.md §4): vertex1 vertex2 crease per record, in any property order.
      const int i1 = index_of("vertex1"), i2 = index_of("vertex2"), is = index_of("crease");
      if (i1 < 0 || i2 < 0) fail("the edge element has a crease but lacks vertex1 or vertex2");
      // Reserved at the declared count, which the size check above bounds by the bytes left: its
      // pages are touched only as records arrive, and no doubling copies them.
      creases.reserve(e.count);
      std::vector<double> values(e.properties.size());
      for (size_t r = 0; r < e.count; ++r) {
        read_scalar_record(body, e, r, values);
        int ends[2];
        for (int k = 0; k < 2; ++k) {
          const double index = values[size_t(k == 0 ? i1 : i2)];
          if (const std::string why = vertex_reference_problem(index, vertex_count); !why.empty())
            fail(body.where() + "edge " + std::to_string(r) + " refers to vertex " + number_as_read(index) + why);
          ends[k] = int(index);
        }
        const auto named = [&] { return edge_record_name(r, ends[0], ends[1]); };
        const double sharpness = values[size_t(is)];
        if (const std::string why = sharpness_problem(sharpness); !why.empty())
          fail(body.where() + named() + " crease " + number_as_read(sharpness) + " " + why);
        if (ends[0] == ends[1]) fail(body.where() + named() + " joins a vertex to itself");
        creases.push_back({ends[0], ends[1], sharpness});
      }
    } else if (e.name == "tristrips") {
      // Triangle strips (as Stanford's scanned models store their faces): an index list per record,
      // −1 restarting the strip; triangle n of a strip is (s[n], s[n+1], s[n+2]), its first two
      // corners swapped for odd n so that all keep one orientation (as GL_TRIANGLE_STRIP). Triangles
      // with a repeated corner, which strips use to turn or to join runs, are left out.
      int list = -1;
      for (size_t i = 0; i < e.properties.size(); ++i)
        if (e.properties[i].is_list &&
            (e.properties[i].name == "vertex_indices" || e.properties[i].name == "vertex_index"))
          list = int(i);
      if (list < 0) fail("the tristrips element has no vertex_indices list");
      std::vector<int> strip;
      for (size_t r = 0; r < e.count; ++r) {
        body.begin_record();
        for (size_t k = 0; k < e.properties.size(); ++k) {
          const Property& p = e.properties[k];
          const size_t n = p.is_list ? body.read_count(p.count_type, e.name, r) : 1;
          strip.clear();
          for (size_t i = 0; i <= n; ++i) {
            const double index = i < n ? body.read(p.type, true) : -1;  // the record's end closes the last run
            if (int(k) != list) continue;
            if (index == -1) {
              for (size_t t = 0; t + 2 < strip.size(); ++t) {
                const int a = strip[t + (t % 2)], b = strip[t + 1 - (t % 2)], c = strip[t + 2];
                if (a == b || b == c || a == c) continue;
                faces.verts.insert(faces.verts.end(), {a, b, c});
                faces.offsets.push_back(int(faces.verts.size()));
                refuse_past_manifold("strip", r);
              }
              strip.clear();
              continue;
            }
            if (const std::string why = vertex_reference_problem(index, vertex_count); !why.empty())
              fail(body.where() + "strip " + std::to_string(r) + " refers to vertex " + number_as_read(index) + why);
            strip.push_back(int(index));
          }
        }
        body.end_record();
      }
    } else {
      if (e.count > 0)
        unread_elements.push_back(quoted_token(e.name) + " (" + std::to_string(e.count) +
                                  (e.count == 1 ? " record)" : " records)"));
      if (e.properties.empty() && *format != Format::ascii) continue;  // empty binary records: nothing to skip
      for (size_t r = 0; r < e.count; ++r) {
        body.begin_record();
        for (const Property& p : e.properties) {
          const size_t n = p.is_list ? body.read_count(p.count_type, e.name, r) : 1;
          for (size_t i = 0; i < n; ++i) body.read(p.type);
        }
        body.end_record();
      }
    }
  }
  body.check_end();
  if (release) std::string().swap(*release);
  if (!unread_elements.empty()) dropped.other.push_back(named_list("element", "elements", unread_elements));
  std::vector<std::string> notes;
  Sharpness sharpness =
      sharpness_of(creases, faces, fail, [&](const std::string& what) { notes.push_back(shown_source + ": " + what); });
  std::vector<CreaseRecord>().swap(creases);
  sharpness.corners = std::move(corners);
  sharpness.normalise();
  file_has_covariances = has_covariances;
  PolygonSoup soup;
  soup.sharpness = std::move(sharpness);
  soup.positions = std::move(means);
  soup.covariances = std::move(covariances);
  soup.faces = std::move(faces);
  soup.notes = std::move(notes);
  if (std::string note = dropped_attributes_note(shown_source, dropped); !note.empty())
    soup.notes.push_back(std::move(note));
  return soup;
}

// The mesh of PLY data, built in place; `release` as above, freed before the mesh is built.
CovarianceMesh parse_ply_mesh(const std::string& data, const std::string& source, bool& file_has_covariances,
                              std::string* release) {
  return mesh_of_soup(ply_soup(data, source, file_has_covariances, release), escaped(source));
}

}  // namespace

PlyContents parse_ply(const std::string& data, const std::string& source) {
  bool has_covariances = false;
  PlyContents out{parse_ply_mesh(data, source, has_covariances, nullptr)};  // in place: a mesh has no move
  out.has_covariances = has_covariances;
  return out;
}

CovarianceMesh parse_ply(std::string data, const std::string& source, bool& has_covariances) {
  return parse_ply_mesh(data, source, has_covariances, &data);
}

PolygonSoup parse_ply_soup(std::string data, const std::string& source, bool& has_covariances) {
  return ply_soup(data, source, has_covariances, &data);
}

void check_ply_head(std::string_view head, size_t size) {
  if (size == 0) throw Error("the file is empty");
  std::string_view first = head.substr(0, head.find('\n'));
  if (first.starts_with(kUtf8ByteOrderMark)) first.remove_prefix(kUtf8ByteOrderMark.size());
  while (!first.empty() && (first.front() == ' ' || first.front() == '\t')) first.remove_prefix(1);
  while (!first.empty() && (first.back() == '\r' || first.back() == ' ' || first.back() == '\t'))
    first.remove_suffix(1);
  if (first != "ply") throw Error("not a PLY file (the first line is not 'ply')");
}

PlyContents read_ply(const std::string& path) {
  std::string data = read_text_file(path, check_ply_head);
  drop_byte_order_mark(data);
  return parse_ply(data, path);
}

namespace {
// Writes a scalar's bytes in little-endian order whatever the host's order.
template <class T>
void put_little_endian(std::ostream& out, T value) {
  auto bytes = std::bit_cast<std::array<char, sizeof(T)>>(value);
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes.begin(), bytes.end());
  out.write(bytes.data(), sizeof(T));
}

// Whether every value is a float exactly, so that "float" keeps them.
template <class Values, class Get>
bool all_floats(const Values& values, Get get) {
  return std::all_of(values.begin(), values.end(), [&](const auto& x) { return double(float(get(x))) == get(x); });
}

// Writes a value of a float or double property: ASCII as the double's shortest exact text.
void put_real(std::ostream& out, double value, bool as_float, bool binary) {
  if (binary) {
    if (as_float)
      put_little_endian(out, float(value));
    else
      put_little_endian(out, value);
    return;
  }
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.write(buffer, r.ptr - buffer);
}
}  // namespace

void write_ply(std::ostream& out, const CovarianceMesh& m, bool binary) {
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
      << "comment gpsurf covariance mesh\n"
      << "element vertex " << m.n_vertices() << "\n";
  for (const char* name : {"x", "y", "z", "cxx", "cxy", "cxz", "cyy", "cyz", "czz"})
    out << "property double " << name << "\n";
  // Sharpness only where there is some, as float where every value is one (kept exactly either way).
  const std::vector<double>& corners = m.sharpness.corners;
  const bool has_corners = corners.size() == m.n_vertices();
  const bool float_corners = all_floats(corners, [](double x) { return x; });
  if (has_corners) out << "property " << (float_corners ? "float" : "double") << " corner\n";
  // Face sizes fit a uchar unless some face has more than 255 corners.
  bool wide = false;
  for (size_t f = 0; f < m.n_faces(); ++f) wide = wide || m.face_size(f) > 255;
  out << "element face " << m.n_faces() << "\nproperty list " << (wide ? "int" : "uchar") << " int vertex_indices\n";
  const std::vector<EdgeCrease>& creases = m.sharpness.creases;
  const bool float_creases = all_floats(creases, [](const EdgeCrease& c) { return c.sharpness; });
  if (!creases.empty())
    out << "element edge " << creases.size() << "\nproperty int vertex1\nproperty int vertex2\nproperty "
        << (float_creases ? "float" : "double") << " crease\n";
  out << "end_header\n";
  char buffer[32];
  for (size_t i = 0; i < m.n_vertices(); ++i) {
    const Vec3 p = m.mean(i);
    // Σ's lower triangle, which the check of a covariance (covariance_problem) and the solvers read: a
    // Σ symmetric only within rounding is saved as it was accepted.
    const Mat3& c = m.covariances[i];
    const double values[9] = {p.x(), p.y(), p.z(), c(0, 0), c(1, 0), c(2, 0), c(1, 1), c(2, 1), c(2, 2)};
    for (int k = 0; k < 9; ++k) {
      if (binary) {
        put_little_endian(out, values[k]);
      } else {
        const auto r = std::to_chars(buffer, buffer + sizeof buffer, values[k]);
        out.write(buffer, r.ptr - buffer);
        out.put(k == 8 && !has_corners ? '\n' : ' ');
      }
    }
    if (has_corners) {
      put_real(out, corners[i], float_corners, binary);
      if (!binary) out.put('\n');
    }
  }
  for (size_t f = 0; f < m.n_faces(); ++f) {
    const int32_t n = static_cast<int32_t>(m.face_size(f));
    if (!binary)
      out << n;
    else if (wide)
      put_little_endian(out, n);
    else
      out.put(char(static_cast<unsigned char>(n)));
    for (const int v : m.face(f)) {
      const int32_t index = v;
      if (binary)
        put_little_endian(out, index);
      else
        out << ' ' << index;
    }
    if (!binary) out << '\n';
  }
  for (const EdgeCrease& c : creases) {
    if (binary) {
      put_little_endian(out, int32_t(c.a));
      put_little_endian(out, int32_t(c.b));
    } else {
      out << c.a << ' ' << c.b << ' ';
    }
    put_real(out, c.sharpness, float_creases, binary);
    if (!binary) out << '\n';
  }
}

}  // namespace gps
