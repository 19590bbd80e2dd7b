// The values a grammar computes with: numbers and axes.
//
// Booleans are numbers (0 is false). An axis is x, y or z; where an axis is
// expected, the numbers 0, 1 and 2 are accepted too (docs/grammar.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace vern {

enum class Axis : std::uint8_t { X = 0, Y = 1, Z = 2 };

const char* axis_name(Axis a);

class Value {
 public:
  constexpr Value() = default;
  constexpr Value(double number) : number_(number) {}  // NOLINT: numbers convert implicitly
  static constexpr Value axis(Axis a) {
    Value v;
    v.axis_ = static_cast<std::int8_t>(a);
    v.number_ = static_cast<double>(a);
    return v;
  }

  bool is_axis() const { return axis_ >= 0; }
  bool is_number() const { return axis_ < 0; }
  double number() const { return number_; }
  Axis as_axis() const { return static_cast<Axis>(axis_); }

  // The axis this value names: an axis, or one of the numbers 0, 1, 2.
  std::optional<Axis> to_axis() const;

  // "3.5" or "axis y": for messages.
  std::string describe() const;

  friend bool operator==(const Value& a, const Value& b) {
    return a.axis_ == b.axis_ && a.number_ == b.number_;
  }

 private:
  double number_ = 0.0;
  std::int8_t axis_ = -1;
};

}  // namespace vern
