// The View settings kept between sessions (settings.json): the gizmo's pivot and whose ellipsoids
// are drawn among them; out-of-range values are clamped, a wrong type is reported.
#include "ui/settings/editor_settings.h"

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

namespace gps {
namespace {

TEST(EditorSettings, ThePivotAndTheEllipsoidScopeAreKept) {
  const test::TempDir dir;
  ViewOptions view;
  ReachOptions reach;
  EXPECT_EQ(view.pivot, 0);            // the active vertex
  EXPECT_EQ(view.ellipsoid_scope, 0);  // automatic
  view.pivot = 1;
  view.ellipsoid_scope = 2;
  view.draw.ellipsoids = true;
  ASSERT_EQ(save_settings(dir.path().string(), view, reach), "");
  ViewOptions read;
  ReachOptions read_reach;
  ASSERT_EQ(load_settings(dir.path().string(), read, read_reach), "");
  EXPECT_EQ(read.pivot, 1);
  EXPECT_EQ(read.ellipsoid_scope, 2);
  EXPECT_TRUE(read.draw.ellipsoids);
}

// The up axis is kept per mesh file; one out of range is clamped, one of the wrong type reported.
TEST(EditorSettings, TheUpAxisIsKeptPerFile) {
  const test::TempDir dir;
  ViewOptions view;
  ReachOptions reach;
  view.up_axes["/scans/a.ply"] = 2;
  view.up_axes["/scans/b.obj"] = 0;
  ASSERT_EQ(save_settings(dir.path().string(), view, reach), "");
  ViewOptions read;
  ASSERT_EQ(load_settings(dir.path().string(), read, reach), "");
  EXPECT_EQ(read.up_axes, view.up_axes);
  dir.write("settings.json", R"({"up_axes": {"/a.ply": 5, "/b.ply": -1}})");
  ViewOptions clamped;
  ASSERT_EQ(load_settings(dir.path().string(), clamped, reach), "");
  EXPECT_EQ(clamped.up_axes.at("/a.ply"), 2);
  EXPECT_EQ(clamped.up_axes.at("/b.ply"), 0);
  dir.write("settings.json", R"({"up_axes": {"/a.ply": "z"}})");
  ViewOptions typed;
  EXPECT_NE(load_settings(dir.path().string(), typed, reach).find("'up_axes'"), std::string::npos);
  EXPECT_TRUE(typed.up_axes.empty());
}

// The mirror modifier is kept per mesh file (on, axis, clipping); an axis out of range is clamped, an
// entry missing a field reported and none kept.
TEST(EditorSettings, TheMirrorModifierIsKeptPerFile) {
  const test::TempDir dir;
  ViewOptions view;
  ReachOptions reach;
  view.mirror_modifiers["/parts/a.ply"] = MirrorSettings{true, 2, false};
  ASSERT_EQ(save_settings(dir.path().string(), view, reach), "");
  ViewOptions read;
  ASSERT_EQ(load_settings(dir.path().string(), read, reach), "");
  EXPECT_EQ(read.mirror_modifiers, view.mirror_modifiers);
  dir.write("settings.json", R"({"mirror_modifiers": {"/a.ply": {"enabled": true, "axis": 7, "clipping": true}}})");
  ViewOptions clamped;
  ASSERT_EQ(load_settings(dir.path().string(), clamped, reach), "");
  EXPECT_EQ(clamped.mirror_modifiers.at("/a.ply").axis, 2);
  dir.write("settings.json", R"({"mirror_modifiers": {"/a.ply": {"enabled": true}}})");
  ViewOptions partial;
  EXPECT_NE(load_settings(dir.path().string(), partial, reach).find("'mirror_modifiers'"), std::string::npos);
  EXPECT_TRUE(partial.mirror_modifiers.empty());
}

TEST(EditorSettings, OutOfRangeChoicesAreClampedAndAWrongTypeReported) {
  const test::TempDir dir;
  dir.write("settings.json", R"({"pivot": 7, "ellipsoid_scope": -3})");
  ViewOptions view;
  ReachOptions reach;
  EXPECT_EQ(load_settings(dir.path().string(), view, reach), "");
  EXPECT_EQ(view.pivot, 1);
  EXPECT_EQ(view.ellipsoid_scope, 0);
  dir.write("settings.json", R"({"pivot": "centroid"})");
  ViewOptions typed;
  const std::string error = load_settings(dir.path().string(), typed, reach);
  EXPECT_NE(error.find("'pivot' has the wrong type"), std::string::npos) << error;
  EXPECT_EQ(typed.pivot, 0);
}

}  // namespace
}  // namespace gps
