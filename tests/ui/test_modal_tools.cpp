// The bevel and slide tools without a window, through a ToolContext over a document: a typed value
// and Enter give exactly core's operation as one undo step (undone: the mesh before, exactly); Esc
// leaves the document untouched with no undo step; a refusal changes nothing; G G hands a grab over
// to the slide; the mouse's bevel width is the distance the cursor gains from the centre; in edge
// mode bevel and crease take the edges selected, not the edges between their ends.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <memory>

#include "../support/mesh_checks.h"
#include "../support/temp_dir.h"
#include "core/io/mesh_io.h"
#include "core/modelling/bevel.h"
#include "core/modelling/inset.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/mesh_arrays.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/samples.h"
#include "core/modelling/slide.h"
#include "ui/document/editor_document.h"
#include "ui/editing/selection.h"
#include "ui/tools/bevel_tool.h"
#include "ui/tools/bisect_tool.h"
#include "ui/tools/handle_drag_tool.h"
#include "ui/tools/inset_tool.h"
#include "ui/tools/sharpness_tool.h"
#include "ui/tools/slide_tool.h"
#include "ui/tools/transform_tool.h"
#include "tests/support/typed_events.h"
#include "tests/support/bevel_width.h"
#include "view/camera.h"
#include "view/projection.h"

namespace gps {
namespace {

using test::key_event;
using test::text_event;

// A document and selection with the editor's services as a ToolContext that records what it was asked.
struct Editor {
  test::TempDir dir;
  EditorDocument document;
  Selection selection;
  ReachOptions reach;
  std::shared_ptr<const CovarianceMesh> shown;  // the preview shown (nullptr: the document)
  int installed = 0;
  std::string said;  // the last report or note

  explicit Editor(const CovarianceMesh& mesh, const std::vector<int>& selected) {
    write_mesh(dir.file("mesh.ply"), mesh);
    document.open(dir.file("mesh.ply"));
    selection.select(selected, false);
  }
  ToolContext context() {
    ToolContext c(document, selection, reach);
    c.install = [this](const Modelled& result, SurfaceReplanner*) {
      document.apply(result, selection.record());
      selection.select(result.selection, false);
      shown.reset();
      ++installed;
    };
    c.operate = [this, install = c.install](const std::string& name,
                                            const std::function<Modelled(const CovarianceMesh&)>& run,
                                            SurfaceReplanner* replanner) {
      try {
        install(run(document.mesh()), replanner);
      } catch (const Error& e) {
        said = name + " refused: " + e.what();
        return false;
      }
      said = name;
      return true;
    };
    c.show_preview = [this](std::shared_ptr<const CovarianceMesh> mesh, const std::vector<int>&,
                            std::optional<ReplannedTables>) { shown = std::move(mesh); };
    c.show_document = [this](std::optional<ReplannedTables>) { shown.reset(); };
    c.rebuild = [](const SelectionRecord&) {};
    c.report = c.note = c.show_status = [this](const std::string& message, bool) { said = message; };
    return c;
  }
  ToolResult send(ModalTool& tool, const InputEvent& e) {
    ToolContext c = context();
    return tool.handle(e, c);
  }
  void type(ModalTool& tool, const std::string& typed) {
    for (const char ch : typed) EXPECT_EQ(send(tool, text_event(ch)), ToolResult::consumed);
  }
};

CovarianceMesh cube() { return make_sample("cube"); }

// The vertices sharing an edge with v (in edge order).
std::vector<int> neighbours(const CovarianceMesh& m, int v) {
  const MeshConnectivity& c = m.connectivity();
  std::vector<int> out;
  for (int k = c.vertex_edge_offsets[size_t(v)]; k < c.vertex_edge_offsets[size_t(v) + 1]; ++k)
    out.push_back(c.other_vertex(c.vertex_edges[size_t(k)], v));
  return out;
}

using test::width;

TEST(BevelTool, TypedWidthAndEnterIsCoresBevelAsOneUndoStep) {
  Editor editor(cube(), {6, 7});
  ToolContext c = editor.context();
  const auto tool = BevelTool::start(c, false);
  ASSERT_TRUE(tool);
  EXPECT_FALSE(editor.shown);  // width 0: the mesh before
  editor.type(*tool, "0.25");
  ASSERT_TRUE(editor.shown);
  const Modelled expected = bevel_edges(cube(), {{6, 7}}, width(0.25));
  EXPECT_TRUE(test::same_mesh(*editor.shown, expected.mesh));
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), cube())) << "a preview leaves the document";
  EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  EXPECT_EQ(editor.installed, 1);
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), expected.mesh));
  EXPECT_EQ(editor.selection.vertices(), expected.selection);
  editor.document.undo();
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), cube()));
  EXPECT_FALSE(editor.document.can_undo());
}

