#include "inverse/check/check.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "forward/evaluate.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check_matcher.hpp"

namespace vern {

using namespace check_detail;

namespace {

// The random constants, tried value by value or left unknown, and a
// Matcher (check_matcher.hpp) per choice of them.

struct ConstantChoice {
  std::vector<Slot> slots;
  std::vector<Unknown> unknowns;
  std::vector<std::string> lines;  // "constant N = 9 (randint(8, 10))"
  std::string prefix;              // "with N = 9: " for mismatches
};

class Checker {
 public:
  Checker(const Grammar& g, const std::vector<LabelledBox>& boxes, double tol, double cut_tol, Budget& budget,
          const Scope& start, bool text, bool learned_order, bool answer_only)
      : g_(g),
        boxes_(boxes),
        tol_(tol),
        cut_tol_(cut_tol),
        budget_(budget),
        deterministic_(g),
        start_(start),
        text_(text),
        learned_order_(learned_order),
        answer_only_(answer_only) {
    for (std::size_t k = 0; k < boxes.size(); ++k) all_.push_back(static_cast<std::uint32_t>(k));
  }

  CheckResult run() {
    // First with every part ending on a box face, then also in empty space.
    for (bool floating : {false, true}) {
      floating_ = floating;
      ConstantChoice choice;
      constants(0, choice);
      if (found_) break;
    }
    CheckResult r;
    r.derivable = found_;
    if (found_) {
      r.witness = witness_;
      r.parts = parts_;
      r.steps = steps_;
    } else {
      r.mismatch = best_.message.empty() ? "the grammar does not derive the example" : best_.message;
      if (!uncheckable_.empty() && best_.message.find("cannot check") == std::string::npos)
        r.mismatch += "\n  note: some alternatives could not be checked: " + uncheckable_;
      if (open_ends_)
        r.mismatch +=
            "\n  note: some boundaries in empty space were not tried (they would move a repeat's tiles, "
            "a comp's faces or a split's start)";
    }
    return r;
  }

 private:
  // Evaluates constants in file order; few-valued random ones are tried
  // value by value (each a derivation of its own), continuous ones become
  // unknowns pinned down by their first use.
  void constants(std::size_t i, ConstantChoice& c) {
    if (found_) return;
    if (i == g_.constants.size()) return attempt(c);
    const Constant& k = g_.constants[i];
    const BindingLookup lookup = [&](ExprKind kind, std::uint32_t index) -> Binding {
      if (kind != ExprKind::Constant || index >= c.slots.size()) return {false, {}, Support::everything()};
      const Slot& s = c.slots[index];
      if (s.unknown < 0) return {true, s.value, {}};
      return {false, {}, c.unknowns[static_cast<std::size_t>(s.unknown)].support};
    };
    Possible p;
    try {
      p = possible_values(k.value, lookup);
    } catch (const EvaluationError& e) {
      return note({0, 0, "the constant '" + k.name + "' cannot be evaluated (" + e.message + "), so derive() fails"});
    } catch (const NotCheckable& e) {
      uncheckable_ = "the constant '" + k.name + "': " + e.message;
      return note({0, 0, "cannot check: the constant '" + k.name + "': " + e.message});
    }
    if (p.exact) {
      c.slots.push_back({p.value, -1});
      constants(i + 1, c);
      c.slots.pop_back();
      return;
    }
    if (auto values = p.support.values(kMaxEnumerated)) {
      for (double v : *values) {
        budget_.step();
        c.slots.push_back({Value(v), -1});
        c.lines.push_back("constant " + k.name + " = " + num(v) + " (" + write_expression(g_, k.value, {}) + ")");
        const std::string prefix = c.prefix;
        c.prefix += (prefix.empty() ? "with " : ", ") + k.name + " = " + num(v);
        constants(i + 1, c);
        c.prefix = prefix;
        c.lines.pop_back();
        c.slots.pop_back();
        if (found_) return;
      }
      return;
    }
    c.unknowns.push_back({p.support, std::nullopt, k.name, Origin{&k.value, kNone, kNone}});
    c.slots.push_back({Value(), static_cast<int>(c.unknowns.size() - 1)});
    constants(i + 1, c);
    c.slots.pop_back();
    c.unknowns.pop_back();
  }

  void attempt(const ConstantChoice& c) {
    Matcher m(g_, boxes_, tol_, cut_tol_, budget_, deterministic_, c.slots, c.unknowns, floating_, learned_order_,
              answer_only_);
    if (m.run(start_, all_)) {
      found_ = true;
      if (answer_only_) return;
      // The first line says what was matched, so even a grammar without
      // choices has a witness.
      parts_ = m.matched_parts();
      steps_ = m.steps();
      if (!text_) return;
      witness_ = {"start: " + g_.rules[g_.start_rule].label + " on " + bounds_text(start_.origin, start_.size) + ", " +
                  std::to_string(boxes_.size()) + " boxes"};
      witness_.insert(witness_.end(), c.lines.begin(), c.lines.end());
      const std::vector<std::string> lines = m.witness();
      witness_.insert(witness_.end(), lines.begin(), lines.end());
      return;
    }
    Mismatch mm = m.mismatch();
    if (!c.prefix.empty()) mm.message = c.prefix + ": " + mm.message;
    note(mm);
    if (uncheckable_.empty()) uncheckable_ = m.uncheckable();
    open_ends_ = open_ends_ || m.open_ends_unsupported();
  }

  void note(const Mismatch& m) {
    if (m.further_than(best_)) best_ = m;
  }

  const Grammar& g_;
  const std::vector<LabelledBox>& boxes_;
  double tol_;
  double cut_tol_;  // CheckOptions::cut_tolerance
  Budget& budget_;
  DeterministicSubtrees deterministic_;
  Scope start_;
  BoxList all_;
  bool found_ = false;
  std::vector<std::string> witness_;
  std::vector<MatchedPart> parts_;
  std::vector<CheckStep> steps_;
  bool text_ = true;  // spell the witness out
  bool learned_order_ = false;
  bool answer_only_ = false;
  Mismatch best_;
  std::string uncheckable_;
  bool open_ends_ = false;
  bool floating_ = false;
};

}  // namespace

CheckResult check_example(const Grammar& grammar, const std::vector<LabelledBox>& boxes, glm::dvec3 scope_size,
                          const CheckOptions& options) {
  double tol = options.tolerance;
  if (!(tol > 0)) {
    glm::dvec3 lo(kInf), hi(-kInf);
    for (const auto& b : boxes) {
      lo = glm::min(lo, b.min);
      hi = glm::max(hi, b.max);
    }
    tol = boxes.empty() ? default_tolerance(glm::dvec3(0), scope_size) : default_tolerance(lo, hi);
    if (!(tol > 0)) tol = 1e-9;
  }
  Scope start;
  start.size = scope_size;
  CheckResult r;
  if (grammar.rules.empty()) {
    r.derivable = boxes.empty();
    if (!r.derivable) r.mismatch = "the grammar has no rules, so it derives nothing, but the example has boxes";
    return r;
  }
  Budget budget(options.max_steps);
  const double cut_tol = options.cut_tolerance > 0 ? std::min(options.cut_tolerance, tol) : tol;
  return Checker(grammar, boxes, tol, cut_tol, budget, start, options.witness && !options.answer_only, options.learned_order,
                 options.answer_only)
      .run();
}

}  // namespace vern
