// The outputs of one run: replaced together or not at all.
#include "base/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "base/error.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;
using test::list_folder;
using test::read_file;
using test::TempFolder;
using test::write_text;

TEST(OutputFiles, CommitReplacesEveryFileAndLeavesNoTemporaries) {
  TempFolder dir;
  write_text(dir / "a.txt", "old a");
  OutputFiles outputs;
  outputs.stage(dir / "a.txt", "new a");
  outputs.stage(dir / "b.txt", "new b");
  // Staged, not yet seen.
  EXPECT_EQ(read_file(dir / "a.txt"), "old a");
  EXPECT_FALSE(fs::exists(dir / "b.txt"));
  outputs.commit();
  EXPECT_EQ(read_file(dir / "a.txt"), "new a");
  EXPECT_EQ(read_file(dir / "b.txt"), "new b");
  EXPECT_EQ(list_folder(dir.path()), (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST(OutputFiles, ARunNotCommittedChangesNothing) {
  TempFolder dir;
  write_text(dir / "a.txt", "old a");
  {
    OutputFiles outputs;
    outputs.stage(dir / "a.txt", "new a");
    // The second output's folder is missing: the run fails here.
    EXPECT_THROW(outputs.stage(dir / "missing" / "b.txt", "new b"), Error);
  }
  EXPECT_EQ(read_file(dir / "a.txt"), "old a");
  EXPECT_EQ(list_folder(dir.path()), (std::vector<std::string>{"a.txt"}));
}

TEST(OutputFiles, ARenameThatFailsPutsBackTheOnesBefore) {
  TempFolder dir;
  write_text(dir / "a.txt", "old a");
  OutputFiles outputs;
  outputs.stage(dir / "a.txt", "new a");
  outputs.stage(dir / "new.txt", "new file");
  outputs.stage(dir / "c.txt", "new c");
  // c.txt turns into a folder after it was staged: its rename fails, after
  // a.txt and new.txt were renamed.
  fs::create_directory(dir / "c.txt");
  try {
    outputs.commit();
    FAIL() << "the commit should fail";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    EXPECT_NE(std::string(e.what()).find("c.txt: error: cannot replace"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_file(dir / "a.txt"), "old a");
  EXPECT_FALSE(fs::exists(dir / "new.txt"));
  EXPECT_TRUE(fs::is_directory(dir / "c.txt"));
}

TEST(OutputFiles, TheTemporariesAreRemovedWhenTheRunEnds) {
  TempFolder dir;
  {
    OutputFiles outputs;
    outputs.stage(dir / "a.txt", "new a");
    outputs.commit();
    fs::create_directory(dir / "b.txt");
    OutputFiles failed;
    failed.stage(dir / "c.txt", "c");
    failed.stage(dir / "d.txt", "d");
    fs::create_directory(dir / "d.txt");
    EXPECT_THROW(failed.commit(), Error);
  }
  EXPECT_EQ(list_folder(dir.path()), (std::vector<std::string>{"a.txt", "b.txt", "d.txt"}));
}

}  // namespace
}  // namespace vern
