// libFuzzer program: a folder tree through vern::fuzz::indirect_inputs (entries/entries.hpp).
#include <cstddef>
#include <cstdint>

#include "entries/entries.hpp"
#include "report_finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vern::fuzz::report_finding(vern::fuzz::indirect_inputs({data, size}));
  return 0;
}
