// Modelling operations as data (core/modelling/operation_list.h): the same result as the calls they
// name, indices that refer to the mesh as each operation finds it, and errors that name the
// operation before anything is applied.
#include <gtest/gtest.h>

#include <array>

#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "core/modelling/affine_transform.h"
#include "core/modelling/crease_edges.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/extrude.h"
#include "core/modelling/fill.h"
#include "core/modelling/grid_fill.h"
#include "core/modelling/inset.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/operation_list.h"
#include "core/modelling/primitives.h"
#include "core/modelling/split_faces.h"
#include "core/plans/patch_layout.h"
#include "tests/support/error_of.h"

namespace gps {
namespace {

using test::error_of;

void expect_same_gaussians_and_faces(const CovarianceMesh& a, const CovarianceMesh& b) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.n_faces(), b.n_faces());
  for (size_t v = 0; v < a.n_vertices(); ++v) {
    EXPECT_EQ(a.mean(v), b.mean(v)) << "vertex " << v;
    EXPECT_EQ(a.covariance(v), b.covariance(v)) << "vertex " << v;
  }
  for (size_t f = 0; f < a.n_faces(); ++f) {
    const std::span<const int> fa = a.face(f), fb = b.face(f);
    EXPECT_EQ(std::vector<int>(fa.begin(), fa.end()), std::vector<int>(fb.begin(), fb.end())) << "face " << f;
  }
}

TEST(OperationList, SameAsTheCallsItNames) {
  const CovarianceMesh cube = make_sample("cube");
  const OperationList ops = OperationList::parse(
      R"([{"op":"loop_cut","edge":[0,1],"cuts":2},{"op":"extrude","faces":[1],"distance":0.25}])", "ops.json");
  EXPECT_EQ(ops.names(), (std::vector<std::string>{"loop_cut", "extrude"}));
  std::vector<std::string> summaries;
  const Modelled scripted = ops.apply(cube, &summaries);
  EXPECT_EQ(summaries.size(), 2u);
  const Modelled direct = extrude_faces(loop_cut(cube, 0, 1, 2).mesh, {1}, 0.25);
  expect_same_gaussians_and_faces(scripted.mesh, direct.mesh);
  EXPECT_EQ(scripted.selection, direct.selection);
}

// A run of steps made on arrays (additions, extrusions and insets of faces) builds its mesh once: the
// same mesh, selection and summaries as one step at a time, with the creases and corners kept, and a
// refusal naming the step that fails.
TEST(OperationList, ARunOfAdditionsIsTheSameAsOneAtATime) {
  CovarianceMesh cube = make_sample("cube");
  cube.sharpness.set_crease(0, 1, 2.0);
  cube.sharpness.set_corner(2, 3.0, int(cube.n_vertices()));
  const OperationList ops = OperationList::parse(
      R"([{"op":"add","primitive":"torus","center":[3,0,0]},{"op":"add","primitive":"cone","size":2},
          {"op":"extrude","faces":[0],"distance":0.5},{"op":"add","primitive":"plane","center":[0,4,0]}])",
      "ops.json");
  std::vector<std::string> summaries;
  const Modelled scripted = ops.apply(cube, &summaries);
  const Modelled torus = add_primitive(cube, Primitive::torus, Vec3(3, 0, 0), 1);
  const Modelled cone = add_primitive(torus.mesh, Primitive::cone, Vec3::Zero(), 2);
  const Modelled direct = add_primitive(extrude_faces(cone.mesh, {0}, 0.5).mesh, Primitive::plane, Vec3(0, 4, 0), 1);
  expect_same_gaussians_and_faces(scripted.mesh, direct.mesh);
  EXPECT_EQ(scripted.mesh.sharpness.creases.size(), direct.mesh.sharpness.creases.size());
  EXPECT_EQ(scripted.mesh.sharpness.corners, direct.mesh.sharpness.corners);
  EXPECT_EQ(scripted.selection, direct.selection);
  ASSERT_EQ(summaries.size(), 4u);
  EXPECT_EQ(summaries[1], cone.summary);
  EXPECT_EQ(error_of([&] {
              OperationList::parse(R"([{"op":"add","primitive":"cube"},{"op":"add","primitive":"cube","size":1e-200}])",
                                   "f")
                  .apply(cube);
            }).rfind("f: ops[1] (add): the result would not be a valid mesh: vertex 16 ", 0),
            0u);
}

