// The witness of a check (CheckResult::witness): the choices and random
// values that make the grammar derive the example, one line each.
//
// Lines are kept as data while matching and spelled out only once the
// example turns out derivable: most attempts fail, and their text would
// cost more than the attempt.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "graph/grammar.hpp"
#include "inverse/check/check_text.hpp"

namespace vern::check_detail {

// Where a random value was drawn.
struct Origin {
  const Expr* expr = nullptr;  // the argument or constant drawn
  RuleId rule = kNone;         // whose parameter names `expr` uses (kNone: a constant)
  NodeId call = kNone;         // the call that drew it (kNone: a constant)
};

struct WitnessLine {
  enum class Kind : std::uint8_t { Alternative, NoAlternative, Value, Part, Tiles };
  Kind kind = Kind::Value;
  RuleId rule = 0;                   // the rule running
  NodeId node = 0;                   // the operation
  std::size_t index = 0, count = 0;  // alternative index of count; part index
  double value = 0, size = 0;        // the value; Tiles: the count and a tile size (0: repeatN)
  double length = 0;                 // Part: its length in metres
  std::uint64_t path = 0;            // Part, Tiles: the split's or repeat's derivation_path
  std::string name;                  // Value: the parameter or constant
  Origin origin;                     // Value: what drew it
  bool spelled = true;               // false: data only (a repeat whose count no draw chose)
};

// "plot: alternative 2 of 2 (split(x) at 24:10)",
// "garage, split(z) at 26:12, part 1: 1.04 (~rand(0.75, 1.25))", ...
std::string witness_text(const Grammar& g, const WitnessLine& w);

}  // namespace vern::check_detail
