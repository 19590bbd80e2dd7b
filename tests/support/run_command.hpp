// Running the command-line programs from tests, as a user would.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vern::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// How long a program may run in a test before it is stopped as hung (the
// sanitized build reads a 200 MB example in well under a minute).
constexpr unsigned kHangSeconds = 600;

// Runs VERN_BIN_DIR/program with the arguments (each shell-quoted), in
// `folder` (the current folder when empty), capturing both streams. A
// program still running after kHangSeconds is stopped (exit code 124).
CommandResult run_program(const std::string& program, const std::vector<std::string>& args,
                          const std::filesystem::path& folder = {});

// A fresh empty folder under the system temp folder, removed by the destructor.
class TempFolder {
 public:
  TempFolder();
  ~TempFolder();
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

std::string read_file(const std::filesystem::path& p);
void write_text(const std::filesystem::path& p, const std::string& text);
// Every file in a folder (names only, sorted).
std::vector<std::string> list_folder(const std::filesystem::path& folder);

}  // namespace vern::test
