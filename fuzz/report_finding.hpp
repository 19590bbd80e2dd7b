// How a libFuzzer program reports a finding of an entry (entries.hpp): it
// prints it and aborts, which libFuzzer records as a crash and saves the
// input that caused it (scripts/fuzz saves it under fuzz/regressions/).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace vern::fuzz {

inline void report_finding(const std::string& finding) {
  if (finding.empty()) return;
  std::fprintf(stderr, "\n==== vern fuzz finding ====\n%s\n===========================\n", finding.c_str());
  std::abort();
}

}  // namespace vern::fuzz
