// Records the readers do not keep are still read as the format defines them: an OBJ face corner's
// texture coordinate and normal name ones that are there, `vt` and `vn` hold numbers, a tag holds
// what its counts say, the values after a vertex or an OFF face are finite numbers, a PLY integer
// holds what its declared type can; records of kinds a mesh does not hold are noted, not dropped
// silently; and files of vertices alone are points to measure, not meshes.
#include <gtest/gtest.h>

#include "core/io/mesh_import.h"
#include "core/io/mesh_io.h"
#include "core/io/ply_io.h"
#include "core/io/polygon_soup.h"
#include "core/support/error.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using test::error_of;

const std::string kPyramid = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\nvt 0 0\nvn 0 0 1\n";

std::string obj_refusal(const std::string& text) {
  return error_of([&] { parse_obj_soup(kPyramid + text, "p.obj"); });
}

TEST(ReaderRecords, ObjFaceCornersNameTextureCoordinatesAndNormalsThatAreThere) {
  EXPECT_EQ(parse_obj_soup(kPyramid + "f 1/1/1 2/-1/-1 5//1\nf 2 3/1/ 5/1\n", "p.obj").faces.n_faces(), 2);
  EXPECT_EQ(obj_refusal("f 1/1 2/9 5/1\n"),
            "p.obj: line 8: '2/9': texture coordinate index 9 is out of range (1 so far)");
  EXPECT_EQ(obj_refusal("f 1/0 2 5\n"), "p.obj: line 8: '1/0': texture coordinate index 0 is out of range (1 so far)");
  EXPECT_EQ(obj_refusal("f 1/-3 2 5\n"),
            "p.obj: line 8: '1/-3': texture coordinate index -3 is out of range (1 so far)");
  EXPECT_EQ(obj_refusal("f 1/x 2 5\n"), "p.obj: line 8: '1/x': 'x' is not a texture coordinate index");
  EXPECT_EQ(obj_refusal("f 1//1 2//7 5//1\n"), "p.obj: line 8: '2//7': normal index 7 is out of range (1 so far)");
  EXPECT_EQ(obj_refusal("f 1/1/1/1 2 5\n"),
            "p.obj: line 8: '1/1/1/1' is not a face corner (v, v/vt, v//vn or v/vt/vn)");
  // A corner may name only what came before it, as OBJ's relative indices count.
  EXPECT_NE(error_of([] {
              parse_obj_soup("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\nvt 0 0\n", "late.obj");
            }).find("texture coordinate index 1 is out of range (0 so far)"),
            std::string::npos);
}

TEST(ReaderRecords, ObjTextureCoordinatesNormalsAndVertexValuesAreNumbers) {
  EXPECT_EQ(parse_obj_soup(kPyramid + "vt 0.5\nvt 0 1 0\nf 1 2 5\n", "p.obj").faces.n_faces(), 1);  // u [v [w]]
  EXPECT_EQ(obj_refusal("vt 0 abc\n"), "p.obj: line 8: 'abc' is not a number");
  EXPECT_EQ(obj_refusal("vn 0 0\n"), "p.obj: line 8: a normal needs 3 numbers (x y z), got 2");
  EXPECT_EQ(obj_refusal("vt 0 0 0 0\n"), "p.obj: line 8: a texture coordinate needs 1 to 3 numbers (u v w), got 4");
  EXPECT_EQ(error_of([] { parse_obj_soup("v 0 0 0 1 0 1e999\n", "c.obj"); }),
            "c.obj: line 1: '1e999' overflows (too large for a double) (after the vertex's coordinates: a weight or a "
            "colour)");
  EXPECT_EQ(error_of([] { parse_obj_soup("v 0 0 0 nan 0 0\n", "n.obj"); }),
            "n.obj: line 1: 'nan' is not a finite number (after the vertex's coordinates: a weight or a colour)");
}

TEST(ReaderRecords, ObjTagsHoldWhatTheirCountsSay) {
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  EXPECT_EQ(error_of([&] { parse_obj_soup(square + "t crease 2/1/0 0 1 2 3 5\n", "t.obj"); }),
            "t.obj: line 6: the crease tag has more values than its counts say ('3')");
  EXPECT_EQ(parse_obj_soup(square + "t crease 2/1/0 0 1 2 # sharp\n", "t.obj").sharpness.creases.size(), 1u);
  EXPECT_EQ(parse_obj_soup(square + "t crease 2/1/1 0 1 2 name\n", "t.obj").sharpness.creases.size(), 1u);
}

TEST(ReaderRecords, RecordsOfOtherKindsAreNoted) {
  const std::string kTail =
      " dropped (a covariance mesh keeps positions, Gaussians and creases; normals come from the limit surface)";
  EXPECT_EQ(
      parse_obj_soup(kPyramid + "o pyramid\ng base\ns 1\nusemtl m\nl 1 2\nl 2 3\np 5\ncurv 0 1 1 2\nf 1 2 5\n", "p.obj")
          .notes,
      (std::vector<std::string>{"p.obj: 1 texture coordinate, 1 normal, 1 'curv' record, 2 'l' records and 1 "
                                "'p' record" +
                                kTail}));
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nelement material 2\nproperty uchar red\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n255\n0\n";
  bool has_covariances = false;
  EXPECT_EQ(parse_ply_soup(ply, "m.ply", has_covariances).notes,
            (std::vector<std::string>{"m.ply: element 'material' (2 records)" + kTail}));
}

TEST(ReaderRecords, PlyIntegersHoldWhatTheirTypeCanAndOffValuesAreNumbers) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property uchar red\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  bool has_covariances = false;
  for (const char* red : {"300", "-1", "1.5"})
    EXPECT_EQ(error_of([&] {
                parse_ply_soup(head + "0 0 0 " + red + "\n1 0 0 0\n0 1 0 0\n3 0 1 2\n", "r.ply", has_covariances);
              }),
              std::string("r.ply: line 11: '") + red +
                  "' is not a non-negative integer of 8 bits, as its property is "
                  "declared");
  EXPECT_EQ(
      error_of([&] { parse_ply_soup(head + "0 0 0 1\n1 0 0 0\n0 1 0 0\n259 0 1 2\n", "c.ply", has_covariances); }),
      "c.ply: line 14: face 0: list length 259 is more than its count type holds (a non-negative integer of 8 bits)");
  EXPECT_EQ(error_of([] { parse_off_soup("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 2 1 junk\n", "j.off"); }),
            "j.off: line 6: 'junk' is not a number (the values after a vertex's position or a face's corners are "
            "numbers)");
  EXPECT_EQ(error_of([] { parse_off_soup("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 2 9\n", "o.off"); }),
            "o.off: line 6: face 0 refers to vertex 9, but there are 3 vertices");
}

TEST(ReaderRecords, FilesOfVerticesAloneArePointsNotMeshes) {
  test::TempDir dir;
  const std::string obj = dir.write("cloud.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  const std::string off = dir.write("cloud.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  for (const std::string& path : {obj, off}) {
    EXPECT_EQ(read_points(path).size(), 3u) << path;
    EXPECT_EQ(error_of([&] { read_mesh(path); }), path + ": the mesh has no faces");
  }
  EXPECT_EQ(error_of([] { parse_obj("v 0 0 0\n", "one.obj"); }), "one.obj: the mesh has no faces");
}

}  // namespace
}  // namespace gps