// Extrusions, insets and deletions in one run, on quads and on triangles (whose bands are split into
// triangles), each naming elements of the mesh as the steps before left it (a deletion renumbers them):
// the mesh, selection and summaries of the calls one at a time; a refusal in the middle of the run
// names its step.
TEST(OperationList, ARunOfExtrusionsInsetsAndDeletionsIsTheSameAsOneAtATime) {
  for (const char* name : {"sphere", "icosphere"}) {
    const CovarianceMesh start = make_sample(name, 300);
    const int last = int(start.n_faces()) - 1;
    const std::array<int, 2> edge = start.edge(7);
    const OperationList ops = OperationList::parse(
        R"([{"op":"extrude","faces":[3,4],"distance":0.1},{"op":"inset","faces":[4],"thickness":0.02},
            {"op":"delete","faces":[9]},{"op":"extrude","faces":[)" +
            std::to_string(last + 2) + R"(],"distance":-0.05},{"op":"inset","faces":[0,1,2],"thickness":0.01},
            {"op":"delete","vertices":[40]},{"op":"extrude","faces":[0],"distance":0.03},
            {"op":"delete","edges":[[)" +
            std::to_string(edge[0]) + "," + std::to_string(edge[1]) + R"(]]}])",
        "ops.json");
    std::vector<std::string> summaries;
    const Modelled scripted = ops.apply(start, &summaries);
    std::vector<Modelled> direct;
    direct.push_back(extrude_faces(start, {3, 4}, 0.1));
    direct.push_back(inset_faces(direct.back().mesh, {4}, 0.02));
    direct.push_back(delete_faces(direct.back().mesh, {9}));
    direct.push_back(extrude_faces(direct.back().mesh, {last + 2}, -0.05));
    direct.push_back(inset_faces(direct.back().mesh, {0, 1, 2}, 0.01));
    direct.push_back(delete_vertices(direct.back().mesh, {40}));
    direct.push_back(extrude_faces(direct.back().mesh, {0}, 0.03));
    direct.push_back(delete_edges(direct.back().mesh, {edge}));
    expect_same_gaussians_and_faces(scripted.mesh, direct.back().mesh);
    EXPECT_EQ(scripted.selection, direct.back().selection) << name;
    ASSERT_EQ(summaries.size(), direct.size()) << name;
    for (size_t i = 0; i < direct.size(); ++i) EXPECT_EQ(summaries[i], direct[i].summary) << name << " step " << i;
  }
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(
      error_of([&] {
        OperationList::parse(R"([{"op":"extrude","faces":[0],"distance":1},{"op":"inset","faces":[99],
                                       "thickness":0.1},{"op":"extrude","faces":[1],"distance":1}])",
                             "f")
            .apply(cube);
      }),
      error_of([&] { inset_faces(extrude_faces(cube, {0}, 1.0).mesh, {99}, 0.1); }).insert(0, "f: ops[1] (inset): "));
  // An extrusion by nothing, which would lay new faces on the old ones, is a usage error as read.
  for (const char* op :
       {R"({"op":"extrude","faces":[0],"distance":0})", R"({"op":"extrude","faces":[0],"distance":-0.0})"})
    EXPECT_EQ(error_of([&] { OperationList::parse(std::string("[") + op + "]", "f"); }),
              "f: ops[0] (extrude): \"distance\" must not be 0 (the new faces would lie on the old ones)");
  EXPECT_EQ(error_of([&] { OperationList::parse(R"([{"op":"extrude","edges":[[0,1]],"offset":[0,0,0]}])", "f"); }),
            "f: ops[0] (extrude): \"offset\" must not be [0, 0, 0] (the new faces would have no area)");
  // A step whose vertices the mesh would refuse (moved past the largest position) is named by its own
  // index, not by the run's last, with the words the step alone would get.
  const std::string far = error_of([&] { extrude_faces(extrude_faces(cube, {0}, 1.0).mesh, {1}, 1e200); });
  EXPECT_NE(far.find("the result would not be a valid mesh: vertex "), std::string::npos) << far;
  EXPECT_EQ(error_of([&] {
              OperationList::parse(R"([{"op":"extrude","faces":[0],"distance":1},{"op":"extrude","faces":[1],
                                       "distance":1e200},{"op":"extrude","faces":[2],"distance":1}])",
                                   "f")
                  .apply(cube);
            }),
            "f: ops[1] (extrude): " + far);
  // A deletion that would leave two fans of faces meeting at a vertex (two diagonal faces of a grid
  // around its centre vertex, the other two deleted) refuses itself, in the middle of a run.
  const CovarianceMesh grid = make_sample("grid", 4);
  const std::string bowtie = error_of([&] { delete_faces(grid, {0, 3}); });
  EXPECT_NE(bowtie.find("non-manifold at vertex"), std::string::npos) << bowtie;
  EXPECT_EQ(error_of([&] {
              OperationList::parse(R"([{"op":"inset","faces":[1],"thickness":0.01},{"op":"delete","faces":[0,3]},
                                       {"op":"extrude","faces":[2],"distance":1}])",
                                   "f")
                  .apply(grid);
            }),
            error_of([&] {
              delete_faces(inset_faces(grid, {1}, 0.01).mesh, {0, 3});
            }).insert(0, "f: ops[1] (delete): "));
}

