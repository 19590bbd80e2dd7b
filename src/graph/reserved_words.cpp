#include "graph/reserved_words.hpp"

#include <algorithm>
#include <array>

namespace vern {

bool is_operation_word(std::string_view s) {
  static constexpr std::array<std::string_view, 11> kWords{"split", "repeat", "repeatN", "I",      "nil",  "T",
                                                           "S",     "R",      "comp",    "colour", "color"};
  return std::find(kWords.begin(), kWords.end(), s) != kWords.end();
}

bool is_reserved_value_name(std::string_view s) {
  return s == "x" || s == "y" || s == "z" || s == "pi" || s == "rand" || is_operation_word(s);
}

bool is_rule_label(std::string_view s) {
  auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (s.empty() || !letter(s[0]) || is_operation_word(s)) return false;
  for (char c : s)
    if (!letter(c) && !(c >= '0' && c <= '9')) return false;
  return true;
}

}  // namespace vern