TEST(BevelTool, TheWheelSetsTheSegmentsRecomputedFromTheMeshBefore) {
  Editor editor(cube(), {6, 7});
  ToolContext c = editor.context();
  const auto tool = BevelTool::start(c, false);
  editor.type(*tool, "0.25");
  InputEvent wheel;
  wheel.type = InputEvent::Type::scroll;
  wheel.steps = 1.0f;
  EXPECT_EQ(editor.send(*tool, wheel), ToolResult::consumed);
  EXPECT_EQ(editor.send(*tool, wheel), ToolResult::consumed);
  EXPECT_TRUE(test::same_mesh(*editor.shown, bevel_edges(cube(), {{6, 7}}, width(0.25, 3)).mesh));
  wheel.steps = -1.0f;
  EXPECT_EQ(editor.send(*tool, wheel), ToolResult::consumed);
  EXPECT_TRUE(test::same_mesh(*editor.shown, bevel_edges(cube(), {{6, 7}}, width(0.25, 2)).mesh));
}

TEST(BevelTool, EscapeLeavesTheDocumentWithoutAnUndoStep) {
  Editor editor(cube(), {6, 7});
  ToolContext c = editor.context();
  const auto tool = BevelTool::start(c, false);
  editor.type(*tool, "0.25");
  EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_ESCAPE)), ToolResult::cancelled);
  EXPECT_FALSE(editor.shown);
  EXPECT_EQ(editor.installed, 0);
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), cube()));
  EXPECT_FALSE(editor.document.can_undo());
  EXPECT_FALSE(editor.document.dirty());
}

// I with a typed thickness and Enter: core's inset of the selected face, one undo step; a thickness
// core refuses is shown, and Enter then says why nothing was done.
TEST(InsetTool, TypedThicknessAndEnterIsCoresInset) {
  Editor editor(cube(), {4, 5, 6, 7});
  ToolContext c = editor.context();
  const std::vector<int> faces = faces_within(cube(), {4, 5, 6, 7});
  ASSERT_EQ(faces.size(), 1u);
  auto tool = InsetTool::start(c);
  ASSERT_TRUE(tool);
  editor.type(*tool, "0.02");
  EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), inset_faces(cube(), faces, 0.02).mesh)) << editor.said;
  Editor refused(cube(), {4, 5, 6, 7});
  ToolContext r = refused.context();
  tool = InsetTool::start(r);
  refused.type(*tool, "5");
  EXPECT_TRUE(tool->error());
  EXPECT_EQ(refused.send(*tool, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  EXPECT_EQ(refused.installed, 0);
  EXPECT_EQ(refused.said.find("move toward the centre"), std::string::npos) << refused.said;
  EXPECT_NE(refused.said.find("inset"), std::string::npos) << refused.said;
}

TEST(BevelTool, ARefusalIsShownAndConfirmingItChangesNothing) {
  Editor editor(cube(), {6, 7});
  ToolContext c = editor.context();
  const auto tool = BevelTool::start(c, false);
  editor.type(*tool, "0.25");
  EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_P)), ToolResult::consumed);  // the straight profile
  BevelOptions straight = width(0.25);
  straight.profile = 0.25;
  EXPECT_TRUE(test::same_mesh(*editor.shown, bevel_edges(cube(), {{6, 7}}, straight).mesh));
  // A vertex on no face (added to a grid): core refuses it, whatever the width.
  MeshArrays arrays = arrays_of(make_sample("grid", 16));
  const int loose = arrays.add_vertex({Vec3(0, 0, 5), Mat3::Identity()});
  const CovarianceMesh plane = build_mesh(arrays);
  Editor flat(plane, {loose});
  ToolContext f = flat.context();
  const auto refused = BevelTool::start(f, true);
  ASSERT_TRUE(refused);
  flat.type(*refused, "0.1");
  EXPECT_TRUE(refused->error());
  EXPECT_FALSE(flat.shown);
  EXPECT_EQ(flat.send(*refused, key_event(GLFW_KEY_ENTER)), ToolResult::cancelled);
  EXPECT_EQ(flat.installed, 0);
  EXPECT_TRUE(test::same_mesh(flat.document.mesh(), plane));
  EXPECT_NE(flat.said.find("nothing done"), std::string::npos) << flat.said;
}