TEST(OperationList, IndicesReferToTheMeshAsItStands) {
  // Deleting face 0 closes up the faces: the old face 1 is face 0 for the next operation, and the
  // hole's corners keep their indices (no vertex is unused), so filling them closes the cube again.
  const CovarianceMesh cube = make_sample("cube");
  const Modelled m = OperationList::parse(R"([{"op":"delete","faces":[0]},{"op":"fill","vertices":[0,3,2,1]},
                                              {"op":"extrude","faces":[0],"distance":1}])",
                                          "")
                         .apply(cube);
  EXPECT_EQ(m.mesh.n_faces(), 6u + 4u);
  const Modelled direct = extrude_faces(fill(delete_faces(cube, {0}).mesh, {0, 3, 2, 1}).mesh, {0}, 1.0);
  expect_same_gaussians_and_faces(m.mesh, direct.mesh);
  // Face 0 is now the old top face (z = 1): its vertices moved up by 1.
  for (const int v : m.mesh.face(0)) EXPECT_DOUBLE_EQ(m.mesh.mean(size_t(v)).z(), 2.0);
}

TEST(OperationList, SetAndTransform) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled m = OperationList::parse(R"([{"op":"set","vertices":[6,7],"covariance":[0.01,0,0,0.04,0,0.09]},
      {"op":"transform","vertices":[6],"matrix":[1,0,0,1, 0,2,0,0, 0,0,1,0, 0,0,0,1]}])",
                                          "")
                         .apply(cube);
  EXPECT_EQ(m.mesh.covariance(7), Vec3(0.01, 0.04, 0.09).asDiagonal().toDenseMatrix());
  EXPECT_TRUE(m.mesh.covariance(6).isApprox(Vec3(0.01, 0.16, 0.09).asDiagonal().toDenseMatrix(), 1e-15));
  EXPECT_EQ(m.mesh.mean(6), Vec3(2, 2, 1));
  EXPECT_EQ(m.mesh.mean(0), cube.mean(0));
}

