#include "ui/settings/recent_files.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>

#include "core/io/text_file.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

namespace fs = std::filesystem;

// Sets an environment variable for one scope, restoring the old value afterwards.
class ScopedEnv {
public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    set(value);
  }
  ~ScopedEnv() { set(old_ ? old_->c_str() : nullptr); }

private:
  void set(const char* value) {
    if (value)
      ::setenv(name_, value, 1);
    else
      ::unsetenv(name_);
  }
  const char* name_;
  std::optional<std::string> old_;
};

// Newest first; adding a path already listed (however written) moves it to the front; remove drops it.
TEST(RecentFiles, MostRecentFirstAndReAddingMovesToFront) {
  RecentFiles recent("");
  recent.add("/m/a.ply");
  recent.add("/m/b.ply");
  recent.add("/m/c.ply");
  EXPECT_EQ(recent.paths(), (std::vector<std::string>{"/m/c.ply", "/m/b.ply", "/m/a.ply"}));
  recent.add("/m/./x/../a.ply");  // the same file, written differently
  EXPECT_EQ(recent.paths(), (std::vector<std::string>{"/m/a.ply", "/m/c.ply", "/m/b.ply"}));
  recent.remove("/m/c.ply");
  EXPECT_EQ(recent.paths(), (std::vector<std::string>{"/m/a.ply", "/m/b.ply"}));
  recent.add("");
  EXPECT_EQ(recent.paths().size(), 2u);
  EXPECT_EQ(recent.last_error(), "");
}

// Ten by default; the oldest goes first.
TEST(RecentFiles, DropsTheOldestPastCapacity) {
  RecentFiles recent("");
  for (int i = 0; i < 12; ++i) recent.add("/m/" + std::to_string(i) + ".ply");
  ASSERT_EQ(recent.paths().size(), 10u);
  EXPECT_EQ(recent.paths().front(), "/m/11.ply");
  EXPECT_EQ(recent.paths().back(), "/m/2.ply");
  RecentFiles small("", 2);
  for (const char* p : {"/a", "/b", "/c"}) small.add(p);
  EXPECT_EQ(small.paths(), (std::vector<std::string>{"/c", "/b"}));
}

// Relative paths are stored absolute (against the working folder) and lexically normal.
TEST(RecentFiles, RelativePathsAreMadeAbsolute) {
  RecentFiles recent("");
  recent.add("sub/../mesh.ply");
  EXPECT_EQ(recent.paths(), (std::vector<std::string>{(fs::current_path() / "mesh.ply").string()}));
}

// Saved on every change (one path per line, creating the folder) and read back by the next instance.
TEST(RecentFiles, PersistsAcrossInstances) {
  test::TempDir dir;
  const std::string store = (dir.path() / "config" / "gpsurf" / "recent.txt").string();
  {
    RecentFiles recent(store);
    EXPECT_TRUE(recent.paths().empty());
    recent.add("/m/a.ply");
    recent.add("/m/b.ply");
    EXPECT_EQ(recent.last_error(), "");
  }
  EXPECT_EQ(read_text_file(store), "/m/b.ply\n/m/a.ply\n");
  RecentFiles again(store);
  EXPECT_EQ(again.paths(), (std::vector<std::string>{"/m/b.ply", "/m/a.ply"}));
  again.remove("/m/b.ply");
  EXPECT_EQ(RecentFiles(store).paths(), (std::vector<std::string>{"/m/a.ply"}));
}

// Empty lines and repeats in the store are skipped; a longer store is cut to capacity.
TEST(RecentFiles, ReadsAHandEditedStore) {
  test::TempDir dir;
  const std::string store = dir.write("recent.txt", "/a.ply\n\n/b.ply\n/a.ply\n/c.ply\n/d.ply");
  EXPECT_EQ(RecentFiles(store).paths(), (std::vector<std::string>{"/a.ply", "/b.ply", "/c.ply", "/d.ply"}));
  EXPECT_EQ(RecentFiles(store, 2).paths(), (std::vector<std::string>{"/a.ply", "/b.ply"}));
  EXPECT_TRUE(RecentFiles(dir.file("missing.txt")).paths().empty());
}

// A store that cannot be written (its folder is a file) records why and keeps the list in memory.
TEST(RecentFiles, UnwritableStoreRecordsTheErrorWithoutThrowing) {
  test::TempDir dir;
  dir.write("blocker", "");
  const std::string store = dir.file("blocker/gpsurf/recent.txt");
  RecentFiles recent(store);
  EXPECT_NO_THROW(recent.add("/m/a.ply"));
  EXPECT_EQ(recent.paths(), (std::vector<std::string>{"/m/a.ply"}));
  EXPECT_NE(recent.last_error().find(store), std::string::npos) << recent.last_error();
  EXPECT_EQ(recent.last_error().find('\n'), std::string::npos);

  const std::string folder_store = dir.file("folder");
  fs::create_directory(folder_store);
  RecentFiles on_folder(folder_store);
  EXPECT_NO_THROW(on_folder.add("/m/a.ply"));
  EXPECT_NE(on_folder.last_error().find(folder_store), std::string::npos) << on_folder.last_error();
}

// $XDG_CONFIG_HOME (when absolute), then $HOME/.config, else in memory only.
TEST(RecentFiles, DefaultStoreHonoursXdgConfigHomeThenHome) {
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", "/x/config");
    ScopedEnv home("HOME", "/h/user");
    EXPECT_EQ(RecentFiles::default_store(), "/x/config/gpsurf/recent.txt");
  }
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", nullptr);
    ScopedEnv home("HOME", "/h/user");
    EXPECT_EQ(RecentFiles::default_store(), "/h/user/.config/gpsurf/recent.txt");
  }
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", "relative/config");  // invalid by the XDG specification
    ScopedEnv home("HOME", "/h/user");
    EXPECT_EQ(RecentFiles::default_store(), "/h/user/.config/gpsurf/recent.txt");
  }
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", "");
    ScopedEnv home("HOME", nullptr);
    EXPECT_EQ(RecentFiles::default_store(), "");
  }
}

}  // namespace
}  // namespace gps
