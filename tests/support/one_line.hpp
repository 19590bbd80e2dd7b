// A grammar's text on one line, for tests that look for a rule in it.
#pragma once

#include <string>

namespace vern::test {

// Runs of white space (spaces, newlines) as one space.
inline std::string one_line(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const bool space = c == ' ' || c == '\n';
    if (!(space && !out.empty() && out.back() == ' ')) out += space ? ' ' : c;
  }
  return out;
}

}  // namespace vern::test
