// What the readers drop (texture coordinates, normals, vertex colours, other properties and tags) is said
// in one note.
#include "core/io/dropped_attributes.h"

#include <gtest/gtest.h>

#include "core/io/mesh_import.h"
#include "core/io/ply_io.h"

namespace gps {
namespace {

const std::string kTail =
    " dropped (a covariance mesh keeps positions, Gaussians and creases; normals come from the limit surface)";

TEST(DroppedAttributes, TheNoteCountsEachKind) {
  EXPECT_EQ(dropped_attributes_note("m.obj", {}), "");
  EXPECT_EQ(dropped_attributes_note("m.obj", {1, 0, 0, {}}), "m.obj: 1 texture coordinate" + kTail);
  EXPECT_EQ(dropped_attributes_note("m.obj", {4, 1, 0, {}}), "m.obj: 4 texture coordinates and 1 normal" + kTail);
  EXPECT_EQ(dropped_attributes_note("m.obj", {4, 2, 3, {}}),
            "m.obj: 4 texture coordinates, 2 normals and 3 vertex colours" + kTail);
}

// A file of 40,000 unread properties gave a note of 389,031 characters on one line.
TEST(DroppedAttributes, ANoteNamesAFewAndCountsTheRest) {
  std::vector<std::string> names;
  for (int i = 0; i < 40000; ++i) names.push_back("'p" + std::to_string(i) + "'");
  EXPECT_EQ(named_list("vertex property", "vertex properties", names),
            "vertex properties 'p0', 'p1', 'p2', 'p3', 'p4', 'p5', 'p6' and 39993 more");
  names.resize(kNamesListed);
  EXPECT_EQ(named_list("vertex property", "vertex properties", names),
            "vertex properties 'p0', 'p1', 'p2', 'p3', 'p4', 'p5', 'p6' and 'p7'");
  EXPECT_EQ(named_list("vertex property", "vertex properties", {"'q'"}), "vertex property 'q'");
}

TEST(DroppedAttributes, ObjTextureCoordinatesNormalsAndColoursAreNoted) {
  const std::string quad =
      "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 1 1 1\n"  // MeshLab's colours
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1 4/4/1\n";
  const PolygonSoup soup = parse_obj_soup(quad, "quad.obj");
  EXPECT_EQ(soup.notes,
            (std::vector<std::string>{"quad.obj: 4 texture coordinates, 1 normal and 4 vertex colours" + kTail}));
  EXPECT_TRUE(parse_obj_soup("v 0 0 0 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "weight.obj").notes.empty());  // a weight
}

TEST(DroppedAttributes, PlyNormalsColoursAndTextureCoordinatesAreNoted) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nproperty float s\nproperty float t\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n"
      "0 0 0 0 0 1 255 0 0 0 0\n1 0 0 0 0 1 0 255 0 1 0\n0 1 0 0 0 1 0 0 255 0 1\n3 0 1 2\n";
  bool has_covariances = true;
  const PolygonSoup soup = parse_ply_soup(ply, "tri.ply", has_covariances);
  EXPECT_FALSE(has_covariances);
  EXPECT_EQ(soup.notes,
            (std::vector<std::string>{"tri.ply: 3 texture coordinates, 3 normals and 3 vertex colours" + kTail}));
}

// A normal, colour or texture coordinate is known by the property that leads it (nx, red, u …); its other
// properties without it (a lone v, alpha beside normals) were dropped without a word: they are named.
TEST(DroppedAttributes, PlyPropertiesWithoutTheirLeadAreNamed) {
  const auto note_of = [](const std::string& properties, const std::string& values) {
    std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    ply += properties + "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    for (const char* position : {"0 0 0 ", "1 0 0 ", "0 1 0 "}) ply += position + values + "\n";
    bool has_covariances = true;
    const PolygonSoup soup = parse_ply_soup(ply + "3 0 1 2\n", "p.ply", has_covariances);
    return soup.notes.empty() ? std::string() : soup.notes[0];
  };
  EXPECT_EQ(note_of("property float v\nproperty uchar alpha\n", "0 9"),
            "p.ply: vertex properties 'v' and 'alpha'" + kTail);
  EXPECT_EQ(note_of("property float nx\nproperty float ny\nproperty float nz\nproperty uchar alpha\n", "0 0 1 9"),
            "p.ply: 3 normals and vertex property 'alpha'" + kTail);
  EXPECT_EQ(note_of("property float ny\nproperty float nz\nproperty float texture_t\nproperty uchar green\n"
                    "property uchar blue\n",
                    "0 1 0 9 9"),
            "p.ply: vertex properties 'ny', 'nz', 'texture_t', 'green' and 'blue'" + kTail);
  EXPECT_EQ(note_of("property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
                    "property float texture_u\nproperty float texture_v\n",
                    "1 2 3 4 0 1"),
            "p.ply: 3 texture coordinates and 3 vertex colours" + kTail);
}

// Whatever else a file holds is named: a PLY's other vertex and face properties, the colours and
// normals of an OFF's variants (COFF, NOFF), an OBJ's tags other than crease and corner.
TEST(DroppedAttributes, OtherPropertiesTagsAndOffValuesAreNamed) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float quality\nelement face 1\nproperty list uchar int vertex_indices\nproperty uchar red\n"
      "property list uchar float texcoord\nend_header\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2 9 6 0 0 1 0 0 1\n";
  bool has_covariances = true;
  EXPECT_EQ(
      parse_ply_soup(ply, "q.ply", has_covariances).notes,
      (std::vector<std::string>{"q.ply: vertex property 'quality' and face properties 'red' and 'texcoord'" + kTail}));
  const std::string coff = "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 255 0 0 255\n0 1 0\n3 0 1 2 255 0 0\n";
  EXPECT_EQ(parse_off_soup(coff, "c.off").notes,
            (std::vector<std::string>{"c.off: the values after the position of 2 vertices (colours, normals or "
                                      "texture coordinates) and the colours of 1 face" +
                                      kTail}));
  EXPECT_TRUE(parse_off_soup("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "p.off").notes.empty());
  const std::string tagged =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nt holes 1/0/0 0\n"
      "t interpolateboundary 1/0/0 2\nt holes 1/0/0 0\n";
  EXPECT_EQ(parse_obj_soup(tagged, "h.obj").notes,
            (std::vector<std::string>{"h.obj: the tags 'holes' and 'interpolateboundary'" + kTail}));
}

}  // namespace
}  // namespace gps
