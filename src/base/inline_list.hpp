// A list that holds its first N elements in place.
//
// Hot loops of inference build many short lists and drop them at once:
// the intervals of a support (support.hpp; almost always one), the runs of
// a split being placed (split_search.hpp; a few). In a std::vector each
// took a heap block of its own, made and freed by the million (a quarter
// of all the allocations of inferring the city). Here up to N elements
// live inside the object; one more moves them all to the heap. Value
// semantics, as a vector's; for small trivially copyable elements.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <type_traits>
#include <utility>
#include <vector>

namespace vern {

template <typename T, std::size_t N>
class InlineList {
  static_assert(N > 0 && std::is_trivially_destructible_v<T>, "an InlineList holds plain values in place");

 public:
  using value_type = T;

  InlineList() = default;
  InlineList(std::initializer_list<T> list) {
    reserve(list.size());
    for (const T& v : list) push_back(v);
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  // Up to N elements: in place; more: all on the heap.
  T* begin() { return size_ <= N ? in_place_.data() : heap_.data(); }
  T* end() { return begin() + size_; }
  const T* begin() const { return size_ <= N ? in_place_.data() : heap_.data(); }
  const T* end() const { return begin() + size_; }
  T& operator[](std::size_t i) { return begin()[i]; }
  const T& operator[](std::size_t i) const { return begin()[i]; }
  T& front() { return *begin(); }
  const T& front() const { return *begin(); }
  T& back() { return begin()[size_ - 1]; }
  const T& back() const { return begin()[size_ - 1]; }

  void reserve(std::size_t n) {
    if (n > N) heap_.reserve(n);
  }
  void clear() {
    size_ = 0;
    heap_.clear();
  }
  void push_back(const T& v) {
    if (size_ < N) {
      in_place_[size_] = v;
    } else {
      if (size_ == N) heap_.assign(in_place_.begin(), in_place_.end());
      heap_.push_back(v);
    }
    ++size_;
  }
  template <typename... Args>
  void emplace_back(Args&&... args) {
    push_back(T{std::forward<Args>(args)...});
  }

  friend bool operator==(const InlineList& a, const InlineList& b) {
    if (a.size_ != b.size_) return false;
    for (std::size_t i = 0; i < a.size_; ++i)
      if (!(a[i] == b[i])) return false;
    return true;
  }

 private:
  std::array<T, N> in_place_{};
  std::vector<T> heap_;  // empty unless size_ > N
  std::size_t size_ = 0;
};

}  // namespace vern
