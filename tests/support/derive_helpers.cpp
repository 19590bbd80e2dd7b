#include "support/derive_helpers.hpp"

#include <algorithm>
#include <filesystem>

namespace vern::test {

Derivation derive_text(const std::string& text, glm::dvec3 size, std::uint64_t seed) {
  const Grammar g = parse_grammar(text, "test.grm");
  DeriveOptions o;
  o.seed = seed;
  o.size = size;
  return derive(g, o);
}

std::vector<LabelledBox> boxes(const Derivation& d) {
  std::vector<LabelledBox> out;
  for (const auto& t : d.terminals) {
    const Bounds b = world_bounds(t.scope);
    out.push_back({d.labels[t.label], b.min, b.max});
  }
  return out;
}

std::vector<std::string> bundled_grammars() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(VERN_SOURCE_DIR "/data/grammars"))
    if (e.path().extension() == ".grm") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace vern::test
