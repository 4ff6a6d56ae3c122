#include "ui/panels/file_browser.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <imgui.h>
#include <imgui_internal.h>

#include "tests/support/temp_dir.h"

namespace gps {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> mesh_extensions = {".ply", ".obj", ".off", ".stl"};

// A Dear ImGui context without any GL: frames are built and rendered into draw lists nobody draws,
// with keyboard and mouse fed through ImGui 1.86's io (KeyMap is the identity: KeysDown[ImGuiKey_X]).
class FileBrowserTest : public ::testing::Test {
protected:
  FileBrowserTest() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280, 720);
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    for (int key = 0; key < ImGuiKey_COUNT; ++key) io.KeyMap[key] = key;
    dir.write("a.ply", "ply");
    dir.write("b.obj", "obj");
    dir.write("c.txt", "txt");
    fs::create_directory(dir.path() / "sub");
  }
  ~FileBrowserTest() override { ImGui::DestroyContext(); }

  /// One frame; what draw() returned in it.
  std::optional<std::string> frame() {
    ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    std::optional<std::string> result = browser.draw();
    ImGui::Render();
    return result;
  }
  /// `n` frames; the first result any of them returned.
  std::optional<std::string> frames(int n) {
    std::optional<std::string> result;
    for (int i = 0; i < n; ++i) {
      std::optional<std::string> r = frame();
      if (!result) result = r;
    }
    return result;
  }
  /// Presses and releases `key` (two frames); the first result.
  std::optional<std::string> press(ImGuiKey key) {
    ImGui::GetIO().KeysDown[key] = true;
    std::optional<std::string> result = frame();
    ImGui::GetIO().KeysDown[key] = false;
    std::optional<std::string> after = frame();
    return result ? result : after;
  }
  /// Types `text` into the focused field.
  void type(const std::string& text) {
    for (const char c : text) ImGui::GetIO().AddInputCharacter(static_cast<unsigned char>(c));
    frame();
  }
  /// Types `text` and presses Enter.
  std::optional<std::string> enter(const std::string& text) {
    type(text);
    return press(ImGuiKey_Enter);
  }
  /// Clicks row `row` of the listing (clicks = 2: a double-click); the first result.
  std::optional<std::string> click_row(int row, int clicks) {
    ImGuiWindow* listing = nullptr;
    for (ImGuiWindow* window : GImGui->Windows) {
      if (window->Active && (window->Flags & ImGuiWindowFlags_ChildWindow) && window->ParentWindow &&
          (window->ParentWindow->Flags & ImGuiWindowFlags_Modal))
        listing = window;
    }
    EXPECT_NE(listing, nullptr);
    if (!listing) return std::nullopt;
    const float row_height = ImGui::GetFontSize() + 2 * ImGui::GetStyle().CellPadding.y;
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos =
        ImVec2(listing->ContentRegionRect.Min.x + 20, listing->ContentRegionRect.Min.y + row_height * (row + 0.5f));
    std::optional<std::string> result = frames(20);  // past the double-click time of earlier clicks
    for (int i = 0; i < clicks; ++i) {
      for (const bool down : {true, false}) {
        io.MouseDown[0] = down;
        std::optional<std::string> r = frame();
        if (!result) result = r;
      }
    }
    return result;
  }
  std::string path(const std::string& name) const { return (dir.path() / name).string(); }

  test::TempDir dir;
  FileBrowser browser;
};

// Save: the proposed name is selected on opening; typing replaces it, Enter confirms, ".ply" is added.
TEST_F(FileBrowserTest, SaveTypedNameGetsTheFirstExtensionOnEnter) {
  browser.open(FileBrowser::Mode::save, "Save mesh", dir.path().string(), mesh_extensions, "untitled.ply");
  EXPECT_TRUE(browser.is_open());
  EXPECT_EQ(frames(3), std::nullopt);
  EXPECT_EQ(enter("out"), path("out.ply"));
  EXPECT_FALSE(browser.is_open());
  EXPECT_EQ(frames(3), std::nullopt);
}

// A name with a listed extension keeps it; relative and absolute paths resolve against the folder.
TEST_F(FileBrowserTest, SaveResolvesRelativeAndAbsoluteNames) {
  browser.open(FileBrowser::Mode::save, "Save mesh", dir.path().string(), mesh_extensions);
  frames(3);
  EXPECT_EQ(enter("sub/../sub/x.OBJ"), path("sub/x.OBJ"));
  browser.open(FileBrowser::Mode::save, "Save mesh", dir.path().string(), mesh_extensions);
  frames(3);
  EXPECT_EQ(enter(path("sub/y.txt")), path("sub/y.txt.ply"));
}

