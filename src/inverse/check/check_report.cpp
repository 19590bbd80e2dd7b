// What the matcher reports (check_matcher.hpp): why the attempt that got
// furthest failed (Mismatch), kept as text only when it is the furthest so far, and the
// witness lines of a success.
#include "inverse/check/check_matcher.hpp"

#include <string>
#include <utility>
#include <vector>

#include "base/number_format.hpp"
#include "forward/rule_chain.hpp"

namespace vern::check_detail {

std::vector<MatchedPart> Matcher::matched_parts() const {
  std::vector<MatchedPart> out;
  for (const WitnessLine& w : witness_) {
    if (w.kind == WitnessLine::Kind::Part) out.push_back({w.path, w.node, w.index, w.length, w.value, w.spelled});
    // A repeat whose tile size draws: its tiles' length, as a part of one,
    // and their count as its value.
    if (w.kind == WitnessLine::Kind::Tiles && w.spelled && w.value > 0 && std::holds_alternative<Repeat>(g_.op(w.node)))
      out.push_back({w.path, w.node, 0, w.length, w.value, true});
  }
  return out;
}

std::vector<std::string> Matcher::witness() const {
  std::vector<std::string> out;
  out.reserve(witness_.size());
  for (const WitnessLine& w : witness_)
    if (w.spelled) out.push_back(witness_text(g_, w));
  return out;
}

std::vector<CheckStep> Matcher::steps() const {
  std::vector<CheckStep> out;
  for (const WitnessLine& w : witness_) {
    switch (w.kind) {
      case WitnessLine::Kind::Alternative: out.push_back({CheckStep::Kind::Alternative, w.node, w.index, 0, 0}); break;
      case WitnessLine::Kind::Value: out.push_back({CheckStep::Kind::Value, w.node, 0, w.value, 0}); break;
      case WitnessLine::Kind::Tiles: out.push_back({CheckStep::Kind::Tiles, w.node, 0, w.value, w.length}); break;
      case WitnessLine::Kind::Part:
        if (w.spelled) out.push_back({CheckStep::Kind::Part, w.node, w.index, w.value, w.length});
        break;
      case WitnessLine::Kind::NoAlternative: break;
    }
  }
  return out;
}

std::string Matcher::rule_label() const { return vars_.rule() == kNone ? "?" : g_.rules[vars_.rule()].label; }

WitnessLine Matcher::line(WitnessLine::Kind kind, NodeId node) const {
  WitnessLine w;
  w.kind = kind;
  w.rule = current_rule();
  w.node = node;
  return w;
}

void Matcher::note_value(NodeId node, const std::string& name, double v, const Origin& origin) {
  if (answer_only_) return;
  WitnessLine w = line(WitnessLine::Kind::Value, node);
  w.name = name;
  w.value = v;
  w.origin = origin;
  witness_.push_back(std::move(w));
}

std::string Matcher::where(NodeId id, const Scope& s) const {
  const Bounds b = world_bounds(s);
  std::string t = "at " + rule_label();
  if (vars_.rule() != kNone) t += " (" + loc_text(g_.rules[vars_.rule()].loc) + ")";
  return t + ", " + node_ref(id) + " on " + bounds_text(b.min, b.max);
}

std::string Matcher::list_boxes(const BoxList& list) const {
  std::string t;
  for (std::size_t k = 0; k < list.size() && k < 3; ++k) t += (k ? ", " : "") + box_text(boxes_[list[k]]);
  if (list.size() > 3) t += ", ... (" + std::to_string(list.size()) + " in all)";
  return t;
}

bool Matcher::fail(NodeId id, const Scope& s, const std::string& what) {
  if (quiet_ > 0) return false;
  if (here().further_than(best_)) best_ = {progress_, depth_, where(id, s) + ": " + what};
  return false;
}

bool Matcher::cannot_check(NodeId id, const Scope& s, const std::string& what) {
  if (quiet_ > 0) {
    open_ends_unsupported_ = true;
    return false;
  }
  if (uncheckable_.empty()) uncheckable_ = where(id, s) + ": " + what;
  return fail(id, s, "cannot check: " + what);
}

void Matcher::refuse(ErrorKind kind, SourceLoc loc, const std::string& message, const std::string& hint) const {
  throw Error(kind,
              format_message(g_.source_name, loc, message) + "\n  rule chain: " + rule_chain() + "\n  hint: " + hint);
}

std::string Matcher::rule_chain() const {
  const std::vector<Frame>& frames = vars_.frames();
  return rule_chain_text(
      g_, frames.size(), [&](std::size_t i) { return frames[i].rule; },
      [&](std::size_t i, std::size_t k) {
        if (k >= frames[i].params.size()) return std::string("?");
        const Slot& slot = frames[i].params[k];
        if (slot.unknown < 0) return slot.value.describe();
        // A random value the example has not pinned down (yet) has no value to name.
        const Unknown& u = vars_.unknown(slot.unknown);
        return u.value ? format_number(*u.value) : std::string("?");
      });
}

}  // namespace vern::check_detail
