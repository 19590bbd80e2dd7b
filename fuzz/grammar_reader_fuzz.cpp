// libFuzzer program: grammar text through vern::fuzz::grammar_reader (entries/entries.hpp).
#include <cstddef>
#include <cstdint>

#include "entries/entries.hpp"
#include "report_finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vern::fuzz::report_finding(vern::fuzz::grammar_reader({data, size}));
  return 0;
}
