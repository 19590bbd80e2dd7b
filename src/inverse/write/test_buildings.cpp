#include "inverse/write/test_buildings.hpp"

#include <cstdio>

#include "base/error.hpp"
#include "forward/layout_faults.hpp"
#include "forward/program.hpp"

namespace vern {

namespace {

// "error: more than 1000000 terminals in one derivation\n  rule chain: ..."
// -> "more than 1000000 terminals in one derivation".
std::string first_line(const std::string& message) {
  std::string line = message.substr(0, message.find('\n'));
  const std::string tag = "error: ";
  if (const auto at = line.find(tag); at != std::string::npos) line.erase(0, at + tag.size());
  return line;
}

// Metres to the centimetre: the scope's sizes are drawn, not written.
std::string metres(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", v);
  return text;
}

}  // namespace

std::vector<std::string> derive_test_buildings(const Grammar& grammar, const TestBuildingsOptions& options) {
  const Program program = compile(grammar);
  // Broken layouts are looked for where the buildings are small enough to
  // keep (a million-part city is only counted).
  const bool judge = options.example_parts <= kJudgedParts;
  std::uint32_t broken = 0;
  std::string first_broken;
  for (std::uint32_t i = 0; i < options.count; ++i) {
    DeriveOptions o;
    o.seed = options.first_seed + i;
    o.limits = options.limits;
    o.keep_terminals = judge;
    try {
      const Derivation d = derive(program, o);
      if (judge) {
        const LayoutFaults faults = find_faults(d);
        if (!faults.valid() && broken++ == 0) first_broken = "seed " + std::to_string(o.seed) + ": " + faults.first;
      }
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::Limit) throw;
      const glm::dvec3 size = derive_start_size(program, o);
      return {"infer: warning: the test building of seed " + std::to_string(o.seed) + " (scope " +
              metres(size.x) + " x " + metres(size.y) + " x " + metres(size.z) +
              " m) stops at a limit: " + first_line(e.what()) + "; the largest example has " +
              std::to_string(options.example_parts) + " part" + (options.example_parts == 1 ? "" : "s") +
              "\n  hint: the grammar derives every example, but @scope reaches sizes that no example with "
              "these parts had; generate with --scope near the examples' sizes, or raise that limit (generate --max-terminals, "
              "--max-depth, --max-operations)"};
    }
  }
  if (broken > 0) {
    return {"infer: warning: " + std::to_string(broken) + " of " + std::to_string(options.count) +
            " test buildings have overlapping parts or parts outside their plot (" + first_broken +
            ")\n  hint: the grammar derives every example, but its variants are not all sound; please report "
            "this with the examples"};
  }
  return {};
}

TestBuildingsOptions test_buildings_for(std::size_t parts, std::size_t largest, std::uint64_t first_seed) {
  TestBuildingsOptions tests;
  tests.first_seed = first_seed;
  tests.count = parts > kJudgedParts ? 1 : 8;
  tests.example_parts = largest;
  return tests;
}

}  // namespace vern
