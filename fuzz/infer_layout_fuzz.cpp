// libFuzzer program: example layouts (entries/layout.hpp) through vern::fuzz::infer_layout (entries/entries.hpp).
#include <cstddef>
#include <cstdint>

#include "entries/entries.hpp"
#include "report_finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vern::fuzz::report_finding(vern::fuzz::infer_layout({data, size}));
  return 0;
}
