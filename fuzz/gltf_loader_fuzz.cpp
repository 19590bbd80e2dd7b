// libFuzzer program: glTF or GLB bytes through vern::fuzz::gltf_loader (entries/entries.hpp).
#include <cstddef>
#include <cstdint>

#include "entries/entries.hpp"
#include "report_finding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vern::fuzz::report_finding(vern::fuzz::gltf_loader({data, size}));
  return 0;
}