// Steps on Gaussians and sharpness change the list's copy in place (at the cost of what they change):
// the same mesh, sharpness, selection and summaries as the whole-mesh calls they name, between
// topology steps, a mirror among them; the input untouched; a refusal names the step.
TEST(OperationList, StepsInPlaceAreTheCallsTheyName) {
  CovarianceMesh cube = make_sample("cube");
  const CovarianceMesh before = cube;
  const OperationList ops = OperationList::parse(
      R"([{"op":"set","vertices":[6,7],"scale":0.5},{"op":"crease","edges":[[0,1],[1,2]],"sharpness":2.5},
          {"op":"extrude","faces":[1],"distance":0.25},{"op":"corner","vertices":[3,9],"sharpness":10},
          {"op":"transform","vertices":[8,9,10,11],"matrix":[1,0,0,0.5, 0,1,0,0, 0,0,2,0, 0,0,0,1]},
          {"op":"set","vertices":[9],"mean":[0.25,0.5,3],"covariance":[0.01,0,0,0.04,0,0.09]},
          {"op":"transform","vertices":"all","matrix":[-1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]},
          {"op":"crease","edges":[[0,1]],"sharpness":0}])",
      "ops.json");
  std::vector<std::string> summaries;
  const Modelled scripted = ops.apply(cube, &summaries);
  expect_same_gaussians_and_faces(cube, before);
  EXPECT_EQ(cube.sharpness, before.sharpness);

  std::vector<std::string> direct_summaries;
  const auto step = [&](const Modelled& m) {
    direct_summaries.push_back(m.summary);
    return m;
  };
  // "set" has no call of its own: its Gaussians set by hand.
  Modelled m{cube, {6, 7}, "set 2 Gaussians", {}, {}};
  m.mesh.covariances[6] *= 0.5;
  m.mesh.covariances[7] *= 0.5;
  direct_summaries.push_back(m.summary);
  m = step(set_crease(m.mesh, {{0, 1}, {1, 2}}, 2.5));
  m = step(extrude_faces(m.mesh, {1}, 0.25));
  m = step(set_corner(m.mesh, {3, 9}, 10));
  Mat3 stretch = Mat3::Identity();
  stretch(2, 2) = 2;
  m = step(transform_vertices(m.mesh, {8, 9, 10, 11}, AffineMap{stretch, Vec3(0.5, 0, 0)}));
  m.mesh.set_mean(9, Vec3(0.25, 0.5, 3));
  m.mesh.covariances[9] = Vec3(0.01, 0.04, 0.09).asDiagonal();
  direct_summaries.push_back("set 1 Gaussian");
  Mat3 mirror = Mat3::Identity();
  mirror(0, 0) = -1;
  m = step(transform_vertices(m.mesh, {}, AffineMap{mirror, Vec3::Zero()}));
  m = step(set_crease(m.mesh, {{0, 1}}, 0));

  expect_same_gaussians_and_faces(scripted.mesh, m.mesh);
  EXPECT_EQ(scripted.mesh.sharpness, m.mesh.sharpness);
  EXPECT_EQ(scripted.selection, m.selection);
  EXPECT_EQ(summaries, direct_summaries);
  EXPECT_EQ(error_of([&] {
              OperationList::parse(
                  R"([{"op":"set","vertices":[1],"scale":2},{"op":"crease","edges":[[0,6]],"sharpness":1}])", "f")
                  .apply(cube);
            }),
            "f: ops[1] (crease): edge 0–6 is not in the mesh");
}

