// Creases and corners in the covariance PLY: the vertex property `corner` and the element `edge`
// (vertex1 vertex2 crease), read in any property and element order, written exactly, refused with
// one-line errors naming the file and the element.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include "core/io/mesh_io.h"
#include "core/io/ply_io.h"
#include "core/support/error.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

struct Crease {
  double a, b, sharpness;  // as the file holds them
};

const double kCube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const int kCubeFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// A cube PLY with the given vertex and edge properties (type, name) in their order, ASCII or binary
// little endian; vertex values by name (x y z from kCube, covariances 0.01 I, corner from `corners`).
struct CubePly {
  std::vector<std::pair<std::string, std::string>> vertex = {{"double", "x"},   {"double", "y"},   {"double", "z"},
                                                             {"double", "cxx"}, {"double", "cxy"}, {"double", "cxz"},
                                                             {"double", "cyy"}, {"double", "cyz"}, {"double", "czz"}};
  std::vector<std::pair<std::string, std::string>> edge = {{"int", "vertex1"}, {"int", "vertex2"}, {"float", "crease"}};
  std::vector<Crease> creases;
  std::vector<double> corners;  // per vertex where the vertex element has a corner property
  bool edge_before_faces = false;
  bool binary = false;

  std::string text() const {
    std::ostringstream out;
    out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\nelement vertex 8\n";
    for (const auto& [type, name] : vertex) out << "property " << type << ' ' << name << '\n';
    const std::string edge_header = [&] {
      std::ostringstream e;
      e << "element edge " << creases.size() << '\n';
      for (const auto& [type, name] : edge) e << "property " << type << ' ' << name << '\n';
      return e.str();
    }();
    if (edge_before_faces) out << edge_header;
    out << "element face 6\nproperty list uchar int vertex_indices\n";
    if (!edge_before_faces) out << edge_header;
    out << "end_header\n";
    const auto put = [&](const std::string& type, double v, bool last) {
      if (!binary) {
        out.precision(17);
        out << v << (last ? '\n' : ' ');
      } else if (type == "float") {
        out.write(std::bit_cast<std::array<char, 4>>(float(v)).data(), 4);
      } else if (type == "double") {
        out.write(std::bit_cast<std::array<char, 8>>(v).data(), 8);
      } else if (type == "int") {
        out.write(std::bit_cast<std::array<char, 4>>(int32_t(v)).data(), 4);
      } else if (type == "uint") {
        out.write(std::bit_cast<std::array<char, 4>>(uint32_t(v)).data(), 4);
      } else {
        out.put(char(uint8_t(v)));
      }
    };
    for (int v = 0; v < 8; ++v) {
      const std::map<std::string, double> values = {
          {"x", kCube[v][0]}, {"y", kCube[v][1]},
          {"z", kCube[v][2]}, {"cxx", 0.01},
          {"cxy", 0.0},       {"cxz", 0.0},
          {"cyy", 0.01},      {"cyz", 0.0},
          {"czz", 0.01},      {"corner", corners.empty() ? 0.0 : corners[size_t(v)]}};
      for (size_t k = 0; k < vertex.size(); ++k)
        put(vertex[k].first, values.at(vertex[k].second), k + 1 == vertex.size());
    }
    const auto faces = [&] {
      for (const auto& f : kCubeFaces) {
        put("uchar", 4, false);
        for (int k = 0; k < 4; ++k) put("int", f[k], k == 3);
      }
    };
    const auto edges = [&] {
      for (const Crease& c : creases)
        for (size_t k = 0; k < edge.size(); ++k) {
          const std::string& name = edge[k].second;
          put(edge[k].first, name == "vertex1" ? c.a : name == "vertex2" ? c.b : c.sharpness, k + 1 == edge.size());
        }
    };
    if (edge_before_faces) edges();
    faces();
    if (!edge_before_faces) edges();
    return out.str();
  }
};

Sharpness expected_top_creases() {
  Sharpness s;
  s.creases = {{4, 5, 10.0}, {4, 7, 10.0}, {5, 6, 2.5}, {6, 7, 0.5}};
  s.corners = {0, 0, 3.0, 0, 0, 0, 0, 0};
  return s;
}