// Escape closes the dialog without a result.
TEST_F(FileBrowserTest, EscapeClosesWithoutResult) {
  browser.open(FileBrowser::Mode::open, "Open mesh", dir.path().string(), mesh_extensions);
  frames(3);
  type("a.ply");
  EXPECT_EQ(press(ImGuiKey_Escape), std::nullopt);
  EXPECT_FALSE(browser.is_open());
  EXPECT_EQ(press(ImGuiKey_Enter), std::nullopt);
}

// Saving over an existing file asks first: Escape returns to the dialog, Enter replaces.
TEST_F(FileBrowserTest, ReplacingAnExistingFileAsksFirst) {
  browser.open(FileBrowser::Mode::save, "Save mesh", dir.path().string(), mesh_extensions);
  frames(3);
  EXPECT_EQ(enter("a"), std::nullopt);  // a.ply exists
  frames(3);
  EXPECT_TRUE(browser.is_open());
  EXPECT_EQ(press(ImGuiKey_Escape), std::nullopt);  // answers "Replace?" only
  EXPECT_TRUE(browser.is_open());
  frames(2);
  EXPECT_EQ(enter("2"), path("a2.ply"));  // back in the name field, the text kept
  browser.open(FileBrowser::Mode::save, "Save mesh", dir.path().string(), mesh_extensions, "a.ply");
  frames(3);
  EXPECT_EQ(press(ImGuiKey_Enter), std::nullopt);
  frames(3);
  EXPECT_EQ(press(ImGuiKey_Enter), path("a.ply"));
  EXPECT_FALSE(browser.is_open());
}

// A typed folder name (or "..") enters that folder; the next name resolves inside it.
TEST_F(FileBrowserTest, TypedFolderIsEntered) {
  browser.open(FileBrowser::Mode::save, "Save mesh", dir.path().string(), mesh_extensions);
  frames(3);
  EXPECT_EQ(enter("sub"), std::nullopt);
  frames(2);
  EXPECT_TRUE(browser.is_open());
  EXPECT_EQ(enter("m"), path("sub/m.ply"));
  browser.open(FileBrowser::Mode::save, "Save mesh", path("sub"), mesh_extensions);
  frames(3);
  EXPECT_EQ(enter(".."), std::nullopt);
  frames(2);
  EXPECT_EQ(enter("n"), path("n.ply"));
}

// Open mode: a missing file is an error in the dialog (no result, still open); no extension is added.
TEST_F(FileBrowserTest, OpenNeedsAnExistingFile) {
  browser.open(FileBrowser::Mode::open, "Open mesh", dir.path().string(), mesh_extensions);
  frames(3);
  EXPECT_EQ(enter("a"), std::nullopt);
  frames(2);
  EXPECT_TRUE(browser.is_open());
  EXPECT_EQ(enter(".ply"), path("a.ply"));  // the text is kept to be corrected
}

// Mouse: double-clicking the folder (row 0) enters it; in the parent again, double-clicking a file
// (row 1: a.ply, c.txt being filtered out) opens it.
TEST_F(FileBrowserTest, DoubleClicksEnterFoldersAndOpenFiles) {
  dir.write("sub/inner.stl", "stl");
  browser.open(FileBrowser::Mode::open, "Open mesh", dir.path().string(), mesh_extensions);
  frames(3);
  EXPECT_EQ(click_row(0, 2), std::nullopt);
  frames(2);
  EXPECT_EQ(click_row(0, 2), path("sub/inner.stl"));

  browser.open(FileBrowser::Mode::open, "Open mesh", dir.path().string(), mesh_extensions);
  frames(3);
  EXPECT_EQ(click_row(1, 1), std::nullopt);        // one click only selects
  EXPECT_EQ(press(ImGuiKey_Enter), std::nullopt);  // the name field no longer has the keyboard
  EXPECT_EQ(click_row(1, 2), path("a.ply"));
}

// A starting folder that cannot be listed falls back to the working folder; a bad folder typed into
// the path bar is reported, and a good one is entered.
TEST_F(FileBrowserTest, BadFoldersAreReportedNotFatal) {
  browser.open(FileBrowser::Mode::save, "Save mesh", path("missing"), mesh_extensions);
  frames(3);
  EXPECT_EQ(enter("w"), (fs::current_path() / "w.ply").string());

  browser.open(FileBrowser::Mode::save, "Save mesh", dir.path().string(), mesh_extensions);
  frames(3);
  EXPECT_EQ(press(ImGuiKey_Tab), std::nullopt);  // from the name field to the path bar
  EXPECT_EQ(enter(path("missing")), std::nullopt);
  frames(2);
  EXPECT_TRUE(browser.is_open());
  for (int i = 0; i < 7; ++i) press(ImGuiKey_Backspace);  // the path bar keeps the bad path to correct
  EXPECT_EQ(enter("sub"), std::nullopt);
  frames(2);
  EXPECT_EQ(enter("z"), path("sub/z.ply"));  // and then the name field has the keyboard
}

}  // namespace
}  // namespace gps
