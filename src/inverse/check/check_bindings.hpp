// What the names in a grammar's expressions stand for while checking
// (check.hpp): parameters and constants, known values or unknowns.
//
// An unknown is a random value the example has not pinned down yet (a
// continuous rand() passed as an argument or drawn for a constant). The
// first split whose sizes use it solves for it and binds it; a failed
// attempt must take that back, so every binding goes on a trail that
// undo() unwinds to a mark, the way a search backtracks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/check/check_text.hpp"
#include "inverse/check/check_witness.hpp"
#include "inverse/sizes/support.hpp"

namespace vern::check_detail {

// A parameter or constant: a known value, or unknown number `unknown`.
struct Slot {
  Value value;
  int unknown = -1;
};

struct Unknown {
  Support support;
  std::optional<double> value;  // once an operation pinned it down
  std::string name;             // the parameter or constant
  Origin origin;
};

// A running rule and its arguments.
struct Frame {
  RuleId rule = 0;
  std::vector<Slot> params;
};

class Bindings {
 public:
  Bindings(std::vector<Slot> constants, std::vector<Unknown> unknowns)
      : constants_(std::move(constants)), unknowns_(std::move(unknowns)) {}

  // A name of the running rule (Param) or a constant, for possible_values().
  Binding binding(ExprKind kind, std::uint32_t index) const {
    const Slot& slot = kind == ExprKind::Param ? param(index) : constant(index);
    if (slot.unknown < 0) return {true, slot.value, {}};
    const Unknown& u = unknowns_[static_cast<std::size_t>(slot.unknown)];
    if (u.value) return {true, Value(*u.value), {}};
    return {false, {}, u.support};
  }
  const Slot& param(std::uint32_t index) const { return frames_.back().params.at(index); }
  const Slot& constant(std::uint32_t index) const { return constants_.at(index); }

  // The unknowns an expression uses that nothing has pinned down yet,
  // added to `out` (each once).
  void open_unknowns(const Expr& e, std::vector<int>& out) const;

  // ---- the rules running, innermost last ----
  void enter(const Frame& frame) { frames_.push_back(frame); }
  void leave() { frames_.pop_back(); }
  std::size_t depth() const { return frames_.size(); }
  const std::vector<Frame>& frames() const { return frames_; }
  // The running rule, kNone before the start rule runs.
  RuleId rule() const { return frames_.empty() ? kNone : frames_.back().rule; }

  // ---- unknowns ----
  Unknown& unknown(int u) { return unknowns_[static_cast<std::size_t>(u)]; }
  const Unknown& unknown(int u) const { return unknowns_[static_cast<std::size_t>(u)]; }
  // A new unknown; its number for a Slot.
  int add(Unknown u) {
    unknowns_.push_back(std::move(u));
    return static_cast<int>(unknowns_.size() - 1);
  }
  std::size_t unknown_count() const { return unknowns_.size(); }
  // Forgets the unknowns from number `count` on (drawn inside a call that
  // is over), and their bindings.
  void drop_unknowns(std::size_t count);

  // ---- the trail ----
  void bind(int u, double v) {
    trail_.emplace_back(u, unknowns_[static_cast<std::size_t>(u)].value);
    unknowns_[static_cast<std::size_t>(u)].value = v;
  }
  std::size_t trail_size() const { return trail_.size(); }
  // Takes back every binding since the trail was `mark` long.
  void undo(std::size_t mark) {
    while (trail_.size() > mark) {
      unknowns_[static_cast<std::size_t>(trail_.back().first)].value = trail_.back().second;
      trail_.pop_back();
    }
  }

 private:
  std::vector<Slot> constants_;
  std::vector<Unknown> unknowns_;
  std::vector<std::pair<int, std::optional<double>>> trail_;  // unknown, its value before
  std::vector<Frame> frames_;
};

}  // namespace vern::check_detail
