// Three values held on the heap, with the value semantics of std::array.
//
// T's offsets, S's sizes and colour's components are three expressions
// each (96 to 120 bytes); held inline, they made every node of the arena
// 144 bytes for the sake of a few T, S and colour nodes. Behind a pointer
// the largest operation is 72 bytes and a node 88: a million-part inference
// touches 40 % less arena memory.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

namespace vern {

template <class T>
class Triple {
 public:
  Triple() = default;
  Triple(T a, T b, T c) : values_(new std::array<T, 3>{std::move(a), std::move(b), std::move(c)}) {}
  Triple(std::array<T, 3> values) : values_(new std::array<T, 3>(std::move(values))) {}  // NOLINT: reads as an array
  Triple(const Triple& other) : values_(other.values_ ? new std::array<T, 3>(*other.values_) : nullptr) {}
  Triple(Triple&& other) noexcept : values_(std::exchange(other.values_, nullptr)) {}
  Triple& operator=(Triple other) noexcept {
    std::swap(values_, other.values_);
    return *this;
  }
  ~Triple() { delete values_; }

  // No storage (default-made or moved from) reads as three default values.
  const T& operator[](std::size_t i) const { return all()[i]; }
  T& operator[](std::size_t i) { return own()[i]; }
  const T* begin() const { return all().data(); }
  const T* end() const { return all().data() + 3; }
  T* begin() { return own().data(); }
  T* end() { return own().data() + 3; }
  static constexpr std::size_t size() { return 3; }

  friend bool operator==(const Triple& a, const Triple& b) { return a.all() == b.all(); }

 private:
  const std::array<T, 3>& all() const {
    static const std::array<T, 3> kDefault{};
    return values_ ? *values_ : kDefault;
  }
  std::array<T, 3>& own() {
    if (!values_) values_ = new std::array<T, 3>{};
    return *values_;
  }

  std::array<T, 3>* values_ = nullptr;  // owned
};

}  // namespace vern
