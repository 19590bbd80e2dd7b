#include "inverse/load/derived_example.hpp"

namespace vern {

Example example_from_derivation(const Derivation& d, std::string source) {
  Example ex;
  ex.source = std::move(source);
  ex.boxes.reserve(d.terminals.size());
  for (std::size_t i = 0; i < d.terminals.size(); ++i) {
    const Bounds b = world_bounds(d.terminals[i].scope);
    LabelledBox box;
    box.label = d.labels[d.terminals[i].label];
    box.min = b.min;
    box.max = b.max;
    box.object = box.label + "." + std::to_string(i);
    box.mesh = static_cast<std::uint32_t>(i);
    ex.boxes.push_back(std::move(box));
  }
  update_bounds(ex);
  return ex;
}

Example boxes_at_origin(const Example& example) {
  Example boxes;
  boxes.source = example.source;
  boxes.boxes = example.boxes;
  boxes.min = example.min;
  boxes.max = example.max;
  boxes.snapped = example.snapped;
  boxes.file_tolerance = example.file_tolerance;
  return at_origin(std::move(boxes));
}

Example at_origin(Example example) {
  const glm::dvec3 shift = example.min;
  for (LabelledBox& b : example.boxes) {
    b.min -= shift;
    b.max -= shift;
  }
  update_bounds(example);
  return example;
}

}  // namespace vern