TEST(BevelTool, NoEdgeSelectedIsRefusedAtOnce) {
  Editor editor(cube(), {6});
  ToolContext c = editor.context();
  EXPECT_FALSE(BevelTool::start(c, false));
  EXPECT_NE(editor.said.find("bevel refused"), std::string::npos) << editor.said;
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), cube()));
}

// In edge mode the tools take the edges selected, not every edge between their ends: two opposite
// edges of the cube's face {0, 1, 5, 4}, whose ends are the whole face.
TEST(BevelTool, EdgeModeBevelsTheSelectedEdgesOnly) {
  Editor editor(cube(), {});
  editor.selection.select_edges(cube(), {{0, 1}, {4, 5}}, false);
  ToolContext c = editor.context();
  const auto tool = BevelTool::start(c, false);
  ASSERT_TRUE(tool);
  editor.type(*tool, "0.25");
  EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), bevel_edges(cube(), {{0, 1}, {4, 5}}, width(0.25)).mesh));
  EXPECT_FALSE(test::same_mesh(editor.document.mesh(),
                               bevel_edges(cube(), edges_within(cube(), {0, 1, 4, 5}), width(0.25)).mesh));
}

TEST(SharpnessTool, EdgeModeCreasesTheSelectedEdgesOnlyAndKeepsThem) {
  Editor editor(cube(), {});
  editor.selection.select_edges(cube(), {{0, 1}, {4, 5}}, false);
  ToolContext c = editor.context();
  const auto tool = SharpnessTool::start(c, false);
  ASSERT_TRUE(tool);
  editor.type(*tool, "10");
  EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  const std::vector<EdgeCrease> expected = {{0, 1, kInfiniteSharpness}, {4, 5, kInfiniteSharpness}};
  EXPECT_EQ(editor.document.mesh().sharpness.creases, expected);
  EXPECT_TRUE(editor.selection.holds_edges());  // the edges stay selected as edges
  EXPECT_EQ(editor.selection.edges(editor.document.mesh()), (std::vector<EdgeEnds>{{0, 1}, {4, 5}}));
}

TEST(BevelTool, TheMouseWidthIsTheDistanceGainedFromTheCentre) {
  const glm::vec2 centre(100.0f, 100.0f), start(130.0f, 140.0f);  // 50 pixels from the centre
  EXPECT_DOUBLE_EQ(BevelTool::width_from_cursor(start, glm::vec2(160.0f, 180.0f), centre, 0.01), 0.5);
  EXPECT_EQ(BevelTool::width_from_cursor(start, glm::vec2(110.0f, 100.0f), centre, 0.01), 0.0);  // nearer: none
  EXPECT_EQ(BevelTool::width_from_cursor(start, start, centre, 0.01), 0.0);
}

// A cube cut once across its vertical edges, and its middle loop.
struct CutCube {
  CovarianceMesh mesh;
  std::vector<int> loop;
  CutCube() {
    const CovarianceMesh c = cube();
    std::array<int, 2> vertical{-1, -1};
    for (size_t e = 0; e < c.n_edges(); ++e)
      if (c.mean(size_t(c.edge(e)[0])).y() != c.mean(size_t(c.edge(e)[1])).y()) vertical = c.edge(e);
    const Modelled cut = loop_cut(c, vertical[0], vertical[1], 1);
    mesh = cut.mesh;
    loop = cut.selection;
  }
};

TEST(SlideTool, TypedFactorIsCoresEdgeSlideAsOneUndoStep) {
  const CutCube cut;
  ASSERT_EQ(cut.loop.size(), 4u);
  Editor editor(cut.mesh, cut.loop);
  ToolContext c = editor.context();
  const auto tool = SlideTool::start(c);
  ASSERT_TRUE(tool);
  editor.type(*tool, "-0.5");
  EXPECT_FALSE(tool->error()) << tool->status();
  EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  const CovarianceMesh expected = edge_slide(cut.mesh, edges_within(cut.mesh, cut.loop), -0.5).mesh;
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), expected));
  editor.document.undo();
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), cut.mesh));
  EXPECT_FALSE(editor.document.can_undo());
}

