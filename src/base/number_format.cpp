#include "base/number_format.hpp"

#include <charconv>

namespace vern {

void append_number(std::string& out, double v) {
  if (v == 0.0) v = 0.0;  // folds -0 into 0
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, end);
}

std::string format_number(double v) {
  std::string s;
  append_number(s, v);
  return s;
}

}  // namespace vern