TEST(OperationList, MalformedListsNameTheOperationBeforeApplyingAny) {
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {R"([{"op":"subdivide"},{"op":"extrude","faces":[1]}])", R"(f: ops[1] (extrude): "distance" is missing)"},
           {R"([{"op":"extrude","faces":[1],"distance":"far"}])",
            R"(f: ops[0] (extrude): "distance" must be a finite number)"},
           {R"([{"op":"extrude","faces":[1],"edges":[[0,1]],"distance":1}])", R"(f: ops[0] (extrude): give one of)"},
           {R"([{"op":"loop_cut","edge":[0]}])", R"(f: ops[0] (loop_cut): "edge" must give an edge as [a, b])"},
           {R"([{"op":"delete","faces":[-1]}])",
            R"(f: ops[0] (delete): "faces"[0] must be an integer from 0 to 2147483647, got -1)"},
           {R"([{"op":"merge","vertices":[0,1],"at":"middle"}])", R"(f: ops[0] (merge): "at" must be)"},
           {R"([{"op":"add","primitive":"teapot"}])", R"(f: ops[0] (add): unknown primitive 'teapot')"},
           {R"([{"op":"subdivide","levels":2}])", R"(f: ops[0] (subdivide): unknown key 'levels')"},
           {R"([{"op":"crease","edges":[[0,1]],"sharpness":-1}])",
            R"(f: ops[0] (crease): "sharpness" must be 0 or more, got -1)"},
           {R"([{"op":"corner","vertices":[0],"sharpness":-0.5}])",
            R"(f: ops[0] (corner): "sharpness" must be 0 or more, got -0.5)"},
           {R"([{"op":"transform","vertices":"all","matrix":[1,0,0,0,0,1,0,0,0,0,1,0,1,0,0,1]}])",
            "f: ops[0] (transform): the matrix's last row must be 0 0 0 1"},
           {R"([3])", R"(f: ops[0]: expected an object with "op")"},
           {R"({})", "f: expected a JSON array"},
           {R"([)", "f: not valid JSON"}}) {
    const std::string error = error_of([&, text = text] { OperationList::parse(text, "f"); });
    EXPECT_EQ(error.rfind(message, 0), 0u) << text << " gave: " << error;
  }
}

// Numbers are taken only as the type they become: nothing wraps, truncates or stops early.
TEST(OperationList, NumbersOutsideTheirTypeAreRefusedNamingTheElement) {
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {R"([{"op":"loop_cut","edge":[0,1],"cuts":4294967297}])",
            R"(f: ops[0] (loop_cut): "cuts" must be an integer from 1 to 64, got 4294967297)"},
           {R"([{"op":"loop_cut","edge":[0,1],"cuts":1000000000000000000}])",
            R"(f: ops[0] (loop_cut): "cuts" must be an integer from 1 to 64, got 1000000000000000000)"},
           {R"([{"op":"loop_cut","edge":[0,1],"cuts":1.9}])",
            R"(f: ops[0] (loop_cut): "cuts" must be an integer from 1 to 64, got 1.9)"},
           {R"([{"op":"delete","faces":[4294967296]}])",
            R"(f: ops[0] (delete): "faces"[0] must be an integer from 0 to 2147483647, got 4294967296)"},
           {R"([{"op":"bridge","loops":[[0,1],[2,1.5]]}])",
            R"(f: ops[0] (bridge): "loops[1]"[1] must be an integer from 0 to 2147483647, got 1.5)"},
           {R"([{"op":"subdivide"},{"op":"extrude","faces":[1],"distance":1e400}])",
            "f: ops[1].distance: a number beyond the range of a double"},
           {std::string("[]\0garbage", 10), "f: not valid JSON (a NUL byte at byte 3)"},
           {R"([{"op":"split_edge","edge":[0,1],"t":1}])",
            R"(f: ops[0] (split_edge): "t" must be between 0 and 1 (not either), got 1)"},
           {R"([{"op":"inset","faces":[0],"thickness":-0.3}])",
            R"(f: ops[0] (inset): "thickness" must be positive, got -0.3)"},
           {R"([{"op":"weld","distance":0}])", R"(f: ops[0] (weld): "distance" must be positive, got 0)"}}) {
    try {
      OperationList::parse(text, "f");
      ADD_FAILURE() << text << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), message) << text;
      EXPECT_EQ(e.kind(), Error::Kind::usage) << text;
    }
  }
}

// Text from the list is cut in messages as core/support/quoted_text.h documents.
TEST(OperationList, MessagesCutTheTextTheyQuote) {
  const std::string long_name(100000, 'q');
  for (const std::string& text :
       {R"([{"op":")" + long_name + R"("}])", R"([{"op":"subdivide",")" + long_name + R"(":1}])",
        R"([{"op":"add","primitive":")" + long_name + R"("}])"}) {
    const std::string error = error_of([&] { OperationList::parse(text, "f"); });
    EXPECT_LT(error.size(), 400u) << error.substr(0, 400);
    EXPECT_NE(error.find("qqq…'"), std::string::npos) << error.substr(0, 400);
  }
}