TEST(SlideTool, AFactorOutOfRangeIsShownAndEscapeRestores) {
  const CutCube cut;
  Editor editor(cut.mesh, cut.loop);
  ToolContext c = editor.context();
  const auto tool = SlideTool::start(c);
  editor.type(*tool, "0.5");
  EXPECT_FALSE(test::same_mesh(editor.document.mesh(), cut.mesh));
  for (int k = 0; k < 3; ++k) EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_BACKSPACE)), ToolResult::consumed);
  editor.type(*tool, "2");  // |factor| > 1: refused, the mesh before shown
  EXPECT_TRUE(tool->error()) << tool->status();
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), cut.mesh));
  EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_ESCAPE)), ToolResult::cancelled);
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), cut.mesh));
  EXPECT_FALSE(editor.document.can_undo());
}

TEST(SlideTool, OneVertexSlidesAlongAnEdge) {
  const CovarianceMesh before = cube();
  Editor editor(before, {6});
  ToolContext c = editor.context();
  const auto tool = SlideTool::start(c);
  ASSERT_TRUE(tool);
  editor.type(*tool, "1");  // all the way: onto a neighbour's Gaussian
  EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  const CovarianceMesh& slid = editor.document.mesh();
  int landed = -1;
  for (const int u : neighbours(before, 6))
    if (slid.mean(6) == before.mean(size_t(u))) landed = u;
  EXPECT_GE(landed, 0);
  for (size_t v = 0; v < slid.n_vertices(); ++v) {
    if (v == 6) continue;
    EXPECT_EQ(slid.mean(v), before.mean(v)) << v;
  }
}

