#include "folder_tree.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <string_view>

namespace vern::fuzz {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxEntries = 32;
constexpr std::size_t kMaxRepeat = std::size_t{1} << 20;

std::string percent_decoded(std::string_view text) {
  const auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && hex(text[i + 1]) >= 0 && hex(text[i + 2]) >= 0) {
      out += static_cast<char>(hex(text[i + 1]) * 16 + hex(text[i + 2]));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

// Words apart by white space (a name can hold none: it is percent-encoded).
std::vector<std::string_view> words(std::string_view line) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::string replaced(std::string text, std::string_view from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// $ROOT and $IN made absolute.
std::string substituted(std::string text, const fs::path& root, const fs::path& inside) {
  return replaced(replaced(std::move(text), "$ROOT", root.string()), "$IN", inside.string());
}

// The count of a repeat section: digits, capped.
std::size_t count_of(std::string_view text) {
  std::size_t n = 0;
  for (char c : text) {
    if (c < '0' || c > '9') break;
    n = std::min(kMaxRepeat, n * 10 + static_cast<std::size_t>(c - '0'));
  }
  return n;
}

// `path` (absolute, lexically normal) relative to `root`, or empty when it
// is the root or not below it.
fs::path below(const fs::path& path, const fs::path& root) {
  const fs::path rel = path.lexically_relative(root);
  if (rel.empty() || rel == "." || *rel.begin() == "..") return {};
  return rel;
}

// Makes the folders on the way to root/rel (not rel itself), none of them
// a link: false when one is a link or a file.
bool make_folders_on_the_way(const fs::path& root, const fs::path& rel) {
  fs::path at = root;
  for (const fs::path& step : rel.parent_path()) {
    at /= step;
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(at, ec);
    if (status.type() == fs::file_type::not_found) {
      if (!fs::create_directory(at, ec) || ec) return false;
    } else if (status.type() != fs::file_type::directory) {
      return false;
    }
  }
  return true;
}

// A new file (never through a link, never over an existing one).
void write_new_file(const fs::path& path, std::string_view bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) return;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);
}

}  // namespace

FolderTree decode_folder_tree(Bytes input) {
  const std::string_view text(reinterpret_cast<const char*>(input.data()), input.size());
  // Section starts: "@@ " at the start of the input or after a line break.
  std::vector<std::size_t> starts;
  if (text.starts_with("@@ ")) starts.push_back(0);
  for (std::size_t at = text.find("\n@@ "); at != std::string_view::npos; at = text.find("\n@@ ", at + 1))
    starts.push_back(at + 1);

  FolderTree tree;
  const std::vector<std::string_view> header = words(text.substr(0, starts.empty() ? text.size() : starts[0]));
  tree.grammar = std::find(header.begin(), header.end(), "grammar") != header.end();
  tree.outside_files = std::find(header.begin(), header.end(), "outside") != header.end();
  bool has_main = false;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const std::size_t end = k + 1 < starts.size() ? starts[k + 1] - 1 : text.size();
    const std::string_view section = text.substr(starts[k] + 3, end - starts[k] - 3);
    const std::size_t line_end = std::min(section.find('\n'), section.size());
    const std::vector<std::string_view> head = words(section.substr(0, line_end));
    const std::string_view bytes = line_end < section.size() ? section.substr(line_end + 1) : std::string_view();
    if (head.empty()) continue;
    const std::string_view kind = head[0];
    if (kind == "main") {
      if (!has_main) tree.main = bytes;
      has_main = true;
      continue;
    }
    if (head.size() < 2 || tree.entries.size() >= kMaxEntries) continue;
    FolderTree::Entry e;
    e.name = percent_decoded(head[1]);
    if (kind == "file") {
      e.bytes = bytes;
    } else if (kind == "repeat") {
      const std::size_t count = head.size() > 2 ? count_of(head[2]) : 0;
      if (bytes.empty()) {
        e.bytes.assign(count, '\0');
      } else {
        e.bytes.reserve(count);
        while (e.bytes.size() < count) e.bytes.append(bytes.substr(0, count - e.bytes.size()));
      }
    } else if (kind == "link" && head.size() > 2) {
      e.kind = FolderTree::Entry::Kind::Link;
      e.bytes = percent_decoded(head[2]);
    } else if (kind == "dir") {
      e.kind = FolderTree::Entry::Kind::Folder;
    } else {
      continue;
    }
    tree.entries.push_back(std::move(e));
  }
  return tree;
}

PlacedTree place_folder_tree(const FolderTree& tree, const fs::path& root) {
  for (const fs::directory_entry& e : fs::directory_iterator(root)) fs::remove_all(e.path());
  PlacedTree placed;
  placed.inside = root / "in";
  fs::create_directory(placed.inside);
  const bool glb = tree.main.starts_with("glTF");
  placed.main = placed.inside / (tree.grammar ? "main.grm" : glb ? "main.glb" : "main.gltf");
  write_new_file(placed.main, substituted(tree.main, root, placed.inside));

  for (const FolderTree::Entry& e : tree.entries) {
    // A NUL would cut the path short where the system reads it.
    const std::string name = substituted(e.name, root, placed.inside);
    if (name.empty() || name.find('\0') != std::string::npos) continue;
    const fs::path path = (placed.inside / name).lexically_normal();
    const fs::path rel = below(path, root);
    if (rel.empty() || rel == "in" || !make_folders_on_the_way(root, rel)) continue;
    std::error_code ec;
    switch (e.kind) {
      case FolderTree::Entry::Kind::File:
        write_new_file(path, substituted(e.bytes, root, placed.inside));
        break;
      case FolderTree::Entry::Kind::Folder:
        fs::create_directory(path, ec);
        break;
      case FolderTree::Entry::Kind::Link: {
        const std::string target = substituted(e.bytes, root, placed.inside);
        if (target.empty() || target.find('\0') != std::string::npos) break;
        const fs::path leads_to = (path.parent_path() / target).lexically_normal();
        if (leads_to != root && below(leads_to, root).empty()) break;
        fs::create_symlink(target, path, ec);
        break;
      }
    }
  }

  // The folders a read would be outside in: all but in/ and what it holds.
  placed.outside_folders.push_back(root);
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    if (it->path() == placed.inside) {
      it.disable_recursion_pending();
    } else if (it->symlink_status().type() == fs::file_type::directory) {
      placed.outside_folders.push_back(it->path());
    }
  }
  return placed;
}

}  // namespace vern::fuzz
