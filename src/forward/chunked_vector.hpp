// A vector that grows in fixed blocks: appending never moves what is held.
//
// The OBJ reader keeps every vertex of a file (a face may use any earlier
// one): 192 MB for a million-part layout. As a std::vector that grew by
// copying everything into twice the memory each time, a tenth of the
// reading time went to copies and the fresh pages they touched.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace vern {

// The first block is an ordinary vector that grows up to a block's size:
// a file of a few parts (every built-in primitive is read at start-up)
// then allocates what it holds, not a whole block per array (with blocks
// of 65536 that cost more than the reading, and kept a sanitizer's
// freed-memory quarantine full). Later blocks are allocated whole and
// left uninitialised.
template <class T>
class ChunkedVector {
 public:
  std::size_t size() const { return size_; }

  const T& operator[](std::size_t i) const { return i < kBlock ? first_[i] : blocks_[(i >> kShift) - 1][i & kMask]; }
  T& operator[](std::size_t i) { return i < kBlock ? first_[i] : blocks_[(i >> kShift) - 1][i & kMask]; }
  const T& back() const { return (*this)[size_ - 1]; }

  void push_back(const T& value) {
    if (size_ < kBlock) {
      first_.push_back(value);
    } else {
      if ((size_ & kMask) == 0) blocks_.push_back(std::make_unique_for_overwrite<T[]>(kBlock));
      blocks_.back()[size_ & kMask] = value;
    }
    ++size_;
  }

  // Grows to n elements, the new ones equal to value (never shrinks).
  void grow_to(std::size_t n, const T& value) {
    while (size_ < n) push_back(value);
  }

 private:
  // 4096 elements (96 KB of vertices): few blocks for a large file, and
  // little for the many small ones (the built-in primitives' meshes).
  static constexpr std::size_t kShift = 12;
  static constexpr std::size_t kBlock = std::size_t{1} << kShift;
  static constexpr std::size_t kMask = kBlock - 1;

  std::vector<T> first_;
  std::vector<std::unique_ptr<T[]>> blocks_;  // elements kBlock and on
  std::size_t size_ = 0;
};

}  // namespace vern
