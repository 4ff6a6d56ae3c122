// OpenSubdiv's OBJ tags "t crease" and "t corner": read with vertices numbered from 0, pairs of
// vertices per crease, one sharpness for all or one each; written back by write_mesh.
#include <gtest/gtest.h>

#include "core/io/mesh_import.h"
#include "core/io/mesh_io.h"
#include "core/support/error.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

// A cube, OBJ vertices 1..8 (tags: 0..7), top face 5 6 7 8.
const std::string kCube =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

std::string message_of(const std::string& tags) {
  try {
    parse_obj(kCube + tags, "x.obj");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ObjCreases, ReadsPairsCornersAndSkipsOtherTags) {
  const CovarianceMesh m = parse_obj(kCube +
                                         "t crease 4/1/0 4 5 5 6 10\n"
                                         "t crease 4/2/0 6 7 7 4 2.5 0.5\n"
                                         "t crease 2/1/0 0 1 3\n"
                                         "t crease 2/1/0 1 0 0\n"  // a later tag wins: 0-1 smooth again
                                         "t corner 2/1/0 0 2 1.5\n"
                                         "t interpolateboundary 1/0/0 2\n"
                                         "t hole 1/0/0 3\n",
                                     "x.obj");
  Sharpness expected;
  expected.creases = {{4, 5, 10.0}, {4, 7, 0.5}, {5, 6, 10.0}, {6, 7, 2.5}};
  expected.corners = {1.5, 0, 1.5, 0, 0, 0, 0, 0};
  EXPECT_EQ(m.sharpness, expected);
}

TEST(ObjCreases, WriteReadRoundTripKeepsSharpness) {
  test::TempDir dir;
  CovarianceMesh m = parse_obj(kCube, "x.obj");
  m.sharpness.set_crease(4, 5, 0.1);  // not exact in binary: 17 digits keep it
  m.sharpness.set_crease(2, 3, kInfiniteSharpness);
  m.sharpness.set_corner(7, 4.7, 8);
  write_mesh(dir.file("c.obj"), m);
  EXPECT_EQ(read_mesh(dir.file("c.obj")).sharpness, m.sharpness);
}

TEST(ObjCreases, ErrorsNameTheFileAndLine) {
  EXPECT_EQ(message_of("t crease 2/1/0 4 8 1\n"),
            "x.obj: line 15: crease tag names vertex 8, but there are 8 vertices (tags number them from 0)");
  EXPECT_EQ(message_of("t corner 1/1/0 -1 1\n"),
            "x.obj: line 15: corner tag names vertex -1 (tags number vertices from 0)");
  // Counts are not trusted: a huge one is refused when the line runs out.
  EXPECT_EQ(message_of("t corner 999999999999/1/0 0 1\n"),
            "x.obj: line 15: the corner tag has fewer values than its counts say");
  EXPECT_EQ(message_of("t crease 2/1/0 0 6 1\n"),
            "x.obj: line 15: crease 0-6 is not an edge of the mesh (tags number vertices from 0; remove the tag or "
            "name an edge)");
  EXPECT_EQ(message_of("t crease 2/1/0 4 5 -2\n"), "x.obj: line 15: crease sharpness -2 is negative");
  EXPECT_EQ(message_of("t corner 1/1/0 4 inf\n"), "x.obj: line 15: corner sharpness inf is not finite");
  EXPECT_EQ(message_of("t crease 3/1/0 4 5 6 1\n"),
            "x.obj: line 15: a crease tag needs pairs of vertices, a corner tag vertices (3 given)");
  EXPECT_EQ(message_of("t crease 4/3/0 4 5 5 6 1 2 3\n"),
            "x.obj: line 15: the crease tag has 3 sharpness values for 2 edges (1 for all or 1 each)");
  EXPECT_EQ(message_of("t crease 2/1/0 4 5\n"), "x.obj: line 15: the crease tag has fewer values than its counts say");
  EXPECT_EQ(message_of("t crease 2/1 4 5 1\n"),
            "x.obj: line 15: the crease tag's counts '2/1' are not nint/nfloat/nstring (three counts, such as 2/1/0 "
            "for a crease: its two vertices, one value)");
  EXPECT_EQ(message_of("t corner 1/1/0 x 1\n"), "x.obj: line 15: 'x' is not a vertex index");
}

// A tag repeated (as OpenSubdiv's catmark_inf_crease0 repeats a crease): with the same value it is read
// once, without a note; with another the later is kept, as OpenSubdiv's readers keep it, and one note per
// kind names the first such tag, the tag it repeats and how many there are.
TEST(ObjCreases, RepeatedTagsKeepTheLaterWithANote) {
  const PolygonSoup same = parse_obj_soup(kCube +
                                              "t crease 2/1/0 4 5 1\n"  // line 15
                                              "t crease 4/1/0 5 4 6 7 1\n"
                                              "t corner 2/1/0 2 2 3\n"
                                              "t corner 1/1/0 2 3\n",
                                          "x.obj");
  Sharpness expected;
  expected.creases = {{4, 5, 1.0}, {6, 7, 1.0}};
  expected.corners = {0, 0, 3, 0, 0, 0, 0, 0};
  EXPECT_EQ(same.sharpness, expected);
  EXPECT_TRUE(same.notes.empty());

  const PolygonSoup other = parse_obj_soup(kCube +
                                               "t crease 2/1/0 4 5 1\n"  // line 15
                                               "t corner 1/1/0 2 3\n"
                                               "t crease 4/2/0 6 7 5 4 2 2.5\n"
                                               "t crease 2/1/0 7 6 0\n"  // smooth again
                                               "t corner 1/1/0 2 0.5\n",
                                           "x.obj");
  expected.creases = {{4, 5, 2.5}};
  expected.corners = {0, 0, 0.5, 0, 0, 0, 0, 0};
  EXPECT_EQ(other.sharpness, expected);
  EXPECT_EQ(other.notes, (std::vector<std::string>{
                             "x.obj: line 17: crease 4-5 repeats line 15's with sharpness 2.5 (line 15 gives 1), and 1 "
                             "more crease tags repeat one with another value: the later is kept",
                             "x.obj: line 19: corner 2 repeats line 16's with sharpness 0.5 (line 16 gives 3): the "
                             "later is kept"}));
  // What the tags name is still checked on every tag, repeated or not.
  EXPECT_EQ(message_of("t crease 2/1/0 4 5 1\nt crease 2/1/0 4 5 2\nt crease 2/1/0 0 6 1\n"),
            "x.obj: line 17: crease 0-6 is not an edge of the mesh (tags number vertices from 0; remove the tag or "
            "name an edge)");
}

}  // namespace
}  // namespace gps