// The cursor moved halfway to a neighbour's pixel: the vertex halfway along that edge (the cube's
// Gaussians are equal, so the 9D path is the straight edge).
TEST(SlideTool, OneVertexFollowsTheMouseTowardTheNeighbourItMovesTo) {
  const CovarianceMesh before = cube();
  Viewport view;  // the default camera, which sees the whole cube
  view.width = 800;
  view.height = 600;
  const auto pixel = [&](int v) {
    return glm::vec2(*project_to_pixel(view.camera, view.width, view.height, before.mean(size_t(v))));
  };
  for (const int u : neighbours(before, 6)) {
    Editor editor(before, {6});
    ToolContext c = editor.context();
    c.viewport = view;
    c.cursor = pixel(6);
    const auto tool = SlideTool::start(c);
    ASSERT_TRUE(tool);
    InputEvent move;
    move.position = pixel(6) + 0.5f * (pixel(u) - pixel(6));
    ToolContext m = editor.context();
    m.viewport = view;
    EXPECT_EQ(tool->handle(move, m), ToolResult::consumed);
    EXPECT_EQ(editor.send(*tool, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
    const Vec3 midpoint = 0.5 * (before.mean(6) + before.mean(size_t(u)));
    EXPECT_NEAR((editor.document.mesh().mean(6) - midpoint).norm(), 0.0, 1e-3) << "toward " << u;
  }
}

TEST(SlideTool, GPressedAgainDuringAGrabSlides) {
  const CutCube cut;
  Editor editor(cut.mesh, cut.loop);
  ToolContext c = editor.context();
  TransformTool grab(TransformKind::grab, TransformPivot::median, c);
  ToolContext again = editor.context();
  EXPECT_EQ(grab.handle(key_event(GLFW_KEY_G), again), ToolResult::replaced);
  ASSERT_TRUE(again.next);
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), cut.mesh)) << "the grab undone";
  editor.type(*again.next, "0.5");
  EXPECT_EQ(editor.send(*again.next, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  EXPECT_TRUE(
      test::same_mesh(editor.document.mesh(), edge_slide(cut.mesh, edges_within(cut.mesh, cut.loop), 0.5).mesh));
}

// A typed scale past what a covariance mesh holds (1e300: coordinates beyond ±1e100) is refused when
// confirmed, saying why, the mesh as it was; a typed exponent is read as one (1e2 is 100, not 12).
TEST(TransformTool, AScalePastTheMeshsRangeIsRefusedAndAnExponentIsRead) {
  Editor editor(cube(), {0, 1, 2, 3, 4, 5, 6, 7});
  {
    ToolContext c = editor.context();
    TransformTool scale(TransformKind::scale, TransformPivot::median, c);
    editor.type(scale, "1e300");
    EXPECT_EQ(editor.send(scale, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  }
  EXPECT_EQ(editor.said.rfind("transform refused: vertex 0 would have a coordinate 1e+300 beyond ±1e+100", 0), 0u)
      << editor.said;
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), cube()));
  ToolContext c = editor.context();
  TransformTool scale(TransformKind::scale, TransformPivot::median, c);
  editor.type(scale, "1e2");
  EXPECT_EQ(editor.send(scale, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  EXPECT_NEAR(editor.document.mesh().mean(0).norm(), 100.0 * cube().mean(0).norm(), 1e-9);
}

// S Z 0 flattens the cube's vertices and holds their Gaussians at the flatness floor: what is reported
// on Enter still counts them (it was cut off with the status line's other parts).
TEST(TransformTool, AFlatteningScaleReportsTheGaussiansHeld) {
  Editor editor(cube(), {0, 1, 2, 3, 4, 5, 6, 7});
  ToolContext c = editor.context();
  TransformTool scale(TransformKind::scale, TransformPivot::median, c);
  editor.send(scale, key_event(GLFW_KEY_Z));
  editor.type(scale, "0");
  EXPECT_EQ(editor.send(scale, key_event(GLFW_KEY_ENTER)), ToolResult::confirmed);
  EXPECT_NE(editor.said.find("(8 Gaussians held at the flatness floor)"), std::string::npos) << editor.said;
}

InputEvent mouse_event(InputEvent::Type type, glm::vec2 at) {
  InputEvent e;
  e.type = type;
  e.position = at;
  return e;
}

// A line dragged across the middle of the view bisects the cube by the plane through the eye and the
// cube's centre (it crosses the four sides: Blender's 12 vertices and 10 faces) as one undo step; a
// drag of a few pixels cuts nothing; Esc leaves the mesh.
TEST(BisectTool, ALineAcrossTheViewCutsByThePlaneSeenAlongIt) {
  Editor editor(cube(), {});
  ToolContext c = editor.context();
  c.viewport.camera = frame_mesh(cube(), 30.0f, 20.0f);
  c.viewport.width = 640;
  c.viewport.height = 480;
  const auto plane = BisectTool::plane_through(c.viewport, {100.0f, 239.5f}, {540.0f, 239.5f});
  ASSERT_TRUE(plane);
  const Vec3 eye = to_vec(c.viewport.camera.eye_double()), target = to_vec(c.viewport.camera.target);
  EXPECT_LT(std::abs(plane->normal.dot(eye - plane->point)), 1e-9);
  EXPECT_LT(std::abs(plane->normal.dot(target - plane->point)), 1e-6);
  EXPECT_FALSE(BisectTool::plane_through(c.viewport, {100.0f, 240.0f}, {102.0f, 240.0f}));

  BisectTool tool(c);
  EXPECT_EQ(tool.handle(mouse_event(InputEvent::Type::press, {320.0f, 240.0f}), c), ToolResult::consumed);
  EXPECT_EQ(tool.handle(mouse_event(InputEvent::Type::release, {321.0f, 240.0f}), c), ToolResult::consumed);
  EXPECT_EQ(editor.installed, 0);
  EXPECT_EQ(tool.handle(mouse_event(InputEvent::Type::press, {100.0f, 239.5f}), c), ToolResult::consumed);
  EXPECT_EQ(tool.handle(mouse_event(InputEvent::Type::move, {320.0f, 239.5f}), c), ToolResult::consumed);
  EXPECT_EQ(tool.handle(mouse_event(InputEvent::Type::release, {540.0f, 239.5f}), c), ToolResult::confirmed);
  EXPECT_EQ(editor.installed, 1);
  const test::Shape shape = test::shape_of(editor.document.mesh());
  EXPECT_EQ(shape.vertices, 12);
  EXPECT_EQ(shape.faces, 10);
  EXPECT_EQ(shape.boundary_edges, 0);
  EXPECT_TRUE(shape.oriented);

  BisectTool cancelled(c);
  EXPECT_EQ(cancelled.handle(key_event(GLFW_KEY_ESCAPE), c), ToolResult::cancelled);
  EXPECT_EQ(editor.installed, 1);
}

// The gizmo's drag as a tool: on its centre, X and a typed 0.5 move the selected vertex along x by
// exactly 0.5 (its covariance kept), Enter keeps it as one undo step; its gizmo is the drag's, the
// centre lit.
TEST(HandleDragTool, ATypedMoveAlongAnAxisIsOneUndoStep) {
  Editor editor(cube(), {6});
  ToolContext c = editor.context();
  c.viewport.camera = frame_mesh(cube(), 30.0f, 20.0f);
  c.viewport.width = 640;
  c.viewport.height = 480;
  const auto at = project_to_pixel(c.viewport.camera, 640, 480, cube().mean(6));
  ASSERT_TRUE(at);
  c.cursor = glm::vec2(*at);
  const Handle centre{6, -1, 1};
  const auto tool = HandleDragTool::start(c, centre, 2.0, c.cursor, false, cube().mean(6));
  ASSERT_TRUE(tool);
  EXPECT_EQ(tool->reached(), 1u);
  const auto gizmo = tool->gizmo(c.viewport);
  ASSERT_TRUE(gizmo);
  EXPECT_TRUE(gizmo->lit.is_centre());
  EXPECT_EQ(tool->handle(key_event(GLFW_KEY_X), c), ToolResult::consumed);
  for (const char ch : std::string("0.5")) EXPECT_EQ(tool->handle(text_event(ch), c), ToolResult::consumed);
  EXPECT_EQ(tool->handle(key_event(GLFW_KEY_ENTER), c), ToolResult::confirmed);
  EXPECT_EQ(editor.document.mesh().mean(6), cube().mean(6) + Vec3(0.5, 0, 0));
  EXPECT_EQ(editor.document.mesh().covariance(6), cube().covariance(6));
  for (size_t v = 0; v < 6; ++v) EXPECT_EQ(editor.document.mesh().mean(v), cube().mean(v)) << v;
  editor.document.undo();
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), cube()));
  EXPECT_FALSE(editor.document.can_undo());
}

