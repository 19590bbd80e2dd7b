// libFuzzer program: a request body for serve through vern::fuzz::editor_request (entries/entries.hpp).
#include <cstddef>
#include <cstdint>

#include "entries/entries.hpp"
#include "report_finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vern::fuzz::report_finding(vern::fuzz::editor_request({data, size}));
  return 0;
}
