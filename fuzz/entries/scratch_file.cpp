#include "scratch_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <map>
#include <stdexcept>

namespace vern::fuzz {

namespace fs = std::filesystem;

namespace {

class ScratchFolder {
 public:
  // The process id keeps parallel fuzzers (-jobs) and test runs apart.
  explicit ScratchFolder(const std::string& suffix)
      : path_(fs::temp_directory_path() / ("vern-fuzz-" + std::to_string(::getpid()) + suffix)) {
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

fs::path scratch_folder(const std::string& purpose) {
  // Destroyed (and removed) at exit, as the function-local statics are.
  static std::map<std::string, ScratchFolder> folders;
  return folders.try_emplace(purpose, "-" + purpose).first->second.path();
}

fs::path scratch_file(const std::string& name, Bytes input) {
  static const ScratchFolder folder("");
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