// A set that would make a Gaussian invalid says what the vertex would have, in one phrase.
TEST(OperationList, AnInvalidSetSaysWhatTheVertexWouldHave) {
  const std::string error = error_of(
      [] { OperationList::parse(R"([{"op":"set","vertices":[0],"scale":1e-200}])", "f").apply(make_sample("cube")); });
  EXPECT_EQ(error.rfind("f: ops[0] (set): vertex 0 would have a covariance eigenvalue ", 0), 0u) << error;
  EXPECT_EQ(error.find("that has"), std::string::npos) << error;
}

TEST(OperationList, RefusalNamesTheOperationAndChangesNothing) {
  const CovarianceMesh cube = make_sample("cube");
  const OperationList ops =
      OperationList::parse(R"([{"op":"extrude","faces":[0],"distance":1},{"op":"loop_cut","edge":[0,6]}])", "ops.json");
  const std::string error = error_of([&] { ops.apply(cube); });
  EXPECT_EQ(error.rfind("ops.json: ops[1] (loop_cut): ", 0), 0u) << error;
  EXPECT_EQ(cube.n_vertices(), 8u);
  EXPECT_EQ(cube.n_faces(), 6u);
}

TEST(OperationList, CreaseAndCornerOperations) {
  const CovarianceMesh cube = make_sample("cube");
  std::vector<std::string> summaries;
  const Modelled m = OperationList::parse(R"([{"op":"crease","edges":[[4,5],[6,5]],"sharpness":2.5},
                                              {"op":"corner","vertices":[7],"sharpness":10},
                                              {"op":"crease","edges":[[4,5]],"sharpness":0},
                                              {"op":"split_edge","edge":[5,6]}])",
                                          "ops.json")
                         .apply(cube, &summaries);
  Sharpness expected;
  expected.creases = {{5, 8, 2.5}, {6, 8, 2.5}};  // 5–6 split at the new vertex 8: both halves keep it
  expected.corners = {0, 0, 0, 0, 0, 0, 0, 10, 0};
  EXPECT_EQ(m.mesh.sharpness, expected);
  EXPECT_EQ(summaries[0], "set the crease of 2 edges to 2.5");
  EXPECT_EQ(summaries[1], "set the corner of 1 vertex to 10 (infinitely sharp)");

  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {R"([{"op":"crease","edges":[[4,5]]}])", R"(f: ops[0] (crease): "sharpness" is missing)"},
           {R"([{"op":"crease","edges":[],"sharpness":1}])",
            R"(f: ops[0] (crease): "edges" must be a list of [a, b] edges)"},
           {R"([{"op":"corner","vertices":[],"sharpness":1}])", R"(f: ops[0] (corner): "vertices" is empty)"},
           {R"([{"op":"corner","vertices":[1],"sharpness":"high"}])",
            R"(f: ops[0] (corner): "sharpness" must be a finite number)"},
           {R"([{"op":"crease","edges":[[0,1]],"sharpness":-2}])",
            R"(f: ops[0] (crease): "sharpness" must be 0 or more, got -2)"}}) {
    const std::string error = error_of([&, text = text] { OperationList::parse(text, "f"); });
    EXPECT_EQ(error, message) << text;
  }
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {R"([{"op":"corner","vertices":[1],"sharpness":1},{"op":"crease","edges":[[0,6]],"sharpness":1}])",
            "f: ops[1] (crease): edge 0–6 is not in the mesh"},
           {R"([{"op":"corner","vertices":[8],"sharpness":1}])",
            "f: ops[0] (corner): vertex 8 is not in the mesh (8 vertices)"}}) {
    const OperationList ops = OperationList::parse(text, "f");
    EXPECT_EQ(error_of([&] { ops.apply(cube); }), message) << text;
  }
}

