#include <array>

#include "entries.hpp"

namespace vern::fuzz {

std::span<const Target> targets() {
  static constexpr std::array<Target, 4> kTargets{{
      {"grammar_reader", grammar_reader},
      {"obj_loader", obj_loader},
      {"gltf_loader", gltf_loader},
      {"infer_layout", infer_layout},
  }};
  return kTargets;
}

}  // namespace vern::fuzz
