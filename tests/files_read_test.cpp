// The files a run has read are never written over by it, once a command
// records them; a library user that does not is unaffected.
#include "base/files_read.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "base/atomic_file.hpp"
#include "base/error.hpp"
#include "base/input_file.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::TempFolder;
using test::write_text;

void read_whole(const fs::path& path) {
  std::vector<unsigned char> bytes;
  ASSERT_FALSE(read_regular_file(path, 1 << 20, bytes));
}

ErrorKind staging_fails(const fs::path& path) {
  try {
    write_file_atomically(path, "an output\n");
  } catch (const Error& e) {
    return e.kind();
  }
  ADD_FAILURE() << "writing " << path << " should fail";
  return ErrorKind::Internal;
}

TEST(FilesRead, AFileReadIsNotWrittenOver) {
  TempFolder dir;
  write_text(dir / "buffer.bin", "an input\n");
  const FilesReadRecorded recording;
  read_whole(dir / "buffer.bin");
  // Spelled another way, and through a link.
  fs::create_symlink(dir / "buffer.bin", dir / "link.bin");
  for (const fs::path& output : {dir / "buffer.bin", dir / "." / "buffer.bin", dir / "link.bin"})
    EXPECT_EQ(staging_fails(output), ErrorKind::Usage) << output;
  EXPECT_EQ(read_file(dir / "buffer.bin"), "an input\n");
  EXPECT_EQ(test::list_folder(dir.path()), (std::vector<std::string>{"buffer.bin", "link.bin"}));
}

TEST(FilesRead, TheErrorNamesBothPaths) {
  TempFolder dir;
  write_text(dir / "mesh.obj", "o wall\n");
  fs::create_directory(dir / "sub");
  const FilesReadRecorded recording;
  require_regular_file(dir / "sub/../mesh.obj");
  try {
    write_file_atomically(dir / "mesh.obj", "an output\n");
    FAIL() << "should fail";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find((dir / "mesh.obj").string() + ": error: this output is a file the run has read (as " +
                           (dir / "sub/../mesh.obj").string() + ")"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("\n  hint: "), std::string::npos) << message;
  }
}

// A file read after its output was staged is refused at the commit,
// before anything is renamed.
TEST(FilesRead, TheCommitChecksAgain) {
  TempFolder dir;
  write_text(dir / "a.txt", "old a");
  write_text(dir / "b.txt", "an input");
  const FilesReadRecorded recording;
  OutputFiles outputs;
  outputs.stage(dir / "a.txt", "new a");
  outputs.stage(dir / "b.txt", "new b");
  read_whole(dir / "b.txt");
  try {
    outputs.commit();
    FAIL() << "the commit should fail";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Usage) << e.what();
  }
  EXPECT_EQ(read_file(dir / "a.txt"), "old a");
  EXPECT_EQ(read_file(dir / "b.txt"), "an input");
}

TEST(FilesRead, OnlyWhileRecorded) {
  TempFolder dir;
  write_text(dir / "a.txt", "read before");
  {
    const FilesReadRecorded recording;
    read_whole(dir / "a.txt");
  }
  write_text(dir / "b.txt", "read without recording");
  read_whole(dir / "b.txt");
  write_file_atomically(dir / "a.txt", "new a");
  write_file_atomically(dir / "b.txt", "new b");
  EXPECT_EQ(read_file(dir / "a.txt"), "new a");
  EXPECT_EQ(read_file(dir / "b.txt"), "new b");
}

}  // namespace
}  // namespace vern
