#include "inverse/sizes/progressions.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "forward/evaluate.hpp"
#include "graph/nodes_below.hpp"
#include "graph/structural.hpp"
#include "inverse/check/derives_examples.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/sizes/linear_size.hpp"
#include "inverse/sizes/tidy_numbers.hpp"
#include "inverse/write/rule_naming.hpp"
#include "inverse/write/unused_rules.hpp"

namespace vern {

namespace {

constexpr RuleId kNoRule = ~RuleId{0};
constexpr NodeId kNoNode = ~NodeId{0};

// A size in a rule's one parameter as a + b s, if it is a straight line.
std::optional<std::pair<double, double>> line_in_parameter(const Expr& e) {
  auto at = [&](double s) -> std::optional<double> {
    const Value param(s);
    try {
      return evaluate_number(e, EvalContext{&param, nullptr, nullptr}, "a size");
    } catch (...) {
      return std::nullopt;
    }
  };
  const auto f0 = at(0), f1 = at(1), f2 = at(2);
  if (!f0 || !f1 || !f2) return std::nullopt;
  const double a = *f0, b = *f1 - *f0;
  if (std::abs(*f2 - (a + 2 * b)) > 1e-9 * std::max(1.0, std::abs(*f2))) return std::nullopt;
  return std::pair{a, b};
}

// The tiles of a repeat as one family of tiles in one value: calls of
// one rule T(v), or one split whose one drawn part takes the value (the
// air above a house); and options that are the family at some value,
// where parts of it vanish (the highest house, with no air above).
struct Family {
  NodeId choose = 0;
  RuleId t = kNoRule;          // calls of T(v), or
  NodeId split = kNoNode;      // a split with one drawn relative part
  std::size_t drawn = 0;       //   that part
  std::vector<std::optional<double>> fixed;  // per option: the value it stands for; nullopt: drawn
};

// The value at which `family_body` (a split whose relative sizes are
// straight lines in one parameter) is `other`, the parts that vanish
// there left out.
std::optional<double> value_of(const Grammar& g, const Split& body, NodeId other) {
  // A node that is no split is a split of one part: all others vanished.
  const auto* as_split = std::get_if<Split>(&g.op(other));
  const Split alone{body.axis, {SplitPart{Size{Expr::number(1), true}, other}}};
  const Split* split = as_split && as_split->axis == body.axis ? as_split : &alone;
  if (split->parts.size() >= body.parts.size()) return std::nullopt;
  std::vector<std::pair<double, double>> lines;
  for (const SplitPart& p : body.parts) {
    if (!p.size.relative) return std::nullopt;
    const auto l = line_in_parameter(p.size.value);
    if (!l) return std::nullopt;
    lines.push_back(*l);
  }
  for (std::size_t vanish = 0; vanish < lines.size(); ++vanish) {
    const auto [a, b] = lines[vanish];
    if (b == 0) continue;
    const double v = -a / b;
    std::vector<double> left, others;
    std::size_t k = 0;
    bool same = true;
    for (std::size_t i = 0; i < lines.size() && same; ++i) {
      const double size = lines[i].first + lines[i].second * v;
      if (std::abs(size) <= 1e-9 * (1 + std::abs(lines[i].first))) continue;
      if (k >= split->parts.size() || !structurally_equal(g, body.parts[i].child, g, split->parts[k].child)) {
        same = false;
        break;
      }
      const auto o = split->parts[k].size.value.literal();
      if (!o || !split->parts[k].size.relative) same = false;
      left.push_back(size);
      others.push_back(o.value_or(0));
      ++k;
    }
    if (!same || k != split->parts.size()) continue;
    double tl = 0, to = 0;
    for (std::size_t i = 0; i < left.size(); ++i) {
      tl += left[i];
      to += others[i];
    }
    bool proportional = tl > 0 && to > 0;
    for (std::size_t i = 0; i < left.size() && proportional; ++i)
      proportional = std::abs(left[i] / tl - others[i] / to) <= 1e-6;
    if (proportional) return v;
  }
  return std::nullopt;
}

// The split of a family of one drawn part with that part's size the
// parameter itself (the reading the steps give values in).
Split with_parameter(const Split& s, std::size_t drawn) {
  Split out = s;
  out.parts[drawn].size = Size{Expr::param(0), true};
  return out;
}

std::optional<Family> family_of(const Grammar& g, const Repeat& r) {
  NodeId c = r.child;
  if (const auto* call = std::get_if<Call>(&g.op(c)); call && call->args.empty()) c = g.rules[call->rule].body;
  const auto* choose = std::get_if<Choose>(&g.op(c));
  if (!choose) return std::nullopt;
  Family f;
  f.choose = c;
  std::vector<bool> member(choose->options.size(), false);
  for (std::size_t i = 0; i < choose->options.size(); ++i) {
    const NodeId o = choose->options[i].child;
    if (const auto* call = std::get_if<Call>(&g.op(o));
        call && call->args.size() == 1 && g.rules[call->rule].params.size() == 1 && !call->args[0].uses_params()) {
      if ((f.t != kNoRule && f.t != call->rule) || f.split != kNoNode) return std::nullopt;
      f.t = call->rule;
      member[i] = true;
    } else if (const auto* split = std::get_if<Split>(&g.op(o))) {
      std::vector<std::size_t> drawn;
      bool literal = true;
      for (std::size_t k = 0; k < split->parts.size(); ++k) {
        if (split->parts[k].size.value.draws_random() && split->parts[k].size.relative) drawn.push_back(k);
        else literal = literal && split->parts[k].size.value.literal().has_value();
      }
      if (drawn.size() != 1 || !literal) continue;
      if (f.t != kNoRule || (f.split != kNoNode && !structurally_equal(g, o, g, f.split) &&
                             std::get<Split>(g.op(f.split)).parts.size() != split->parts.size()))
        return std::nullopt;
      f.split = o;
      f.drawn = drawn.front();
      member[i] = true;
    }
  }
  if (f.t == kNoRule && f.split == kNoNode) return std::nullopt;
  const Split body =
      f.t != kNoRule ? std::get<Split>(g.op(g.rules[f.t].body)) : with_parameter(std::get<Split>(g.op(f.split)), f.drawn);
  if (f.t != kNoRule && !std::holds_alternative<Split>(g.op(g.rules[f.t].body))) return std::nullopt;
  for (std::size_t i = 0; i < choose->options.size(); ++i) {
    if (member[i]) {
      f.fixed.push_back(std::nullopt);
      continue;
    }
    f.fixed.push_back(value_of(g, body, choose->options[i].child));
    if (!f.fixed.back()) return std::nullopt;
  }
  return f;
}

// One run of the repeat in one example: its tiles' values, its tile length.
struct Run {
  std::vector<double> values;
  double tile = 0;
};

// The runs of repeat `id` in a derivation's steps, or none where a tile's
// value cannot be read.
std::optional<std::vector<Run>> runs_of(const std::vector<CheckStep>& steps, NodeId id, const Family& f) {
  std::vector<Run> runs;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i].kind != CheckStep::Kind::Tiles || steps[i].node != id) continue;
    Run run;
    run.tile = steps[i].length;
    const auto n = static_cast<std::size_t>(steps[i].value);
    std::size_t j = i + 1;
    while (run.values.size() < n && j < steps.size()) {
      if (steps[j].kind != CheckStep::Kind::Alternative || steps[j].node != f.choose) {
        ++j;
        continue;
      }
      const std::size_t option = steps[j].index;
      if (option >= f.fixed.size()) return std::nullopt;
      if (f.fixed[option]) {
        run.values.push_back(*f.fixed[option]);
        ++j;
        continue;
      }
      // The value drawn in the tile: T's parameter pinned down, or the
      // family split's drawn part.
      std::size_t k = j + 1;
      while (k < steps.size() &&
             !(f.t != kNoRule ? steps[k].kind == CheckStep::Kind::Value
                              : steps[k].kind == CheckStep::Kind::Part && steps[k].index == f.drawn))
        ++k;
      if (k == steps.size()) return std::nullopt;
      run.values.push_back(steps[k].value);
      j = k + 1;
    }
    if (run.values.size() != n) return std::nullopt;
    runs.push_back(std::move(run));
  }
  return runs;
}

