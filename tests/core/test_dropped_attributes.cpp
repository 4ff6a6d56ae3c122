// What the readers drop (texture coordinates, normals, vertex colours) is said in one note.
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
  EXPECT_EQ(dropped_attributes_note("m.obj", {1, 0, 0}), "m.obj: 1 texture coordinate" + kTail);
  EXPECT_EQ(dropped_attributes_note("m.obj", {4, 1, 0}), "m.obj: 4 texture coordinates and 1 normal" + kTail);
  EXPECT_EQ(dropped_attributes_note("m.obj", {4, 2, 3}),
            "m.obj: 4 texture coordinates, 2 normals and 3 vertex colours" + kTail);
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

}  // namespace
}  // namespace gps
