#include "support/bad_input_helpers.hpp"

#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace vern::test {

namespace fs = std::filesystem;

namespace {
// Size and FNV-1a hash of a file, read in blocks: the snapshot of a folder
// holding a 200 MB input stays small, so the test process (whose memory a
// forked child starts from) stays small too.
std::string fingerprint(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::uint64_t hash = 14695981039346656037ULL;
  std::uint64_t size = 0;
  std::vector<char> block(1 << 16);
  while (in.read(block.data(), static_cast<std::streamsize>(block.size())) || in.gcount() > 0) {
    const auto n = static_cast<std::size_t>(in.gcount());
    for (std::size_t i = 0; i < n; ++i) hash = (hash ^ static_cast<unsigned char>(block[i])) * 1099511628211ULL;
    size += n;
  }
  return std::to_string(size) + " bytes, hash " + std::to_string(hash);
}
}  // namespace

FolderSnapshot snapshot(const fs::path& folder) {
  FolderSnapshot files;
  for (fs::recursive_directory_iterator it(folder), end; it != end; ++it) {
    const fs::directory_entry& e = *it;
    const std::string name = e.path().lexically_relative(folder).generic_string();
    // Links and FIFOs by what they are: reading through them could wait
    // for a writer or never end (a link to /dev/zero), or fail (a link
    // that leads to itself). Links are not followed into folders either.
    const fs::file_status status = e.symlink_status();
    if (fs::is_symlink(status)) {
      files[name] = "-> " + fs::read_symlink(e.path()).string();
      it.disable_recursion_pending();
    } else if (fs::is_directory(status)) {
      files[name] = "/";
    } else if (fs::is_regular_file(status)) {
      files[name] = fingerprint(e.path());
    } else {
      files[name] = "special file";
    }
  }
  return files;
}

MeasuredResult run_program_measured(const std::string& program, const std::vector<std::string>& args,
                                    const fs::path& folder, ChildLimits limits) {
  ChildSetup setup;
  setup.limits = limits;
  setup.measure_peak = true;
  ChildProcess child(program, args, folder, setup);
  const ChildProcess::Ended ended = child.wait();
  return {ended.result, ended.peak_kib};
}

namespace {
const char* const kTwoBoxes =
    "o wall\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 3\nv 2 0 3\nv 2 1 3\nv 0 1 3\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
    "o roof\nv 0 0 3\nv 2 0 3\nv 2 1 3\nv 0 1 3\nv 0 0 4\nv 2 0 4\nv 2 1 4\nv 0 1 4\n"
    "f 9 12 11 10\nf 13 14 15 16\nf 9 10 14 13\nf 10 11 15 14\nf 11 12 16 15\nf 12 9 13 16\n";
}  // namespace

void write_commented_obj(const fs::path& path, std::size_t bytes) {
  std::ofstream out(path, std::ios::binary);
  out << kTwoBoxes;
  std::string block;
  const std::string line = "# exported by a tool that writes a lot of remarks, " + std::string(40, '.') + "\n";
  while (block.size() < (1u << 20)) block += line;
  std::size_t written = std::char_traits<char>::length(kTwoBoxes);
  while (written < bytes) {
    out.write(block.data(), static_cast<std::streamsize>(block.size()));
    written += block.size();
  }
}

void write_many_parts_obj(const fs::path& path, std::size_t parts) {
  std::ofstream out(path, std::ios::binary);
  std::string text;
  for (std::size_t i = 0; i < parts; ++i) {
    const std::size_t b = 8 * i;
    text += (i % 2 ? "o wall\n" : "o window\n");
    for (int z = 0; z < 2; ++z)
      for (int k = 0; k < 4; ++k) {
        const std::size_t x = i + (k == 1 || k == 2 ? 1 : 0);
        text += "v " + std::to_string(x) + (k >= 2 ? " 1 " : " 0 ") + std::to_string(z) + "\n";
      }
    for (const auto& f : {"1 4 3 2", "5 6 7 8", "1 2 6 5", "2 3 7 6", "3 4 8 7", "4 1 5 8"}) {
      text += "f";
      for (const char* p = f; *p; ++p)
        if (*p != ' ') text += " " + std::to_string(b + static_cast<std::size_t>(*p - '0'));
      text += "\n";
    }
    if (text.size() > (1u << 20)) {
      out << text;
      text.clear();
    }
  }
  out << text;
}

void write_endless_line(const fs::path& path, std::size_t bytes) {
  std::ofstream out(path, std::ios::binary);
  std::string block;
  while (block.size() < (1u << 20)) block += "v 1 ";
  for (std::size_t written = 0; written < bytes; written += block.size())
    out.write(block.data(), static_cast<std::streamsize>(block.size()));
}

void write_generated_glb(const fs::path& folder, const std::string& name) {
  write_text(folder / "two_parts_for_glb.grm", "p --> split(x){ ~1 : I(rect) | ~1 : I(window) }\n");
  const CommandResult r = run_program("generate", {"two_parts_for_glb.grm", "--scope", "2", "1", "1", "-q", "-o", name}, folder);
  fs::remove(folder / "two_parts_for_glb.grm");
  if (r.exit_code != 0) throw std::runtime_error("generate could not write a GLB: " + r.err);
}

}  // namespace vern::test
