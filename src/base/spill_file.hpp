// Bytes a writer produces before it can write them where they go: a GLB's
// nodes come after a JSON head that is only known once every building has
// been seen. They are kept in memory up to a threshold, then moved to a
// temporary file that has no name (unlinked at once: nothing to clean up
// after a crash or a signal), so a writer's memory stays flat however many
// buildings it is given.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace vern {

class SpillFile {
 public:
  // folder: where the bytes go past `threshold` (the output's own folder,
  // so they use the disk the output will); none keeps everything in memory.
  // `owner` names the output in error messages.
  SpillFile(std::optional<std::filesystem::path> folder, std::string owner, std::size_t threshold = 1 << 20);
  SpillFile(const SpillFile&) = delete;
  SpillFile& operator=(const SpillFile&) = delete;
  ~SpillFile();

  // Appends bytes. Throws vern::Error (Io) naming the owner.
  void append(std::string_view bytes);
  std::uint64_t size() const { return on_disk_ + memory_.size(); }
  // Bytes held in memory now: at most about the threshold when spilling.
  std::size_t held_bytes() const { return memory_.capacity(); }

  // Every byte appended, in order, given in pieces of bounded size.
  void read(const std::function<void(std::string_view)>& take) const;

 private:
  void write_to_disk(std::string_view bytes);

  std::optional<std::filesystem::path> folder_;
  std::string owner_;
  std::size_t threshold_;
  std::string memory_;
  std::uint64_t on_disk_ = 0;
  int fd_ = -1;
};

}  // namespace vern
