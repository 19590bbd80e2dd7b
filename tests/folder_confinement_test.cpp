// Files a file names stay in its folder (base/folder_confinement.hpp):
// what is refused as written, and links that lead out.
#include "base/folder_confinement.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "support/run_command.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;
using test::TempFolder;
using test::write_text;

// What path_in_folder gives, as text ("refused" for nothing): gtest prints
// strings, not paths.
std::string in_folder(const fs::path& folder, std::string_view named) {
  const std::optional<fs::path> path = path_in_folder(folder, named);
  return path ? path->string() : "refused";
}

TEST(FolderConfinement, PathsInTheFolderOrBelowAreFollowed) {
  TempFolder dir;
  fs::create_directories(dir / "g/meshes");
  write_text(dir / "g/a.obj", "o a\n");
  write_text(dir / "g/meshes/b.obj", "o b\n");
  EXPECT_EQ(in_folder(dir / "g", "a.obj"), (dir / "g/a.obj").string());
  EXPECT_EQ(in_folder(dir / "g", "meshes/b.obj"), (dir / "g/meshes/b.obj").string());
  EXPECT_EQ(in_folder(dir / "g", "meshes"), (dir / "g/meshes").string());
  EXPECT_EQ(in_folder(dir / "g", "missing.obj"), (dir / "g/missing.obj").string());  // reading it says so
  // A link that stays inside is fine.
  fs::create_symlink("meshes/b.obj", dir / "g/link.obj");
  EXPECT_EQ(in_folder(dir / "g", "link.obj"), (dir / "g/link.obj").string());
}

TEST(FolderConfinement, PathsWrittenOutsideAreRefusedAsWritten) {
  TempFolder dir;
  fs::create_directories(dir / "g");
  EXPECT_EQ(in_folder(dir / "g", "/etc/passwd"), "refused");
  EXPECT_EQ(in_folder(dir / "g", "../secret.obj"), "refused");
  EXPECT_EQ(in_folder(dir / "g", "meshes/../../secret.obj"), "refused");
  EXPECT_EQ(in_folder(dir / "g", "meshes/../a.obj"), "refused");  // any '..' at all
  EXPECT_EQ(in_folder(dir / "g", ""), "refused");
  EXPECT_EQ(in_folder(dir / "g", std::string("a.obj\0b", 7)), "refused");
}

TEST(FolderConfinement, LinksThatLeadOutAreRefused) {
  TempFolder dir;
  fs::create_directories(dir / "g/sub");
  write_text(dir / "secret.obj", "o secret\n");
  fs::create_symlink("../secret.obj", dir / "g/out.obj");
  fs::create_symlink("..", dir / "g/up");
  fs::create_symlink("loop.obj", dir / "g/loop.obj");
  EXPECT_EQ(in_folder(dir / "g", "out.obj"), "refused");
  EXPECT_EQ(in_folder(dir / "g", "up/secret.obj"), "refused");
  EXPECT_EQ(in_folder(dir / "g", "loop.obj"), "refused");  // cannot be told: refused
  EXPECT_FALSE(leads_into_folder(dir / "g/out.obj", dir / "g"));
  EXPECT_TRUE(leads_into_folder(dir / "secret.obj", dir.path()));
  // A folder whose name starts like the grammar's is not below it.
  fs::create_directories(dir / "g2");
  write_text(dir / "g2/x.obj", "o x\n");
  fs::create_symlink("../g2/x.obj", dir / "g/x.obj");
  EXPECT_EQ(in_folder(dir / "g", "x.obj"), "refused");
}

TEST(FolderConfinement, TheCurrentFolderIsAnEmptyFolderPath) {
  // A grammar named without a folder ("g.grm") names files from where the
  // command runs: the test process's own folder here.
  EXPECT_EQ(in_folder("", "some_file.obj"), "some_file.obj");
  EXPECT_EQ(in_folder("", "../some_file.obj"), "refused");
}

}  // namespace
}  // namespace vern