// A reading of a family's value: the value itself, or for a split of one
// drawn part of weight v beside parts weighing F in all, the share of the
// rest, F / (F + v) (a house's height, where v is the air above it), or
// the drawn part's own share, v / (F + v).
enum class Reading { Value, RestShare, OwnShare };

double read(Reading r, double v, double rest) {
  switch (r) {
    case Reading::Value: return v;
    case Reading::RestShare: return rest / (rest + v);
    case Reading::OwnShare: return v / (rest + v);
  }
  return v;
}

// One first value and one step, ratio or difference, for every run.
struct Progression {
  double first = 0, step = 0;
  bool geometric = true;
  double tile = 0;
};

std::optional<Progression> progression_of(const std::vector<Run>& runs, double tolerance) {
  std::size_t steps = 0;
  for (const Run& r : runs) steps += r.values.size() > 1 ? r.values.size() - 1 : 0;
  if (runs.empty() || steps < 3) return std::nullopt;
  // Values read back from examples carry their rounding (a tenth of a
  // millimetre in ten metres); the guard after checks the whole grammar.
  auto close = [](double a, double b) { return std::abs(a - b) <= 1e-4 * std::max(std::abs(a), std::abs(b)); };
  for (const bool geometric : {true, false}) {
    std::optional<double> step;
    bool holds = true;
    const double first = runs.front().values.front();
    for (const Run& r : runs) {
      holds = holds && close(r.values.front(), first) && std::abs(r.tile - runs.front().tile) <= tolerance;
      for (std::size_t i = 1; i < r.values.size() && holds; ++i) {
        if (geometric && r.values[i - 1] == 0) holds = false;
        if (!holds) break;
        const double s = geometric ? r.values[i] / r.values[i - 1] : r.values[i] - r.values[i - 1];
        if (!step) step = s;
        else holds = close(s, *step);
      }
    }
    if (holds && step && !close(*step, geometric ? 1.0 : 0.0))
      return Progression{first, *step, geometric, runs.front().tile};
  }
  return std::nullopt;
}

}  // namespace

