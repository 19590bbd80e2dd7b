#include "graph/value.hpp"

#include "base/number_format.hpp"

namespace vern {

const char* axis_name(Axis a) {
  switch (a) {
    case Axis::X: return "x";
    case Axis::Y: return "y";
    case Axis::Z: return "z";
  }
  return "?";
}

std::optional<Axis> Value::to_axis() const {
  if (is_axis()) return as_axis();
  if (number_ == 0.0 || number_ == 1.0 || number_ == 2.0) return static_cast<Axis>(static_cast<int>(number_));
  return std::nullopt;
}

std::string Value::describe() const {
  if (is_axis()) return std::string("axis ") + axis_name(as_axis());
  return format_number(number_);
}

}  // namespace vern
