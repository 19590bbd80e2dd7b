#include <array>

#include "entries.hpp"

namespace vern::fuzz {

std::span<const Target> targets() {
  static constexpr std::array<Target, 6> kTargets{{
      {"grammar_reader", grammar_reader},
      {"obj_loader", obj_loader},
      {"gltf_loader", gltf_loader},
      {"infer_layout", infer_layout},
      {"indirect_inputs", indirect_inputs},
      {"editor_request", editor_request},
  }};
  return kTargets;
}

}  // namespace vern::fuzz
