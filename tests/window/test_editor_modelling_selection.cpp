// Blender's edit-mode selection in the editor, in a real window under Xvfb: boxes that take only the
// vertices the camera sees (and all of them with X-ray), Ctrl+box subtracting; edge and face mode
// clicks; an Alt+click edge loop; L and Ctrl+I; and two drags that used to be lost (a release in the
// frame of the last motion, the centre dot in an orthographic axis view). Each selection is read
// back by moving it: a typed move of 0.25 along y moves exactly the selected vertices.
// Screenshots kept in build/test-artefacts/EditorModellingSelection/.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <filesystem>
#include <set>

#include "../support/editor_driver.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "core/modelling/mesh_queries.h"
#include "render/image/image_io.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/test_meshes.h"
#include "view/visible_vertices.h"

namespace gps {
namespace {

using test::artefact;
using test::editor_view;
using test::Events;
using test::pixel_of;

constexpr int kWidth = test::kWindowWidth, kHeight = test::kWindowHeight;
constexpr double kMove = 0.25;

class EditorModellingSelection : public ::testing::Test {
protected:
  void use_mesh(const CovarianceMesh& mesh) {
    write_mesh(dir_.file("original.ply"), mesh);
    original_ = read_mesh(dir_.file("original.ply"));
    view_ = editor_view(original_);
  }
  void SetUp() override {  // the gizmo at the selection's centroid
    std::filesystem::create_directories(dir_.path() / "gpsurf");
    dir_.write("gpsurf/settings.json", R"({"pivot": 1})");
  }
  // Grabs the gizmo's centre dot, at the centroid of `selected` (what the events should have
  // selected), and types a move of kMove along y.
  Events& move_selection(Events& events, const std::vector<int>& selected) const {
    Vec3 centroid = Vec3::Zero();
    for (const int v : selected) centroid += original_.mean(size_t(v)) / double(selected.size());
    const glm::vec2 centre = pixel_of(view_, centroid);
    return events.press(centre)
        .move(centre + glm::vec2(5.0f, 5.0f))
        .key("y")
        .text("0.25")
        .key("enter")
        .release(centre + glm::vec2(5.0f, 5.0f))
        .wait();
  }
  // Plays the events, saves (and keeps a screenshot when named); returns the saved mesh.
  CovarianceMesh play(const Events& events, const std::string& screenshot = "") const {
    const std::string extra =
        "--save " + dir_.file("edited.ply") + (screenshot.empty() ? "" : " --screenshot " + artefact(screenshot));
    const auto r = test::play_editor(dir_, dir_.file("original.ply"), events, kWidth, kHeight, extra);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_mesh(dir_.file("edited.ply"));
  }
  // The vertices the typed move moved; every other vertex must be unchanged.
  std::vector<int> moved(const CovarianceMesh& edited) const {
    std::vector<int> out;
    for (size_t v = 0; v < edited.n_vertices(); ++v) {
      const Vec3 d = edited.mean(v) - original_.mean(v);
      if (d.norm() == 0.0) continue;
      EXPECT_NEAR(d.y(), kMove, 1e-6) << "vertex " << v;
      EXPECT_NEAR(d.x(), 0.0, 1e-6) << "vertex " << v;
      EXPECT_NEAR(d.z(), 0.0, 1e-6) << "vertex " << v;
      out.push_back(int(v));
    }
    return out;
  }
  // A box around the whole mesh on screen, `margin` pixels wider.
  std::pair<glm::vec2, glm::vec2> box_around_mesh(float margin = 12.0f) const {
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (size_t v = 0; v < original_.n_vertices(); ++v) {
      lo = glm::min(lo, pixel_of(view_, original_.mean(v)));
      hi = glm::max(hi, pixel_of(view_, original_.mean(v)));
    }
    return {lo - margin, hi + margin};
  }
  test::TempDir dir_;
  CovarianceMesh original_;
  Viewport view_;
};

std::vector<int> all_but(size_t n, int left_out) {
  std::vector<int> out;
  for (int v = 0; v < int(n); ++v)
    if (v != left_out) out.push_back(v);
  return out;
}

// The default camera looks at the cube from +x, +y, +z: a box around it selects the seven corners
// it sees and not (−1, −1, −1) behind it; with Select through (Alt+Z) all eight.
TEST_F(EditorModellingSelection, ABoxSelectsOnlyTheVerticesTheCameraSees) {
  use_mesh(make_sample("cube"));
  const auto [lo, hi] = box_around_mesh();
  Events visible_only;
  visible_only.drag(glm::vec2(lo.x, hi.y), glm::vec2(hi.x, lo.y), 8).wait();
  Events shot = visible_only;
  play(shot.wait(), "box_visible_only.png");
  EXPECT_EQ(moved(play(move_selection(visible_only, all_but(8, 0)))), all_but(8, 0));

  Events xray;
  xray.key("alt+z").drag(glm::vec2(lo.x, hi.y), glm::vec2(hi.x, lo.y), 8).wait();
  EXPECT_EQ(moved(play(move_selection(xray, all_but(8, -1)))), all_but(8, -1));
}

// On the sphere the box takes the front half: every vertex one of whose faces clearly faces the
// camera, none all of whose faces clearly face away. Ctrl+box then removes the left half of it.
TEST_F(EditorModellingSelection, OnTheSphereABoxTakesTheFrontHalfAndCtrlBoxSubtracts) {
  use_mesh(make_sample("sphere", 384));
  const auto [lo, hi] = box_around_mesh();
  const std::vector<char> visible = visible_vertices(view_, original_);
  std::vector<int> seen;
  for (size_t v = 0; v < visible.size(); ++v)
    if (visible[v]) seen.push_back(int(v));
  Events box;
  box.drag(glm::vec2(lo.x, hi.y), glm::vec2(hi.x, lo.y), 8).wait();
  Events shot = box;
  play(shot.key("3").wait(), "sphere_box_face_mode.png");
  const std::vector<int> selected = moved(play(move_selection(box, seen)));

  const Vec3 eye = to_vec(view_.camera.eye());
  std::vector<double> facing(original_.n_vertices(), -1.0);
  for (size_t f = 0; f < original_.n_faces(); ++f) {
    std::vector<Vec3> p;
    for (const int v : original_.face(f)) p.push_back(original_.mean(size_t(v)));
    Vec3 normal = Vec3::Zero(), centre = Vec3::Zero();
    for (size_t k = 0; k < p.size(); ++k) normal += p[k].cross(p[(k + 1) % p.size()]), centre += p[k];
    const double cosine = normal.normalized().dot((eye - centre / double(p.size())).normalized());
    for (const int v : original_.face(f)) facing[size_t(v)] = std::max(facing[size_t(v)], cosine);
  }
  const std::set<int> in(selected.begin(), selected.end());
  for (size_t v = 0; v < original_.n_vertices(); ++v) {
    if (facing[v] > 0.1) {
      EXPECT_TRUE(in.count(int(v))) << "front vertex " << v << " not selected";
    }
    if (facing[v] < -0.1) {
      EXPECT_FALSE(in.count(int(v))) << "back vertex " << v << " selected";
    }
  }
  EXPECT_GT(selected.size(), original_.n_vertices() / 4);
  EXPECT_LT(selected.size(), original_.n_vertices() * 3 / 4);

  // Ctrl+box over the left half of the sphere: the front vertices left of the middle leave the
  // selection.
  const float middle = 0.5f * (lo.x + hi.x);
  Events subtract;
  subtract.drag(glm::vec2(lo.x, hi.y), glm::vec2(hi.x, lo.y), 8)
      .wait()
      .drag(glm::vec2(lo.x, hi.y), glm::vec2(middle, lo.y), 8, "ctrl")
      .wait();
  std::vector<int> expected;
  for (const int v : selected)
    if (pixel_of(view_, original_.mean(size_t(v))).x > middle + 0.5f) expected.push_back(v);
  ASSERT_FALSE(expected.empty());
  Events subtracted = subtract;
  play(subtracted.wait(), "sphere_ctrl_box.png");
  EXPECT_EQ(moved(play(move_selection(subtract, expected))), expected);
}

// Edge mode (2): a click beside the middle of a front edge selects its two ends. Face mode (3): a
// click inside a front face selects its four corners; Shift+click on a second face adds it.
TEST_F(EditorModellingSelection, EdgeAndFaceModeClicks) {
  use_mesh(make_sample("cube"));
  // The edge 6–7 (top, front: +y, +z) and the faces +z {4, 5, 6, 7} and +y {2, 3, 7, 6} (+x lies
  // under the Inspector).
  const glm::vec2 edge_mid = pixel_of(view_, 0.5 * (original_.mean(6) + original_.mean(7)));
  Events edge;
  edge.key("2").click(edge_mid + glm::vec2(1.0f, 3.0f)).wait();
  Events edge_shot = edge;
  play(edge_shot.wait(), "edge_mode.png");
  EXPECT_EQ(moved(play(move_selection(edge, {6, 7}))), (std::vector<int>{6, 7}));

  const auto centre_of = [this](std::vector<int> corners) {
    Vec3 c = Vec3::Zero();
    for (const int v : corners) c += original_.mean(size_t(v)) / double(corners.size());
    return pixel_of(view_, c);
  };
  Events face;
  face.key("3").click(centre_of({4, 5, 6, 7})).wait();
  Events one_face = face;
  play(one_face.wait(), "face_mode.png");
  EXPECT_EQ(moved(play(move_selection(one_face, {4, 5, 6, 7}))), (std::vector<int>{4, 5, 6, 7}));
  face.click(centre_of({2, 3, 7, 6}), "shift").wait();
  Events two_faces = face;
  play(two_faces.wait(), "face_mode_two_faces.png");
  const std::vector<int> both{2, 3, 4, 5, 6, 7};
  EXPECT_EQ(moved(play(move_selection(face, both))), both);
}

// Face mode holds faces: clicking the eight faces around the centre of a 3×3 grid selects those eight,
// not the centre face whose corners are all theirs. E then extrudes the ring alone (16 side quads; from
// its vertices it would be all nine faces, 12 sides), and the centre face stays where it was.
TEST_F(EditorModellingSelection, FaceModeSelectsTheFacesClickedNotTheFaceTheyEnclose) {
  use_mesh(test::grid_mesh(3, 3, 0.3, true));
  const auto centre_of = [this](int face) {
    Vec3 c = Vec3::Zero();
    int n = 0;
    for (const int v : original_.face(size_t(face))) c += original_.mean(size_t(v)), ++n;
    return pixel_of(view_, c / double(n));
  };
  Events ring;
  ring.key("3").click(centre_of(0)).wait();
  for (const int f : {1, 2, 3, 5, 6, 7, 8}) ring.click(centre_of(f), "shift").wait();
  Events selected = ring;
  play(selected.wait(), "face_mode_ring.png");
  ring.key("e").text("0.5").key("enter").wait();
  const CovarianceMesh extruded = play(ring, "face_mode_ring_extruded.png");
  EXPECT_EQ(extruded.n_faces(), 9u + 16u) << "the ring extruded alone";
  for (const int v : extruded.face(4)) EXPECT_EQ(extruded.mean(size_t(v)).z(), 0.0);
}

// H in face mode hides the face clicked: its patch leaves the frame, so the background shows through
// the flat grid there; Alt+H shows it again. Hiding is a view state: the saved mesh is the file's.
TEST_F(EditorModellingSelection, HHidesTheClickedFaceFromTheFrameAndAltHShowsItAgain) {
  use_mesh(test::grid_mesh(3, 3, 0.3, true));
  Vec3 c = Vec3::Zero();
  for (const int v : original_.face(4)) c += original_.mean(size_t(v)) / 4.0;
  const glm::vec2 centre = pixel_of(view_, c);
  Events shown;
  shown.key("3").wait();
  play(shown, "hide_shown.png");
  Events hidden = shown;
  hidden.click(centre).wait().key("h").wait(3);
  EXPECT_TRUE(test::same_mesh(play(hidden, "hide_hidden.png"), original_));
  Events revealed = hidden;
  revealed.key("alt+h").wait(3);
  play(revealed, "hide_revealed.png");
  // Pixels of a 15 × 15 box at the face's centre that differ between two screenshots.
  const auto differing = [&](const std::string& a, const std::string& b) {
    const Image x = read_image(artefact(a)), y = read_image(artefact(b));
    int n = 0;
    for (int dy = -7; dy <= 7; ++dy)
      for (int dx = -7; dx <= 7; ++dx) {
        const int px = int(centre.x) + dx, py = int(centre.y) + dy;
        float d = 0.0f;
        for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(x.at(px, py, k) - y.at(px, py, k)));
        n += d > 0.1f;
      }
    return n;
  };
  EXPECT_GT(differing("hide_shown.png", "hide_hidden.png"), 200) << "the hidden face's patch is still drawn";
  EXPECT_GT(differing("hide_hidden.png", "hide_revealed.png"), 200) << "Alt+H did not draw it again";
}

// In face mode Ctrl+click selects the shortest path of faces from the face clicked last, and
// Ctrl+Alt+click on an edge the loop of faces across it (as Blender's edge ring selects there). E then
// extrudes exactly the path's 7 faces; Y splits off exactly the cylinder's lower band of 8 quads, not
// the bottom cap whose corners the band's edges hold all of (16 rim vertices are doubled, not 8).
TEST_F(EditorModellingSelection, FaceModeCtrlClickSelectsAPathOfFacesAndCtrlAltClickABand) {
  use_mesh(test::grid_mesh(4, 4, 0.3, true));
  const auto centre_of = [this](int face) {
    Vec3 c = Vec3::Zero();
    int n = 0;
    for (const int v : original_.face(size_t(face))) c += original_.mean(size_t(v)), ++n;
    return pixel_of(view_, c / double(n));
  };
  int lifted = 0;  // faces whose corners all rose
  Events path;
  path.key("3").click(centre_of(0)).wait().click(centre_of(15), "ctrl").wait();
  Events path_shot = path;
  play(path_shot.wait(), "face_mode_path.png");
  path.key("e").text("0.5").key("enter").wait();
  const CovarianceMesh extruded = play(path, "face_mode_path_extruded.png");
  for (size_t f = 0; f < extruded.n_faces(); ++f) {
    bool up = true;
    for (const int v : extruded.face(f)) up = up && extruded.mean(size_t(v)).z() == 0.5;
    lifted += up;
  }
  EXPECT_EQ(lifted, 7);

  use_mesh(make_sample("cylinder"));  // rings of 8 at y = −1, 0, 1 (vertices 0–7, 8–15, 16–23), two octagons
  int front = 0;                      // the lower band's vertical edge nearest the camera
  for (int v = 1; v < 8; ++v)
    if ((original_.mean(size_t(v)) - to_vec(view_.camera.eye())).norm() <
        (original_.mean(size_t(front)) - to_vec(view_.camera.eye())).norm())
      front = v;
  Events band;
  band.key("3").click(pixel_of(view_, 0.5 * (original_.mean(size_t(front)) + original_.mean(size_t(front + 8)))),
                      "ctrl+alt");
  Events band_shot = band;
  play(band_shot.wait(), "face_mode_band.png");
  band.wait().key("y").wait();
  const CovarianceMesh split = play(band, "face_mode_band_split.png");
  EXPECT_EQ(split.n_faces(), original_.n_faces());
  EXPECT_EQ(split.n_vertices(), original_.n_vertices() + 16);
}

// Alt+click on an edge of the sphere's front, away from its eight poles, selects the whole edge
// loop through it (round the back too).
TEST_F(EditorModellingSelection, AltClickSelectsTheEdgeLoop) {
  use_mesh(make_sample("sphere", 384));
  const std::vector<char> visible = visible_vertices(view_, original_);
  // The visible edge nearest the window's centre whose ends both have valence 4.
  std::array<int, 2> edge{-1, -1};
  float best = 1e9f;
  for (size_t e = 0; e < original_.n_edges(); ++e) {
    const auto [a, b] = original_.edge(e);
    const bool regular = original_.valence(size_t(a)) == 4 && original_.valence(size_t(b)) == 4;
    if (!visible[size_t(a)] || !visible[size_t(b)] || !regular) continue;
    const glm::vec2 mid = pixel_of(view_, 0.5 * (original_.mean(size_t(a)) + original_.mean(size_t(b))));
    if (const float d = glm::length(mid - glm::vec2(kWidth / 2, kHeight / 2)); d < best) best = d, edge = {a, b};
  }
  ASSERT_GE(edge[0], 0);
  const std::vector<int> loop = edge_loop(original_, edge[0], edge[1]);
  ASSERT_GT(loop.size(), 8u);
  const glm::vec2 mid = pixel_of(view_, 0.5 * (original_.mean(size_t(edge[0])) + original_.mean(size_t(edge[1]))));
  Events events;
  events.click(mid, "alt").wait();
  play(events, "edge_loop.png");
  EXPECT_EQ(moved(play(move_selection(events, loop))), loop);
}

// On the cube the gizmo's axis ends sit on the selected corner's neighbours: a Shift+click on each
// neighbour selects it, rather than grabbing the axis end under it.
TEST_F(EditorModellingSelection, AClickOnANeighbourUnderAnAxisEndSelectsIt) {
  use_mesh(make_sample("cube"));
  const MeshConnectivity& c = original_.connectivity();
  int corner = 0;  // the corner nearest the camera, which looks from +x, +y, +z
  for (size_t v = 0; v < original_.n_vertices(); ++v)
    if (original_.mean(v).sum() > original_.mean(size_t(corner)).sum()) corner = int(v);
  std::vector<int> expected{corner};
  Events events;
  events.click(pixel_of(view_, original_.mean(size_t(corner)))).wait();
  for (int k = c.vertex_edge_offsets[size_t(corner)]; k < c.vertex_edge_offsets[size_t(corner) + 1]; ++k) {
    const int n = c.other_vertex(c.vertex_edges[size_t(k)], corner);
    events.click(pixel_of(view_, original_.mean(size_t(n))), "shift").wait();
    expected.push_back(n);
  }
  std::sort(expected.begin(), expected.end());
  Events shot = events;
  play(shot, "neighbours_under_axis_ends.png");
  EXPECT_EQ(moved(play(move_selection(events, expected))), expected);
}

// Shift+Alt+click adds a second edge loop to the first (as for a bridge), where Shift alone pans.
TEST_F(EditorModellingSelection, ShiftAltClickAddsASecondEdgeLoop) {
  use_mesh(make_sample("sphere", 384));
  const std::vector<char> visible = visible_vertices(view_, original_);
  const glm::vec2 centre(kWidth / 2, kHeight / 2);
  // Visible edges between vertices of valence 4, nearest the window's centre first.
  std::vector<std::pair<float, std::array<int, 2>>> edges;
  for (size_t e = 0; e < original_.n_edges(); ++e) {
    const auto [a, b] = original_.edge(e);
    const bool regular = original_.valence(size_t(a)) == 4 && original_.valence(size_t(b)) == 4;
    if (!visible[size_t(a)] || !visible[size_t(b)] || !regular) continue;
    const glm::vec2 mid = pixel_of(view_, 0.5 * (original_.mean(size_t(a)) + original_.mean(size_t(b))));
    edges.push_back({glm::length(mid - centre), {a, b}});
  }
  std::sort(edges.begin(), edges.end());
  ASSERT_FALSE(edges.empty());
  const auto midpoint = [&](const std::array<int, 2>& e) {
    return pixel_of(view_, 0.5 * (original_.mean(size_t(e[0])) + original_.mean(size_t(e[1]))));
  };
  const std::array<int, 2> first = edges.front().second;
  const std::vector<int> first_loop = edge_loop(original_, first[0], first[1]);
  // The nearest edge whose loop shares no vertex with the first, clear of the first's midpoint.
  std::array<int, 2> second{-1, -1};
  std::vector<int> second_loop;
  for (const auto& [distance, e] : edges) {
    if (glm::length(midpoint(e) - midpoint(first)) < 40.0f) continue;
    std::vector<int> loop = edge_loop(original_, e[0], e[1]), common;
    std::set_intersection(loop.begin(), loop.end(), first_loop.begin(), first_loop.end(), std::back_inserter(common));
    if (loop.size() > 8 && common.empty()) {
      second = e, second_loop = std::move(loop);
      break;
    }
  }
  ASSERT_GE(second[0], 0);
  std::vector<int> both;
  std::set_union(first_loop.begin(), first_loop.end(), second_loop.begin(), second_loop.end(),
                 std::back_inserter(both));
  Events events;
  events.click(midpoint(first), "alt").wait().click(midpoint(second), "shift+alt").wait();
  Events shot = events;
  play(shot, "two_edge_loops.png");
  EXPECT_EQ(moved(play(move_selection(events, both))), both);
}

// Two cubes apart: L over one selects its eight corners only; Ctrl+I then selects the other's.
TEST_F(EditorModellingSelection, LinkedUnderTheCursorAndInvert) {
  const CovarianceMesh cube = make_sample("cube");
  std::vector<Vec3> means;
  std::vector<Mat3> covariances;
  std::vector<std::vector<int>> faces;
  for (const double y : {-1.6, 1.6}) {  // one above the other, clear of the panels at the sides
    const int base = int(means.size());
    for (size_t v = 0; v < cube.n_vertices(); ++v) {
      means.push_back(0.6 * cube.mean(v) + Vec3(0, y, 0));
      covariances.push_back(cube.covariance(v));
    }
    for (size_t f = 0; f < cube.n_faces(); ++f) {
      std::vector<int> corners;
      for (const int v : cube.face(f)) corners.push_back(base + v);
      faces.push_back(corners);
    }
  }
  use_mesh(make_covariance_mesh(means, covariances, faces, "two cubes"));
  const auto face_centre = [this](int first) {  // the +z face of the cube whose vertices start at `first`
    Vec3 c = Vec3::Zero();
    for (const int v : {4, 5, 6, 7}) c += original_.mean(size_t(first + v)) / 4.0;
    return pixel_of(view_, c);
  };
  std::vector<int> first(8), second(8);
  for (int v = 0; v < 8; ++v) first[size_t(v)] = v, second[size_t(v)] = 8 + v;
  Events linked;
  linked.move(face_centre(0)).key("l").wait();
  Events shot = linked;
  play(shot.key("3").wait(), "linked.png");
  Events linked_moved = linked;
  EXPECT_EQ(moved(play(move_selection(linked_moved, first))), first);
  linked.key("ctrl+i").wait();
  EXPECT_EQ(moved(play(move_selection(linked, second))), second);
  Events from_selection;  // Ctrl+L grows a clicked vertex to its cube
  from_selection.click(pixel_of(view_, original_.mean(14))).wait().key("ctrl+l").wait();
  EXPECT_EQ(moved(play(move_selection(from_selection, second))), second);
}

// A press, then the last motion and the release in one frame (as at a low frame rate): the drag
// moves the vertex to where it was released (the centre dot moves it in the view plane).
TEST_F(EditorModellingSelection, ADragWhoseReleaseComesWithItsLastMotionIsKept) {
  use_mesh(make_sample("cube"));
  const glm::vec2 start = pixel_of(view_, original_.mean(6)), end = start + glm::vec2(-30.0f, 20.0f);
  Events events;
  events.click(start).wait().press(start).move(end).release(end).wait();
  const CovarianceMesh edited = play(events);
  const Vec3 d = edited.mean(6) - original_.mean(6);
  EXPECT_GT(d.norm(), 0.05) << "the drag was lost";
  EXPECT_LT(glm::length(pixel_of(view_, edited.mean(6)) - end), 0.5f);
  EXPECT_NEAR(d.dot((original_.mean(6) - to_vec(view_.camera.eye())).normalized()), 0.0, 1e-3)
      << "the move is in the view plane";
}

// In the orthographic front view (Numpad 1, Numpad 5) the axis of the vertex's ellipsoid along z
// points at the viewer and its ends lie on the centre dot: a drag there moves the vertex (the
// bottom-left front corner, clear of the panels).
TEST_F(EditorModellingSelection, TheCentreDotDragsInTheOrthographicFrontView) {
  CovarianceMesh cube = make_sample("cube");
  cube.covariances[4] = Vec3(0.004, 0.02, 0.06).asDiagonal();
  use_mesh(cube);
  view_.camera.yaw_degrees = 0.0f;
  view_.camera.pitch_degrees = 0.0f;
  view_.camera.orthographic = true;
  const glm::vec2 start = pixel_of(view_, original_.mean(4)), end = start + glm::vec2(-40.0f, 30.0f);
  Events events;
  events.key("kp1").key("kp5").wait().click(start).wait().drag(start, end, 6).wait();
  const CovarianceMesh edited = play(events, "ortho_front_drag.png");
  const Vec3 d = edited.mean(4) - original_.mean(4);
  EXPECT_GT(d.norm(), 0.1) << "the centre dot did not move the vertex";
  EXPECT_NEAR(d.z(), 0.0, 1e-6);
  EXPECT_LT(glm::length(pixel_of(view_, edited.mean(4)) - end), 0.5f);
  EXPECT_EQ(edited.covariance(4), original_.covariance(4));
}

}  // namespace
}  // namespace gps