std::string message_of(const std::string& ply) {
  try {
    parse_ply(ply, "x.ply");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(PlyCreases, ReadsEveryPropertyOrderEncodingAndElementPlace) {
  std::vector<std::pair<std::string, std::string>> edge = {
      {"int", "vertex1"}, {"uint", "vertex2"}, {"double", "crease"}};
  std::sort(edge.begin(), edge.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
  int cases = 0;
  do {
    for (const size_t corner_place : {size_t(0), size_t(4), size_t(9)})
      for (const bool before : {false, true})
        for (const bool binary : {false, true}) {
          CubePly ply;
          ply.vertex.insert(ply.vertex.begin() + long(corner_place), {"float", "corner"});
          ply.edge = edge;
          ply.creases = {{4, 5, 10}, {7, 6, 0.5}, {5, 6, 2.5}, {0, 1, 0}, {7, 4, 10}};
          ply.corners = {0, 0, 3, 0, 0, 0, 0, 0};
          ply.edge_before_faces = before;
          ply.binary = binary;
          const PlyContents read = parse_ply(ply.text(), "x.ply");
          EXPECT_EQ(read.mesh.sharpness, expected_top_creases())
              << "corner at " << corner_place << (before ? ", edges first" : "") << (binary ? ", binary" : "");
          ++cases;
        }
  } while (std::next_permutation(edge.begin(), edge.end(),
                                 [](const auto& x, const auto& y) { return x.second < y.second; }));
  EXPECT_EQ(cases, 6 * 3 * 2 * 2);
}

TEST(PlyCreases, RoundTripIsExactAndWritesFloatOnlyWhereExact) {
  test::TempDir dir;
  CubePly ply;
  const CovarianceMesh cube = parse_ply(ply.text(), "cube.ply").mesh;
  EXPECT_TRUE(cube.sharpness.empty());
  for (const bool exact_floats : {true, false}) {
    CovarianceMesh m = cube;
    m.sharpness = expected_top_creases();
    if (!exact_floats) {
      m.sharpness.set_crease(0, 1, 4.7);  // not a float
      m.sharpness.set_corner(5, 0.1, 8);
    }
    for (const bool binary : {false, true}) {
      const std::string path = dir.file(std::string(binary ? "b" : "a") + (exact_floats ? "f" : "d") + ".ply");
      write_mesh(path, m, binary);
      const CovarianceMesh back = read_mesh(path);
      EXPECT_EQ(back.sharpness, m.sharpness);
      std::ifstream in(path, std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      const std::string type = exact_floats ? "float" : "double";
      EXPECT_NE(text.find("property " + type + " corner\n"), std::string::npos);
      EXPECT_NE(text.find("element edge " + std::to_string(m.sharpness.creases.size()) +
                          "\nproperty int vertex1\nproperty int vertex2\nproperty " + type + " crease\n"),
                std::string::npos);
      // Written again, the file is the same bytes.
      const std::string again = dir.file("again.ply");
      write_mesh(again, back, binary);
      std::ifstream in2(again, std::ios::binary);
      EXPECT_EQ(text, std::string((std::istreambuf_iterator<char>(in2)), std::istreambuf_iterator<char>()));
    }
  }
}

TEST(PlyCreases, SmoothMeshWritesNeitherCornerNorEdge) {
  test::TempDir dir;
  const CovarianceMesh cube = parse_ply(CubePly().text(), "cube.ply").mesh;
  write_mesh(dir.file("c.ply"), cube);
  std::ifstream in(dir.file("c.ply"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text.find("corner"), std::string::npos);
  EXPECT_EQ(text.find("element edge"), std::string::npos);
}

TEST(PlyCreases, WritesNothingItWouldRefuse) {
  test::TempDir dir;
  const CovarianceMesh cube = parse_ply(CubePly().text(), "cube.ply").mesh;
  const auto message = [&](const Sharpness& s) {
    CovarianceMesh m = cube;
    m.sharpness = s;
    try {
      write_mesh(dir.file("w.ply"), m);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(written)");
  };
  const std::string head = dir.file("w.ply") + ": not written: ";
  EXPECT_EQ(message({{{0, 6, 1.0}}, {}}), head + "crease 0-6 is not an edge of the mesh");
  EXPECT_EQ(message({{{4, 8, 1.0}}, {}}), head + "crease 4-8 names a vertex outside the mesh");
  EXPECT_EQ(message({{{4, 5, std::nan("")}}, {}}), head + "crease 4-5 is not finite");
  EXPECT_EQ(message({{{4, 5, 1.0}, {5, 4, 2.0}}, {}}), head + "crease 4-5 is named twice");
  EXPECT_EQ(message({{}, {0, 0, 1}}), head + "3 corner values for 8 vertices");
  EXPECT_EQ(message({{}, {0, 0, -1, 0, 0, 0, 0, 0}}), head + "vertex 2 corner sharpness is negative");
  EXPECT_FALSE(std::filesystem::exists(dir.file("w.ply")));
}

TEST(PlyCreases, EdgeElementWithoutCreaseIsSkipped) {
  CubePly ply;
  ply.edge = {{"int", "vertex1"}, {"int", "vertex2"}, {"uchar", "red"}};
  ply.creases = {{0, 6, 200}};  // not an edge, but no crease either: a wireframe's record
  EXPECT_TRUE(parse_ply(ply.text(), "x.ply").mesh.sharpness.empty());
}

// A binary edge index too large for the mesh is shown in full, as the file holds it.
TEST(PlyCreases, ALargeBinaryEdgeIndexIsShownAsAnInteger) {
  CubePly ply;
  ply.edge = {{"uint", "vertex1"}, {"uint", "vertex2"}, {"float", "crease"}};
  ply.creases = {{4, 2147483648.0, 1}};
  ply.binary = true;
  EXPECT_EQ(message_of(ply.text()), "x.ply: edge 0 refers to vertex 2147483648, but there are 8 vertices");
}

TEST(PlyCreases, ErrorsNameTheFileAndTheRecord) {
  const auto with = [](std::vector<Crease> creases, bool binary = false) {
    CubePly ply;
    ply.creases = std::move(creases);
    ply.binary = binary;
    return message_of(ply.text());
  };
  EXPECT_EQ(with({{4, 5, 1}, {0, 6, 2}}), "x.ply: edge 1 (vertices 0-6) is not an edge of the mesh");
  EXPECT_EQ(with({{4, 5, 1}, {0, 6, 2}}, true), "x.ply: edge 1 (vertices 0-6) is not an edge of the mesh");
  EXPECT_EQ(with({{4, 9, 1}}), "x.ply: line 34: edge 0 refers to vertex 9, but there are 8 vertices");
  EXPECT_EQ(with({{-1, 4, 1}}, true), "x.ply: edge 0 refers to vertex -1, but there are 8 vertices");
  EXPECT_EQ(with({{4, 5, -1}}), "x.ply: line 34: edge 0 (vertices 4-5) crease -1 is negative");
  EXPECT_EQ(with({{4, 5, std::numeric_limits<double>::infinity()}}, true),
            "x.ply: edge 0 (vertices 4-5) crease inf is not finite");
  EXPECT_EQ(with({{4, 5, std::nan("")}}, true), "x.ply: edge 0 (vertices 4-5) crease nan is not finite");
  EXPECT_EQ(with({{3, 3, 1}}), "x.ply: line 34: edge 0 (vertices 3-3) joins a vertex to itself");
  {
    CubePly ply;
    ply.vertex.push_back({"float", "corner"});
    ply.corners = {0, 0, -0.5, 0, 0, 0, 0, 0};
    EXPECT_EQ(message_of(ply.text()), "x.ply: line 23: vertex 2 corner sharpness -0.5 is negative");
  }
  {
    CubePly ply;
    ply.edge = {{"int", "vertex1"}, {"float", "crease"}};
    ply.creases = {{4, 5, 1}};
    EXPECT_EQ(message_of(ply.text()), "x.ply: the edge element has a crease but lacks vertex1 or vertex2");
  }
  {
    std::string text = CubePly().text();
    text.insert(text.find("end_header"), "element edge 0\nproperty int vertex1\n");
    EXPECT_EQ(message_of(text), "x.ply: line 19: a second edge element (the first is line 15)");
  }
}

// An edge named again (as OpenSubdiv's catmark_inf_crease0 names one): with the same crease it is read
// once, without a note; with another the later record's crease is kept and one note names the first
// such record and how many there are, in ASCII and binary alike; a record of the pair on no edge is
// still refused.
TEST(PlyCreases, RepeatedEdgesKeepTheLaterCreaseWithANote) {
  const auto soup_of = [](std::vector<Crease> creases, bool binary) {
    CubePly ply;
    ply.creases = std::move(creases);
    ply.binary = binary;
    bool has_covariances = false;
    return parse_ply_soup(ply.text(), "x.ply", has_covariances);
  };
  for (const bool binary : {false, true}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    const PolygonSoup same = soup_of({{4, 5, 1}, {5, 6, 2}, {5, 4, 1}, {4, 5, 1}}, binary);
    EXPECT_EQ(same.sharpness.creases, (std::vector<EdgeCrease>{{4, 5, 1.0}, {5, 6, 2.0}}));
    EXPECT_TRUE(same.notes.empty());

    const PolygonSoup one = soup_of({{6, 7, 3}, {4, 5, 1}, {5, 6, 2}, {5, 4, 2.5}}, binary);
    EXPECT_EQ(one.sharpness.creases, (std::vector<EdgeCrease>{{4, 5, 2.5}, {5, 6, 2.0}, {6, 7, 3.0}}));
    EXPECT_EQ(one.notes,
              std::vector<std::string>{"x.ply: edge 3 (vertices 5-4) repeats edge 1 with crease 2.5 (edge 1 has 1): "
                                       "the later is kept"});

    // A later 0 makes the edge smooth again; the count covers every change, the example is the first.
    const PolygonSoup many = soup_of({{5, 6, 2}, {4, 5, 1}, {5, 6, 0}, {4, 5, 0.5}, {4, 5, 1}}, binary);
    EXPECT_EQ(many.sharpness.creases, (std::vector<EdgeCrease>{{4, 5, 1.0}}));
    EXPECT_EQ(many.notes, std::vector<std::string>{"x.ply: edge 2 (vertices 5-6) repeats edge 0 with crease 0 (edge 0 "
                                                   "has 2), and 2 more records repeat an edge with another crease: "
                                                   "the later is kept"});
  }
  CubePly refused;
  refused.creases = {{4, 5, 1}, {0, 6, 2}, {0, 6, 2}};
  EXPECT_EQ(message_of(refused.text()), "x.ply: edge 1 (vertices 0-6) is not an edge of the mesh");
}

// read_mesh passes the notes to its caller and reads the mesh with the later crease.
TEST(PlyCreases, ReadMeshGivesTheNotes) {
  test::TempDir dir;
  CubePly ply;
  ply.creases = {{4, 5, 1}, {4, 5, 3}};
  std::ofstream(dir.file("r.ply"), std::ios::binary) << ply.text();
  std::vector<std::string> notes;
  const CovarianceMesh m = read_mesh(dir.file("r.ply"), {}, nullptr, &notes);
  EXPECT_EQ(m.sharpness.crease(4, 5), 3.0);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], dir.file("r.ply") +
                          ": edge 1 (vertices 4-5) repeats edge 0 with crease 3 (edge 0 has 1): the "
                          "later is kept");
}

TEST(PlyCreases, RepairCarriesCreasesThroughWeldsAndRenumbering) {
  test::TempDir dir;
  // The cube with an isolated vertex first (all indices shifted by one), vertex 9 a copy of vertex 7
  // (6 in the cube) 1e-9 away that a sliver triangle 7 9 8 uses, and creases on the top edges, the sliver's
  // edge 7-9 (welded onto one vertex: dropped) and 9-8 (becoming 6-7 of the cube).
  std::ostringstream ply;
  ply << "ply\nformat ascii 1.0\nelement vertex 10\nproperty double x\nproperty double y\nproperty double z\n"
         "property float corner\nelement face 7\nproperty list uchar int vertex_indices\nelement edge 4\n"
         "property int vertex1\nproperty int vertex2\nproperty float crease\nend_header\n";
  ply << "5 5 5 0\n";
  for (int v = 0; v < 8; ++v)
    ply << kCube[v][0] << ' ' << kCube[v][1] << ' ' << kCube[v][2] << (v == 2 ? " 3\n" : " 0\n");
  ply << "1 1 1.000000001 1.5\n";
  for (const auto& f : kCubeFaces)
    ply << "4 " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << ' ' << f[3] + 1 << '\n';
  ply << "3 7 9 8\n";
  ply << "5 6 10\n6 7 2.5\n7 9 4\n9 8 0.5\n";
  const std::string path = dir.write("r.ply", ply.str());
  EXPECT_THROW(read_mesh(path), Error);  // not repaired: the sliver is refused
  ImportOptions options;
  options.repair = true;
  RepairReport report;
  const CovarianceMesh m = read_mesh(path, options, &report);
  ASSERT_EQ(m.n_vertices(), 8u);
  Sharpness expected;
  expected.creases = {{4, 5, 10.0}, {5, 6, 2.5}, {6, 7, 0.5}};
  expected.corners = {0, 0, 3.0, 0, 0, 0, 1.5, 0};  // the weld keeps the group's largest corner
  EXPECT_EQ(m.sharpness, expected);
  EXPECT_EQ(report.dropped_creases, 1);
  const auto lines = report.lines();
  EXPECT_NE(std::find(lines.begin(), lines.end(), "dropped 1 crease no longer on an edge"), lines.end());
}

}  // namespace
}  // namespace gps
