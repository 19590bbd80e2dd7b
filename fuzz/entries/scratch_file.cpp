#include "scratch_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace vern::fuzz {

namespace fs = std::filesystem;

namespace {

class ScratchFolder {
 public:
  ScratchFolder() {
    // The process id keeps parallel fuzzers (-jobs) and test runs apart.
    path_ = fs::temp_directory_path() / ("vern-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

fs::path scratch_file(const std::string& name, Bytes input) {
  static const ScratchFolder folder;
  const fs::path path = folder.path() / name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  // The harness's own failure, not the toolkit's: std::runtime_error makes
  // it a finding that says so.
  if (!f) throw std::runtime_error("fuzz harness: cannot write " + path.string());
  const std::size_t written = input.empty() ? 0 : std::fwrite(input.data(), 1, input.size(), f);
  if (std::fclose(f) != 0 || written != input.size())
    throw std::runtime_error("fuzz harness: cannot write " + path.string());
  return path;
}

}  // namespace vern::fuzz