std::size_t fold_progressions(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options) {
  // Repeats of one family of tiles, before checking: most grammars have
  // none, and checking every example is most of this step's time.
  std::vector<std::pair<NodeId, Family>> repeats;
  for (const NodeId id : nodes_of_rules(g))
    if (const auto* r = std::get_if<Repeat>(&g.op(id)); r && r->size.literal())
      if (auto f = family_of(g, *r)) repeats.emplace_back(id, std::move(*f));
  if (repeats.empty()) return 0;
  std::vector<CheckResult> results;
  if (!derives_examples(g, examples, options, results)) return 0;

  const Grammar before = g;
  std::size_t folded = 0;
  for (const auto& [id, family] : repeats) {
    const Repeat repeat = std::get<Repeat>(g.op(id));
    const Family* f = &family;
    std::vector<Run> runs;
    bool found = true;
    for (const CheckResult& r : results) {
      const auto more = runs_of(r.steps, id, *f);
      if (!more) {
        found = false;
        break;
      }
      runs.insert(runs.end(), more->begin(), more->end());
    }
    if (!found) continue;
    // The family's body in the parameter of the reading that progresses.
    double rest = 0;
    if (f->split != kNoNode)
      for (std::size_t k = 0; k < std::get<Split>(g.op(f->split)).parts.size(); ++k)
        if (k != f->drawn) rest += *std::get<Split>(g.op(f->split)).parts[k].size.value.literal();
    std::optional<Progression> p;
    Reading reading = Reading::Value;
    for (const Reading r : {Reading::Value, Reading::RestShare, Reading::OwnShare}) {
      if (r != Reading::Value && f->split == kNoNode) break;
      std::vector<Run> read_runs = runs;
      for (Run& run : read_runs)
        for (double& v : run.values) v = read(r, v, rest);
      if ((p = progression_of(read_runs, options.tolerance))) {
        reading = r;
        break;
      }
    }
    if (!p) continue;
    // The tile as a rule of the reading's parameter.
    RuleId tile = f->t;
    if (tile == kNoRule) {
      Split body = std::get<Split>(g.op(f->split));
      Linear own, others;  // the drawn part's weight, the others' factor
      switch (reading) {
        case Reading::Value: own.add(0, 1); others.c0 = 1; break;
        case Reading::RestShare: own.c0 = rest; own.add(0, -rest); others.add(0, 1); break;
        case Reading::OwnShare: own.add(0, rest); others.c0 = 1; others.add(0, -1); break;
      }
      for (std::size_t k = 0; k < body.parts.size(); ++k) {
        if (k == f->drawn) {
          body.parts[k].size = Size{linear_expr(own), true};
        } else if (reading != Reading::Value) {
          Linear part = others;
          const double w = *body.parts[k].size.value.literal();
          part.c0 *= w;
          for (double& c : part.c) c *= w;
          body.parts[k].size = Size{linear_expr(part), true};
        }
      }
      tile = static_cast<RuleId>(g.rules.size());
      g.rules.push_back(Rule{free_label(g, node_name(g, f->split)), {"s1"}, 0, g.node(f->split).loc});
      g.rules[tile].body = g.intern({std::move(body), g.node(f->split).loc});
    }
    // row(s1) --> split(axis){ t : tile(s1) | ~1 : row(next s1) }
    const RuleId row = static_cast<RuleId>(g.rules.size());
    g.rules.push_back(Rule{free_label(g, g.rules[tile].label + "Row"), {"s1"}, 0, g.rules[tile].loc});
    Linear next;
    if (p->geometric) {
      // Rounded as the values were read: the guard checks what it makes.
      next.add(0, shortest_decimal(p->step, 1e-5 * std::abs(p->step)));
    } else {
      next.add(0, 1);
      next.c0 = shortest_decimal(p->step, options.tolerance / 4);
    }
    Split split;
    split.axis = repeat.axis;
    split.parts.push_back({Size{Expr::number(shortest_decimal(p->tile, options.tolerance / 4)), false},
                           g.intern({Call{tile, {Expr::param(0)}}, {}})});
    split.parts.push_back({Size{Expr::number(1), true}, g.intern({Call{row, {linear_expr(next)}}, {}})});
    g.rules[row].body = g.intern({std::move(split), g.node(id).loc});
    const NodeId call =
        g.intern({Call{row, {Expr::number(shortest_decimal(p->first, 1e-5 * std::abs(p->first)))}}, g.node(id).loc});
    std::vector<NodeId> replace(g.node_count(), kNoReplacement);
    replace[id] = call;
    for (Rule& r : g.rules) r.body = substitute_until_settled(g, r.body, replace);
    ++folded;
  }
  if (folded == 0) return 0;
  drop_unused_rules(g);
  if (!derives_examples(g, examples, options, results)) {
    g = before;
    return 0;
  }
  return folded;
}

}  // namespace vern