// With proportional editing the wheel widens the reach from the drag's start; a key that is not the
// drag's reaches the commands; Esc restores every vertex with no undo step.
TEST(HandleDragTool, TheWheelWidensTheReachAndEscapeRestores) {
  const CovarianceMesh grid = make_sample("grid");
  Editor editor(grid, {0});
  editor.reach.proportional = true;
  editor.reach.radius = 1e-3;
  ToolContext c = editor.context();
  c.viewport.camera = frame_mesh(grid, 30.0f, 20.0f);
  c.viewport.width = 640;
  c.viewport.height = 480;
  c.cursor = glm::vec2(*project_to_pixel(c.viewport.camera, 640, 480, grid.mean(0)));
  const auto tool = HandleDragTool::start(c, Handle{0, -1, 1}, 2.0, c.cursor, false, grid.mean(0));
  EXPECT_EQ(tool->reached(), 1u);
  InputEvent wheel;
  wheel.type = InputEvent::Type::scroll;
  wheel.steps = 60.0f;  // 1.15^60: some thousand times wider
  EXPECT_EQ(tool->handle(wheel, c), ToolResult::consumed);
  EXPECT_GT(tool->reached(), 1u);
  EXPECT_GT(editor.reach.radius, 1.0);
  c.cursor += glm::vec2(0.0f, -40.0f);
  EXPECT_EQ(tool->handle(mouse_event(InputEvent::Type::move, c.cursor), c), ToolResult::consumed);
  EXPECT_NE(editor.document.mesh().mean(0), grid.mean(0));
  EXPECT_EQ(tool->handle(key_event(GLFW_KEY_F), c), ToolResult::passed_on);
  EXPECT_EQ(tool->handle(key_event(GLFW_KEY_ESCAPE), c), ToolResult::cancelled);
  EXPECT_TRUE(test::same_mesh(editor.document.mesh(), grid));
  EXPECT_FALSE(editor.document.can_undo());
}

}  // namespace
}  // namespace gps