// Split then grid fill: the cube's top split off, its hole in the open box filled again (the same
// calls), and their keys checked before anything is applied.
TEST(OperationList, SplitAndGridFill) {
  const CovarianceMesh cube = make_sample("cube");
  const OperationList ops = OperationList::parse(
      R"([{"op":"split","faces":[1]},{"op":"grid_fill","vertices":[7,6,5,4],"span":1,"offset":2}])", "f");
  std::vector<std::string> summaries;
  const Modelled scripted = ops.apply(cube, &summaries);
  const Modelled direct = grid_fill(split_faces(cube, {1}).mesh, {7, 6, 5, 4}, 1, 2);
  expect_same_gaussians_and_faces(scripted.mesh, direct.mesh);
  EXPECT_EQ(scripted.mesh.n_vertices(), 12u);
  EXPECT_EQ(scripted.mesh.n_faces(), 7u);
  EXPECT_EQ(summaries, (std::vector<std::string>{"split off 1 face: 4 vertices duplicated along the cut",
                                                  "grid-filled a loop of 4 vertices with 1 × 1 quads: 0 vertices added"}));
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {R"([{"op":"split","faces":[]}])", R"(f: ops[0] (split): "faces" is empty)"},
           {R"([{"op":"split"}])", R"(f: ops[0] (split): "faces" is missing)"},
           {R"([{"op":"grid_fill","vertices":[4,5,6,7],"span":0}])",
            R"(f: ops[0] (grid_fill): "span" must be an integer from 1 to 2147483647, got 0)"},
           {R"([{"op":"grid_fill","vertices":[4,5,6,7],"rails":2}])", "f: ops[0] (grid_fill): unknown key 'rails'"}}) {
    const std::string error = error_of([&, text = text] { OperationList::parse(text, "f"); });
    EXPECT_EQ(error, message) << text;
  }
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {R"([{"op":"split","faces":[0,1,2,3,4,5]}])",
            "f: ops[0] (split): every face is selected: there is nothing to split them from"},
           {R"([{"op":"split","faces":[6]}])", "f: ops[0] (split): face 6 is not in the mesh (6 faces)"},
           {R"([{"op":"delete","faces":[1]},{"op":"grid_fill","vertices":[4,5,6]}])",
            "f: ops[1] (grid_fill): a grid fill needs a loop of at least 4 vertices (3 given)"}}) {
    const OperationList list = OperationList::parse(text, "f");
    EXPECT_EQ(error_of([&] { list.apply(cube); }), message) << text;
  }
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

// A parameter next to nothing made vertices a repair would weld: a list refuses them, naming the step.
TEST(OperationList, ResultsWithNewVerticesOnTheirNeighboursAreRefused) {
  const CovarianceMesh cube = make_sample("cube");
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {R"([{"op":"inset","faces":[1],"thickness":1e-12}])",
            "f: ops[0] (inset): the result would put vertex 5 within 3.4641e-06 of new vertex 9"},
           {R"([{"op":"inset","faces":[1],"thickness":0.9999999}])",
            "f: ops[0] (inset): the result would put new vertex 8 within 3.4641e-06 of new vertex 9"},
           {R"([{"op":"split_edge","edge":[0,1],"t":1e-12}])",
            "f: ops[0] (split_edge): the result would put new vertex 8 within 3.4641e-06 of vertex 0"},
           {R"([{"op":"subdivide"},{"op":"loop_cut","edge":[0,8],"slide":0.9999999}])",
            "f: ops[1] (loop_cut): the result would put new vertex "}}) {
    const std::string& listed = text;  // clang 15 does not capture a structured binding
    const std::string why = test::error_of([&] { OperationList::parse(listed, "f").apply(cube); });
    EXPECT_EQ(why.rfind(message, 0), 0u) << text << "\n" << why;
  }
  // The same at sensible sizes are made.
  EXPECT_NO_THROW(OperationList::parse(R"([{"op":"inset","faces":[1],"thickness":0.2}])", "f").apply(cube));
  EXPECT_NO_THROW(OperationList::parse(R"([{"op":"split_edge","edge":[0,1],"t":0.01}])", "f").apply(cube));
}

}  // namespace
}  // namespace gps
