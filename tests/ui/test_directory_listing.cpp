#include "ui/panels/directory_listing.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

#include "core/support/error.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> names(const std::vector<DirectoryEntry>& entries) {
  std::vector<std::string> out;
  for (const DirectoryEntry& e : entries) out.push_back(e.name + (e.is_directory ? "/" : ""));
  return out;
}

// Folders come first, then files; each group by name, ignoring case; sizes are the file sizes.
TEST(DirectoryListing, FoldersFirstThenFilesSortedIgnoringCase) {
  test::TempDir dir;
  dir.write("b.ply", "12345");
  dir.write("A.ply", "");
  dir.write("c.PLY", "");
  fs::create_directory(dir.path() / "zeta");
  fs::create_directory(dir.path() / "Alpha");
  fs::create_directory(dir.path() / "beta.ply");  // a folder, whatever its name says
  const std::vector<DirectoryEntry> entries = list_directory(dir.path().string(), {});
  EXPECT_EQ(names(entries), (std::vector<std::string>{"Alpha/", "beta.ply/", "zeta/", "A.ply", "b.ply", "c.PLY"}));
  EXPECT_EQ(entries[4].size, 5u);
  EXPECT_EQ(entries[0].size, 0u);
}

// Only files with a listed extension (case-insensitive, with dot); folders are always listed.
TEST(DirectoryListing, FiltersFilesByExtensionIgnoringCase) {
  test::TempDir dir;
  for (const char* name : {"a.ply", "b.OBJ", "c.txt", "d.Off", "ply", "e.ply.bak", "f.stl"}) dir.write(name, "x");
  fs::create_directory(dir.path() / "models");
  EXPECT_EQ(names(list_directory(dir.path().string(), {".ply", ".obj", ".off"})),
            (std::vector<std::string>{"models/", "a.ply", "b.OBJ", "d.Off"}));
  EXPECT_EQ(names(list_directory(dir.path().string(), {".STL"})), (std::vector<std::string>{"models/", "f.stl"}));
}

// The extension test on its own: a name that is only the extension does not count.
TEST(DirectoryListing, HasExtension) {
  EXPECT_TRUE(has_extension("mesh.PLY", {".obj", ".ply"}));
  EXPECT_TRUE(has_extension("a.tar.gz", {".tar.gz"}));
  EXPECT_FALSE(has_extension(".ply", {".ply"}));
  EXPECT_FALSE(has_extension("mesh.ply.bak", {".ply"}));
  EXPECT_FALSE(has_extension("mesh", {}));
}

// Names with a leading '.' only when asked for.
TEST(DirectoryListing, HiddenEntriesOnlyWhenAsked) {
  test::TempDir dir;
  dir.write(".secret.ply", "");
  dir.write("shown.ply", "");
  fs::create_directory(dir.path() / ".cache");
  EXPECT_EQ(names(list_directory(dir.path().string(), {".ply"})), (std::vector<std::string>{"shown.ply"}));
  EXPECT_EQ(names(list_directory(dir.path().string(), {".ply"}, true)),
            (std::vector<std::string>{".cache/", ".secret.ply", "shown.ply"}));
}

// Links are followed; a broken link and a fifo are skipped rather than listed or failing.
TEST(DirectoryListing, FollowsLinksAndSkipsWhatCannotBeOpened) {
  test::TempDir dir;
  dir.write("real.ply", "abc");
  fs::create_directory(dir.path() / "folder");
  fs::create_symlink(dir.path() / "real.ply", dir.path() / "link.ply");
  fs::create_directory_symlink(dir.path() / "folder", dir.path() / "folder_link");
  fs::create_symlink(dir.path() / "missing.ply", dir.path() / "broken.ply");
  ASSERT_EQ(::mkfifo(dir.file("pipe.ply").c_str(), 0600), 0);
  const std::vector<DirectoryEntry> entries = list_directory(dir.path().string(), {".ply"});
  EXPECT_EQ(names(entries), (std::vector<std::string>{"folder/", "folder_link/", "link.ply", "real.ply"}));
  EXPECT_EQ(entries[2].size, 3u);
}

// A missing folder, or a file given as a folder, is one line naming it.
TEST(DirectoryListing, MissingFolderIsOneLineErrorNamingIt) {
  test::TempDir dir;
  const std::string missing = dir.file("nowhere");
  try {
    list_directory(missing, {});
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(missing), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  const std::string file = dir.write("plain.ply", "");
  EXPECT_THROW(list_directory(file, {}), Error);
}

// A folder without read permission is an error naming it; an unreadable sub-folder is skipped.
TEST(DirectoryListing, UnreadableFolderIsAnErrorAndUnreadableEntriesAreSkipped) {
  if (::geteuid() == 0) GTEST_SKIP() << "permissions do not apply to root";
  test::TempDir dir;
  fs::create_directory(dir.path() / "locked");
  fs::create_directory(dir.path() / "open");
  fs::permissions(dir.path() / "locked", fs::perms::none);
  EXPECT_EQ(names(list_directory(dir.path().string(), {})), (std::vector<std::string>{"open/"}));
  try {
    list_directory((dir.path() / "locked").string(), {});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("locked"), std::string::npos) << e.what();
  }
  fs::permissions(dir.path() / "locked", fs::perms::owner_all);
}

}  // namespace
}  // namespace gps
