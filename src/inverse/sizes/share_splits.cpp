#include "inverse/sizes/share_splits.hpp"

#include <algorithm>
#include <iterator>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "base/parallel_for.hpp"
#include "graph/nodes_below.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/sizes/fit_distribution.hpp"
#include "inverse/sizes/linear_size.hpp"
#include "inverse/sizes/tidy_numbers.hpp"
#include "inverse/write/rule_naming.hpp"

namespace vern {

namespace {

// How many parameters of the rule it is written in a node and the nodes
// below it read (calls not entered): 1 + the highest index. A split deep
// in a counted recursion, nest(n), holds the call nest(n - 1): the rule it
// becomes takes n on, before its share.
std::size_t params_read_below(const Grammar& g, NodeId id, std::unordered_map<NodeId, std::size_t>& memo) {
  if (const auto known = memo.find(id); known != memo.end()) return known->second;
  const Operation& op = g.op(id);
  std::size_t out = 0;
  for (const Expr* e : node_expressions(op)) out = std::max(out, e->params_read());
  if (!std::holds_alternative<Call>(op))
    for_each_child(op, [&](NodeId c) { out = std::max(out, params_read_below(g, c, memo)); });
  memo[id] = out;
  return out;
}

// The rule each node is written in (first rule by id that holds it, calls
// not entered): where the names of the parameters it reads come from.
std::unordered_map<NodeId, RuleId> rules_written_in(const Grammar& g) {
  std::unordered_map<NodeId, RuleId> out;
  for (RuleId r = 0; r < g.rules.size(); ++r)
    for (const NodeId id : nodes_below(g, g.rules[r].body)) out.emplace(id, r);
  return out;
}

// The lines of one run of a split (a repeat runs it once per tile, on one
// path): each starts where the part index does not go up.
struct SplitRun {
  NodeId split = 0;
  std::vector<const MatchedPart*> parts;
};

std::vector<SplitRun> runs_of(const std::vector<MatchedPart>& parts) {
  std::vector<SplitRun> out;
  for (const MatchedPart& m : parts) {
    if (out.empty() || out.back().split != m.split || out.back().parts.back()->path != m.path ||
        out.back().parts.back()->part >= m.part)
      out.push_back({m.split, {}});
    out.back().parts.push_back(&m);
  }
  return out;
}

// The parts of a split whose sizes share one draw, where two or more draw
// and nothing uses a parameter: its relative parts, with the sum of the
// shares written as numbers among them (0 when all draw); else its
// lengths in metres that draw (a window pair's casements and mullion
// drawn apart, `rand(0.42, 0.54) : casement | rand(0.17, 0.22) : wall |
// ...`, where every bay shows them in one proportion).
struct DrawnShares {
  std::vector<std::size_t> parts;
  double fixed = 0;
  bool metres = false;
};

std::optional<DrawnShares> drawn_shares(const Split& s) {
  DrawnShares shares, metres;
  std::size_t drawing = 0;
  bool numbers_only = true;
  for (std::size_t i = 0; i < s.parts.size(); ++i) {
    const Expr& size = s.parts[i].size.value;
    if (size.uses_params()) return std::nullopt;
    if (!s.parts[i].size.relative) {
      if (size.draws_random()) metres.parts.push_back(i);
      continue;
    }
    shares.parts.push_back(i);
    if (size.draws_random()) {
      ++drawing;
    } else if (const auto v = size.literal()) {
      shares.fixed += *v;
    } else {
      numbers_only = false;
    }
  }
  if (drawing >= 2 && numbers_only) return shares;
  if (metres.parts.size() < 2) return std::nullopt;
  metres.metres = true;
  return metres;
}

// Each of columns[0, count) as a constant or a straight line (within
// `tol`) of the first that varies, s1 (index 0), which may lead only where
// may_lead(its values) says so. None when nothing varies, or one varies
// apart from s1: check() pins down one parameter per split.
template <class MayLead>
std::optional<std::vector<Linear>> lines_of_first(const std::vector<std::vector<double>>& columns, std::size_t count,
                                                  double tol, MayLead may_lead) {
  std::vector<Linear> out(columns.size());
  std::optional<std::size_t> leader;
  for (std::size_t j = 0; j < count; ++j) {
    const auto [lo, hi] = std::ranges::minmax(columns[j]);
    if (hi - lo <= tol) {
      out[j].c0 = shortest_decimal((lo + hi) / 2, tol / 4);
      continue;
    }
    if (!leader) {
      if (!may_lead(columns[j])) return std::nullopt;
      leader = j;
      out[j].add(0, 1);
      continue;
    }
    if (!shows_a_line(columns[*leader], tol)) return std::nullopt;
    Fit f = line_fit(columns[*leader], columns[j]);
    f.worst = worst_miss(columns[*leader], columns[j], f.a, f.b);
    if (f.worst > tol / 4) return std::nullopt;
    const Fit s = short_line(columns[*leader], columns[j], f, tol / 4);
    out[j].c0 = s.a;
    out[j].add(0, s.b);
  }
  if (!leader) return std::nullopt;
  return out;
}

// The shares of one split, as lines in one parameter s1: the first share
// that varies is s1, the others constants or straight-line functions of
// it (the two equal insets around a tier: s1 and s1), the last the rest.
// Where some shares are numbers (`fixed`), those set the scale and no part
// is the rest: each is a line of s1 or a constant (a bay's two piers
// drawn once, `~s1 : pier | ~0.84 : window | ~s1 : pier`).
std::optional<std::vector<Linear>> share_lines(const std::vector<std::vector<double>>& shares, double total,
                                               bool fixed, double tol) {
  const std::size_t k = shares.size();
  const auto any = [](const std::vector<double>&) { return true; };
  if (fixed) return lines_of_first(shares, k, tol, any);
  auto out = lines_of_first(shares, k - 1, tol, any);
  if (!out) return std::nullopt;  // nothing varies: no draw to share
  (*out)[k - 1].c0 = total;
  for (std::size_t j = 0; j + 1 < k; ++j) {
    (*out)[k - 1].c0 -= (*out)[j].c0;
    (*out)[k - 1].add(0, -(*out)[j].coefficient(0));
  }
  (*out)[k - 1].c0 = shortest_decimal((*out)[k - 1].c0, tol / 4);
  for (double& c : (*out)[k - 1].c) c = shortest_decimal(c, 1e-9);  // -1 - 0.69 is not quite -1.69
  return out;
}

// The lengths of one split as lines in one parameter s1, in metres: where
// the split's own length varies and every part's length is a straight
// line of the first varying one's (within `tol`), the split's length
// follows that part (a tower 1.5 times its podium plus 6 m, on plots as
// high as both): the parts are absolute, the first drawn, the others
// lines of it. On a plot of another height they keep their lengths, as
// the source's do, where shares would stretch both. None otherwise.
std::optional<std::vector<Linear>> metric_lines(const std::vector<std::vector<double>>& lengths, double tol) {
  const std::size_t k = lengths.front().size();
  std::vector<double> totals;
  std::vector<std::vector<double>> column(k);
  for (const auto& run : lengths) {
    double t = 0;
    for (std::size_t j = 0; j < k; ++j) {
      t += run[j];
      column[j].push_back(run[j]);
    }
    totals.push_back(t);
  }
  const auto [tlo, thi] = std::ranges::minmax(totals);
  if (thi - tlo <= tol) return std::nullopt;  // one length: shares say as much
  // Four lengths or more, not three clumps (plots of three sizes put any
  // two parts on some line through three points only by chance).
  return lines_of_first(column, k, tol, [&](const std::vector<double>& x) {
    std::vector<double> sorted = x;
    std::ranges::sort(sorted);
    std::size_t distinct = 1;
    for (std::size_t i = 1; i < sorted.size(); ++i) distinct += sorted[i] - sorted[i - 1] > tol ? 1 : 0;
    return distinct >= 4;
  });
}

// Where a split ran: which example, and its place among that example's
// runs in derivation order.
struct RunAt {
  std::size_t example = 0, order = 0;
};

// A changed split's draw in one run.
struct DrawnAt {
  RunAt at;
  double value = 0;
};

// The split nodes below id, not entering calls.
void splits_below(const Grammar& g, NodeId id, std::unordered_set<NodeId>& out) {
  if (!out.insert(id).second) return;
  if (std::holds_alternative<Call>(g.op(id))) return;
  for_each_child(g.op(id), [&](NodeId c) { splits_below(g, c, out); });
}

// The parameters a changed split's rule carries on, passed as they are.
std::vector<Expr> carried_args(std::size_t m) {
  std::vector<Expr> args;
  for (std::size_t k = 0; k < m; ++k) args.push_back(Expr::param(static_cast<std::uint32_t>(k)));
  return args;
}

// A split whose draw, in every run, is a straight line of the draw of the
// split it runs inside (a tier's inset along y, the same share as its
// inset along x, in towers of every tier count): it takes that line of
// the outer split's parameter instead of a draw of its own,
// `rectY(1.006 * s1)` inside `rectX(s1)`. Only for a split that runs
// nowhere else, paired run by run with the outer split's latest run in the
// same example (four pairs or more showing a line, or two or more equal).
void link_nested_shares(Grammar& g, const std::unordered_map<NodeId, RuleId>& rule_of,
                        const std::unordered_map<RuleId, NodeId>& body_of,
                        const std::unordered_map<NodeId, std::vector<DrawnAt>>& values,
                        const std::unordered_map<NodeId, std::size_t>& carried, std::vector<NodeId>& replace,
                        double tol) {
  // How many places hold each node, and call each rule, over what the
  // rules reach.
  std::vector<std::uint32_t> parents(g.node_count(), 0), calls(g.rules.size(), 0);
  {
    std::vector<bool> seen(g.node_count(), false);
    std::vector<NodeId> stack;
    // Each rule's body as it is about to be: a changed split's new one.
    for (RuleId r = 0; r < g.rules.size(); ++r) {
      const auto own = body_of.find(r);
      stack.push_back(own != body_of.end() ? own->second : g.rules[r].body);
    }
    while (!stack.empty()) {
      const NodeId id = stack.back();
      stack.pop_back();
      if (id >= seen.size() || seen[id]) continue;
      seen[id] = true;
      if (const auto* c = std::get_if<Call>(&g.op(id)); c && c->rule < calls.size()) ++calls[c->rule];
      // A changed split becomes a call of its rule, whose new body is
      // walked on its own.
      if (const auto changed = rule_of.find(id); changed != rule_of.end()) {
        ++calls[changed->second];
        continue;
      }
      for_each_child(g.op(id), [&](NodeId c) {
        if (c < parents.size()) ++parents[c];
        stack.push_back(c);
      });
    }
  }
  std::vector<NodeId> outer_splits;
  for (const auto& [id, rule] : rule_of) outer_splits.push_back(id);
  std::ranges::sort(outer_splits);  // one order every time
  for (const NodeId outer : outer_splits) {
    const RuleId rule = rule_of.at(outer);
    std::unordered_set<NodeId> below;
    for_each_child(g.op(body_of.at(rule)), [&](NodeId c) { splits_below(g, c, below); });
    // Inner splits run here only: held here alone, or the body of a rule
    // called here alone (where: the node to replace).
    std::vector<std::pair<NodeId, NodeId>> inner_splits;  // (changed split, where)
    for (const NodeId id : below) {
      if (id >= parents.size() || parents[id] != 1) continue;
      if (id != outer && rule_of.count(id)) inner_splits.emplace_back(id, id);
      if (const auto* c = std::get_if<Call>(&g.op(id)); c && c->args.empty() && calls[c->rule] == 1) {
        const NodeId body = g.rules[c->rule].body;
        if (body != outer && rule_of.count(body) && body_of.count(c->rule)) inner_splits.emplace_back(body, id);
      }
    }
    std::ranges::sort(inner_splits);
    if (inner_splits.empty()) continue;
    // The outer split's runs by example and order, for the latest before
    // each inner run (runs come in derivation order, examples in order).
    std::vector<DrawnAt> outside = values.at(outer);
    auto earlier = [](const DrawnAt& a, const DrawnAt& b) {
      return a.at.example != b.at.example ? a.at.example < b.at.example : a.at.order < b.at.order;
    };
    std::ranges::sort(outside, earlier);
    for (const auto& [inner, where] : inner_splits) {
      std::vector<double> x, y;
      for (const DrawnAt& v : values.at(inner)) {
        const auto after = std::ranges::lower_bound(outside, v, earlier);
        if (after == outside.begin() || std::prev(after)->at.example != v.at.example) break;
        x.push_back(std::prev(after)->value);
        y.push_back(v.value);
      }
      if (x.size() != values.at(inner).size() || x.size() < 2) continue;
      Fit f;
      if (shows_a_line(x, tol)) {
        f = line_fit(x, y);
      } else {
        f.b = 1;  // from fewer, only equality
      }
      f.worst = worst_miss(x, y, f.a, f.b);
      if (f.worst > tol / 4) continue;
      const Fit line = short_line(x, y, f, tol / 4);
      Linear passed;
      passed.c0 = line.a;
      passed.add(carried.at(outer), line.b);  // the outer rule's share, after what it carries
      const RuleId callee = rule_of.at(inner);
      std::vector<Expr> args = carried_args(carried.at(inner));
      args.push_back(linear_expr(passed));
      replace[where] = g.intern({Call{callee, std::move(args)}, g.node(where).loc});
    }
  }
}

// The lowest a line reaches for s1 in [lo, hi].
double lowest(const Linear& f, double lo, double hi) {
  const double b = f.coefficient(0);
  return f.c0 + b * (b > 0 ? lo : hi);
}

// The runs of one split in every example, as their relative parts' lengths.
struct Seen {
  std::vector<std::vector<double>> lengths;  // per run: the relative parts' lengths
  std::vector<RunAt> at;                     // per run: where it ran
  bool lined_up = true;
  double fixed = 0;  // DrawnShares::fixed
  bool metres = false;  // DrawnShares::metres
  std::vector<bool> drawing;  // per part: whether it draws
};

// What a split that varies in one way becomes: each relative part's line of
// s1, in metres or as shares, and the draw of s1 (one value per run).
struct SharePlan {
  std::vector<Linear> lines;
  bool metric = false;
  Distribution d;
  std::vector<Observation> drawn;
};

// The plan for a split seen in these runs, or nothing when its shares vary
// in more than one way or leave a part no room. Reads nothing else.
std::optional<SharePlan> plan_shares(const Seen& s, const ShareOptions& opt) {
  const std::size_t k = s.lengths.front().size();
  const double runs = static_cast<double>(s.lengths.size());
  double total = 0;
  for (const auto& run : s.lengths)
    for (double l : run) total += l / runs;
  total = shortest_decimal(total, total * 0.01);
  const bool fixed = s.fixed > 0;
  std::vector<std::vector<double>> shares(k);  // per part, per run (lengths in metres need none)
  for (std::size_t r = 0; r < s.lengths.size() && !s.metres; ++r) {
    const std::vector<double>& run = s.lengths[r];
    // In the scale of the shares written as numbers, where there are.
    double sum = 0;
    for (std::size_t j = 0; j < k; ++j) sum += !fixed || !s.drawing[j] ? run[j] : 0;
    if (!(sum > 0)) return std::nullopt;
    for (std::size_t j = 0; j < k; ++j) shares[j].push_back((fixed ? s.fixed : total) * run[j] / sum);
  }
  // In metres where the split's length follows its parts, else shares.
  SharePlan plan;
  std::optional<std::vector<Linear>> lines;
  if (s.metres) {
    std::vector<std::vector<double>> column(k);
    for (const auto& run : s.lengths)
      for (std::size_t j = 0; j < k; ++j) column[j].push_back(run[j]);
    lines = lines_of_first(column, k, opt.tolerance, [](const std::vector<double>&) { return true; });
  } else {
    lines = metric_lines(s.lengths, opt.tolerance);
  }
  plan.metric = lines.has_value();
  if (!plan.metric && !s.metres) lines = share_lines(shares, total, fixed, opt.tolerance);
  if (!lines) return std::nullopt;
  for (std::size_t j = 0; j < k; ++j)
    if ((*lines)[j].coefficient(0) == 1 && (*lines)[j].c0 == 0 && plan.drawn.empty())
      for (std::size_t r = 0; r < s.lengths.size(); ++r)
        plan.drawn.push_back({plan.metric ? s.lengths[r][j] : shares[j][r], 1,
                              static_cast<std::int64_t>(s.at[r].example)});
  if (plan.drawn.size() != s.at.size()) return std::nullopt;
  FitOptions fit;
  fit.resolution = opt.tolerance;
  fit.floor = 0;
  fit.uniform_only = opt.uniform_distributions;
  Distribution d = fit_distribution(plan.drawn, fit);
  auto room = [&](double lo, double hi) {
    return std::ranges::all_of(*lines, [&](const Linear& f) { return lowest(f, lo, hi) > 0; });
  };
  if ((d.kind == DistributionKind::Uniform || d.kind == DistributionKind::TruncatedNormal) && !room(d.lo, d.hi)) {
    // Every share must stay a share: keep to the values seen.
    const auto [lo, hi] = std::ranges::minmax(plan.drawn, {}, &Observation::value);
    d = Distribution{DistributionKind::Uniform, {}, lo.value, hi.value};
  }
  const double lo = d.kind == DistributionKind::Choice ? d.values.front() : d.lo;
  const double hi = d.kind == DistributionKind::Choice ? d.values.back() : d.hi;
  if (!room(lo, hi)) return std::nullopt;
  plan.lines = std::move(*lines);
  plan.d = std::move(d);
  return plan;
}

// A split whose drawn parts become lines in metres through 0 of one draw
// (a tier set in by a tenth of its width on each side: s1 : nil | 8 * s1
// : tier | s1 : nil) while no part is a share: the parts always fill the
// split, so the draw is fixed by the split's length, and drawn on its own
// it set parts that no longer fill it. The same split with those parts as
// shares (~1 : ~8 : ~1) draws nothing; none where some line does not pass
// through 0 or a part stays a share.
std::optional<Split> proportional_split(Split split, const SharePlan& plan) {
  if (!plan.metric) return std::nullopt;
  const std::vector<std::size_t> drawing = drawn_shares(split)->parts;
  for (std::size_t j = 0; j < plan.lines.size(); ++j) {
    const Linear& line = plan.lines[j];
    if (line.c0 != 0 || !line.draws.empty() || line.coefficient(0) <= 0) return std::nullopt;
    split.parts[drawing[j]].size = Size{Expr::number(line.coefficient(0)), true};
  }
  for (std::size_t q = 0; q < split.parts.size(); ++q)
    if (split.parts[q].size.relative && std::ranges::find(drawing, q) == drawing.end()) return std::nullopt;
  return split;
}

}  // namespace

std::size_t share_splits(Grammar& g, const std::vector<CheckResult>& results, const ShareOptions& opt) {
  // Each example's runs, read on the threads (a city's splits run 25,000
  // times), then gathered in example order.
  std::vector<std::vector<SplitRun>> runs_in(results.size());
  parallel_for(results.size(), opt.threads, [&](std::size_t e) { runs_in[e] = runs_of(results[e].parts); });
  std::unordered_map<NodeId, Seen> seen;
  // Per split: its drawn shares, read once.
  std::unordered_map<NodeId, std::optional<DrawnShares>> shares_of;
  for (std::size_t e = 0; e < results.size(); ++e) {
    const std::vector<SplitRun>& runs = runs_in[e];
    for (std::size_t order = 0; order < runs.size(); ++order) {
      const SplitRun& run = runs[order];
      const auto* split = std::get_if<Split>(&g.op(run.split));
      if (!split) continue;
      auto [known, fresh] = shares_of.try_emplace(run.split);
      if (fresh) known->second = drawn_shares(*split);
      if (!known->second) continue;
      const std::vector<std::size_t>* relative = &known->second->parts;
      Seen& s = seen[run.split];
      if (s.drawing.empty()) {
        s.fixed = known->second->fixed;
        s.metres = known->second->metres;
        for (std::size_t i : *relative) s.drawing.push_back(split->parts[i].size.value.draws_random());
      }
      std::vector<double> lengths(relative->size(), -1);
      for (const MatchedPart* m : run.parts)
        for (std::size_t j = 0; j < relative->size(); ++j)
          if (m->part == (*relative)[j]) lengths[j] = m->length;
      double sum = 0;
      for (double l : lengths) sum += l;
      if (std::ranges::any_of(lengths, [](double l) { return l < 0; }) || !(sum > 0)) {
        s.lined_up = false;
      } else {
        s.lengths.push_back(std::move(lengths));
        s.at.push_back({e, order});
      }
    }
  }
  runs_in = {};

  // The rule each changed split runs as, the call that stands for it.
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  std::unordered_map<NodeId, RuleId> rule_of;  // changed split -> its rule
  std::unordered_map<RuleId, NodeId> body_of;  // that rule -> the split with shares
  std::unordered_map<NodeId, std::vector<DrawnAt>> values;  // changed split -> its draw in each run
  std::vector<std::vector<RuleId>> bodies(g.node_count());
  for (RuleId r = 0; r < g.rules.size(); ++r)
    if (g.rules[r].params.empty() && r != g.start_rule) bodies[g.rules[r].body].push_back(r);  // the start takes none
  std::vector<NodeId> order;
  for (const auto& [id, s] : seen)
    if (s.lined_up && !s.lengths.empty()) order.push_back(id);
  std::ranges::sort(order);  // the rules come out in one order every time
  // Each split's plan on the threads (fitting is most of the work), then
  // the grammar changed here, in that order.
  std::vector<std::optional<SharePlan>> plans(order.size());
  parallel_for(order.size(), opt.threads, [&](std::size_t i) { plans[i] = plan_shares(seen.at(order[i]), opt); });
  std::unordered_map<NodeId, std::size_t> read_memo, carried;  // changed split -> parameters it carries on
  std::size_t proportional = 0;  // splits made shares that draw nothing (proportional_split)
  const std::unordered_map<NodeId, RuleId> written_in = rules_written_in(g);
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (!plans[i]) continue;
    const NodeId id = order[i];
    // Parts all in metres, each a multiple of one draw: they fill the
    // split, so the draw is its length's and the parts are its shares.
    if (const auto fixed = proportional_split(std::get<Split>(g.op(id)), *plans[i])) {
      const NodeId now = g.intern({*fixed, g.node(id).loc});
      if (replace.size() < g.node_count()) replace.resize(g.node_count(), kNoReplacement);
      replace[id] = now;
      ++proportional;
      continue;
    }
    // A split below which its rule's parameters are read becomes a rule
    // taking them on, before the share; it is never a rule's own body
    // (those rules take none).
    const std::size_t m = params_read_below(g, id, read_memo);
    if (m > 0 && !bodies[id].empty()) continue;
    std::vector<std::string> params;
    if (m > 0) {
      const auto in = written_in.find(id);
      if (in == written_in.end() || g.rules[in->second].params.size() < m) continue;
      params.assign(g.rules[in->second].params.begin(), g.rules[in->second].params.begin() + static_cast<std::ptrdiff_t>(m));
    }
    std::string share = "s1";
    for (int n = 2; std::ranges::find(params, share) != params.end(); ++n) share = "s" + std::to_string(n);
    params.push_back(share);
    SharePlan& plan = *plans[i];
    const std::size_t k = plan.lines.size();
    Split split = std::get<Split>(g.op(id));
    const std::vector<std::size_t> relative = drawn_shares(split)->parts;
    for (std::size_t j = 0; j < k; ++j) {
      Linear line = plan.lines[j];
      if (!line.c.empty()) line.c.insert(line.c.begin(), m, 0.0);  // the share after what is carried
      split.parts[relative[j]].size = Size{linear_expr(line), !plan.metric};
    }
    const SourceLoc loc = g.node(id).loc;
    const NodeId shared = g.intern({std::move(split), loc});
    RuleId rule;
    if (!bodies[id].empty()) {
      rule = bodies[id].front();
    } else {
      rule = static_cast<RuleId>(g.rules.size());
      g.rules.push_back(Rule{free_label(g, node_name(g, id)), {}, shared, loc});
    }
    g.rules[rule].params = std::move(params);
    rule_of[id] = rule;
    body_of[rule] = shared;
    carried[id] = m;
    const Distribution d = short_decimals(plan.d, opt.tolerance / 4);
    std::vector<Expr> args = carried_args(m);
    args.push_back(distribution_expr(d));
    const NodeId call = g.intern({Call{rule, std::move(args)}, loc});
    if (replace.size() < g.node_count()) replace.resize(g.node_count(), kNoReplacement);
    replace[id] = call;
    const Seen& s = seen.at(id);
    for (std::size_t r = 0; r < plan.drawn.size(); ++r) values[id].push_back({s.at[r], plan.drawn[r].value});
  }
  if (rule_of.empty() && proportional == 0) return 0;
  // Calls of a rule that now takes the share: with it.
  for (NodeId id = 0; id < replace.size(); ++id)
    if (const auto* c = std::get_if<Call>(&g.op(id)); c && c->args.empty() && body_of.count(c->rule))
      replace[id] = replace[g.rules[c->rule].body];
  link_nested_shares(g, rule_of, body_of, values, carried, replace, opt.tolerance);
  for (RuleId r = 0; r < g.rules.size(); ++r) {
    const auto own = body_of.find(r);
    // Until settled: a split made shares in place holds splits that may
    // be replaced in turn.
    g.rules[r].body = substitute_until_settled(g, own != body_of.end() ? own->second : g.rules[r].body, replace);
  }
  return rule_of.size() + proportional;
}

}  // namespace vern
