// A list of closed intervals that holds one of them in place.
//
// Almost every support a check builds (support.hpp) is one interval: a
// length, a share, a single value. Kept in a std::vector, each took a heap
// block of its own, and clamping, uniting and adding supports made and
// freed them by the million (a quarter of all the allocations of inferring
// the city). Here the first interval lives inside the object; a second
// moves them all to the heap. Value semantics, as a vector's.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <utility>
#include <vector>

namespace vern {

class Intervals {
 public:
  using value_type = std::pair<double, double>;

  Intervals() = default;
  Intervals(std::initializer_list<value_type> list) {
    reserve(list.size());
    for (const value_type& v : list) push_back(v);
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  // One interval or none: in place; two or more: all on the heap.
  value_type* begin() { return size_ <= 1 ? &one_ : many_.data(); }
  value_type* end() { return begin() + size_; }
  const value_type* begin() const { return size_ <= 1 ? &one_ : many_.data(); }
  const value_type* end() const { return begin() + size_; }
  value_type& operator[](std::size_t i) { return begin()[i]; }
  const value_type& operator[](std::size_t i) const { return begin()[i]; }
  value_type& front() { return *begin(); }
  const value_type& front() const { return *begin(); }
  value_type& back() { return begin()[size_ - 1]; }
  const value_type& back() const { return begin()[size_ - 1]; }

  void reserve(std::size_t n) {
    if (n > 1) many_.reserve(n);
  }
  void clear() {
    size_ = 0;
    many_.clear();
  }
  void push_back(const value_type& v) {
    if (size_ == 0) {
      one_ = v;
    } else {
      if (size_ == 1) many_.push_back(one_);
      many_.push_back(v);
    }
    ++size_;
  }
  void emplace_back(double lo, double hi) { push_back({lo, hi}); }

  friend bool operator==(const Intervals& a, const Intervals& b) {
    if (a.size_ != b.size_) return false;
    for (std::size_t i = 0; i < a.size_; ++i)
      if (a[i] != b[i]) return false;
    return true;
  }

 private:
  value_type one_{0.0, 0.0};
  std::vector<value_type> many_;  // empty unless size_ >= 2
  std::size_t size_ = 0;
};

}  // namespace vern
