#include "inverse/sizes/joint_sizes.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "graph/recursive_rules.hpp"
#include "inverse/check/check.hpp"
#include "inverse/check/derives_examples.hpp"
#include "inverse/load/derived_example.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/sizes/fit_distribution.hpp"
#include "inverse/sizes/linear_size.hpp"
#include "inverse/sizes/tile_draws.hpp"
#include "inverse/sizes/share_splits.hpp"
#include "inverse/sizes/tidy_numbers.hpp"
#include "inverse/write/rule_naming.hpp"
#include "inverse/write/unused_rules.hpp"

namespace vern {

namespace {

constexpr double kCorrelated = 0.9;      // |r| at which one size follows another
constexpr std::size_t kMinNoisy = 5;     // examples needed to call a loose fit a dependence

// Do the values differ by more than the tolerance?
bool varies(const std::vector<double>& x, double tolerance) {
  const auto [lo, hi] = std::ranges::minmax(x);
  return hi - lo > tolerance;
}

// A split of a region whose sizes draw, where it runs.
struct Occurrence {
  std::uint64_t path = 0;
  NodeId split = 0;
  bool tiled = false;  // inside a repeat: it runs once per tile
  // Its place in the innermost alternative that holds it: that region and
  // the split's ordinal there (slots alike in sibling alternatives).
  std::size_t alternative = ~std::size_t{0};
  std::size_t ordinal = 0;
};

struct Region {
  NodeId root = 0;
  RuleId rule = 0;  // the rule whose body holds the root: the new rule's name
  std::vector<Occurrence> splits;  // in the order check() matches them
  std::size_t parent = kNoRegion;  // the region whose choice it is an alternative of
  std::uint64_t choice = 0;        // the path of that choice
  static constexpr std::size_t kNoRegion = ~std::size_t{0};
};

bool draws(const Split& s) {
  return std::ranges::any_of(s.parts, [](const SplitPart& p) { return p.size.value.draws_random(); });
}

// A slot's sizes: a split's parts, or a repeat's tile size as a split of
// one part in metres. A tile size drawn once per building and used by the
// repeats of several subtrees (both fronts' storeys of a block) is a size
// like any other: check reports its tiles' length (MatchedPart), and the
// repeats that show the same length in every building draw it once.
Split sized_view(const Operation& op) {
  if (const auto* s = std::get_if<Split>(&op)) return *s;
  const Repeat& r = std::get<Repeat>(op);
  return Split{r.axis, {SplitPart{Size{r.size, false}, r.child}}};
}

// Whether a part holds a run of tiles (a repeat), directly or through
// the rules written for it (a row rule).
bool holds_run(const Grammar& g, NodeId id) {
  for (int depth = 0; depth < 4; ++depth) {
    const auto* call = std::get_if<Call>(&g.op(id));
    if (!call) break;
    id = g.rules[call->rule].body;
  }
  return std::holds_alternative<Repeat>(g.op(id)) || std::holds_alternative<RepeatN>(g.op(id));
}

// The regions of a grammar, and a region's nodes rebuilt with new sizes.
// Both follow the nodes in the order check() matches them, computing the
// same derivation_path.
class Regions {
 public:
  Regions(Grammar& g) : g_(g), recursive_(recursive_rules(g)), visits_(g.node_count(), 0) {
    const NodeId body = g.rules[g.start_rule].body;
    regions_.push_back({body, g.start_rule, {}});
    std::vector<std::size_t> open{0};
    collect(body, 0, 0, open, g.start_rule, false);
    if (steps_ > kMaxSteps) regions_.clear();
  }

  // None when the grammar, unrolled through its calls and alternatives,
  // is too large to walk (joining is then not tried).
  const std::vector<Region>& all() const { return regions_; }
  const Region& at(std::size_t k) const { return regions_[k]; }
  // A region's root reached at one place only can be replaced by node id.
  bool unique(const Region& r) const { return visits_[r.root] == 1; }

  // The region below `root` with sizes[k] (per part: a new size, or none)
  // for its k-th occurrence.
  // params: the new rule's; a choice whose sizes change becomes a rule
  // taking them too (a choice is written as a rule's alternatives).
  NodeId rebuild(NodeId root, const std::vector<std::vector<std::optional<Size>>>& sizes,
                 const std::vector<std::string>& params) {
    std::size_t next = 0;
    params_ = &params;
    return rebuild(root, sizes, next);
  }

 private:
  bool enters(const Call& c) const {
    return !recursive_[c.rule] && g_.rules[c.rule].params.empty() && c.args.empty();
  }

  // `open`: the regions the node lies in, outermost first. An alternative
  // of a choice is a region of its own and stays in the ones around it:
  // its sizes may follow sizes outside the choice. `tiled`: the node lies
  // inside a repeat (each tile runs it; all tiles have one path).
  void collect(NodeId id, std::uint64_t parent, std::uint32_t slot, std::vector<std::size_t>& open, RuleId rule,
               bool tiled) {
    // Every place a node runs is visited: calls and alternatives of
    // shared rules multiply, so the walk stops at a bound.
    if (++steps_ > kMaxSteps) return;
    const std::uint64_t path = derivation_path(parent, id, slot);
    ++visits_[id];
    const Operation& op = g_.op(id);
    if (const auto* s = std::get_if<Split>(&op)) {
      if (draws(*s)) {
        const std::size_t ordinal = regions_[open.back()].splits.size();
        for (std::size_t r : open) regions_[r].splits.push_back({path, id, tiled, open.back(), ordinal});
      }
      for (std::size_t i = 0; i < s->parts.size(); ++i)
        collect(s->parts[i].child, path, static_cast<std::uint32_t>(i + 1), open, rule, tiled);
    } else if (const auto* c = std::get_if<Call>(&op)) {
      if (enters(*c)) collect(g_.rules[c->rule].body, path, 0, open, c->rule, tiled);
    } else if (const auto* ch = std::get_if<Choose>(&op)) {
      for (std::size_t j = 0; j < ch->options.size(); ++j) {
        const std::size_t inner = regions_.size();
        regions_.push_back({ch->options[j].child, rule, {}, open.back(), path});
        open.push_back(inner);
        collect(ch->options[j].child, path, static_cast<std::uint32_t>(j + 1), open, rule, tiled);
        open.pop_back();
      }
    } else if (std::holds_alternative<Translate>(op) || std::holds_alternative<Scale>(op) ||
               std::holds_alternative<Rotate>(op)) {
      collect(node_children(op)[0], path, 0, open, rule, tiled);
    } else if (std::holds_alternative<Repeat>(op) || std::holds_alternative<RepeatN>(op)) {
      if (const auto* r = std::get_if<Repeat>(&op); r && r->size.draws_random()) {
        const std::size_t ordinal = regions_[open.back()].splits.size();
        for (std::size_t k : open) regions_[k].splits.push_back({path, id, tiled, open.back(), ordinal});
      }
      // Tiles draw anew, but a size every tile of a building shows the
      // same (the storeys' door bay above the ground floor's) may follow
      // a size outside: region() keeps such sizes and leaves the others.
      collect(node_children(op)[0], path, 0, open, rule, true);
    }
    // Comps' faces are not lined up: a region stops there.
  }

  NodeId rebuild(NodeId id, const std::vector<std::vector<std::optional<Size>>>& sizes, std::size_t& next) {
    Operation op = g_.op(id);  // a copy: interning may move the arena
    const SourceLoc loc = g_.node(id).loc;
    if (auto* s = std::get_if<Split>(&op)) {
      if (draws(*s)) {
        const auto& mine = sizes[next++];
        for (std::size_t i = 0; i < s->parts.size(); ++i)
          if (mine[i]) s->parts[i].size = *mine[i];
      }
      for (auto& part : s->parts) part.child = rebuild(part.child, sizes, next);
      return kept(id, std::move(op), loc);
    }
    if (const auto* c = std::get_if<Call>(&op)) {
      // Written out only where a size below it changes.
      if (!enters(*c)) return id;
      const NodeId body = g_.rules[c->rule].body;
      const NodeId now = rebuild(body, sizes, next);
      if (now == body) return id;
      if (!std::holds_alternative<Choose>(g_.op(now))) return now;
      auto [it, fresh] = choice_rules_.try_emplace(now, static_cast<RuleId>(g_.rules.size()));
      const RuleId called = it->second;
      if (fresh)
        g_.rules.push_back(
            Rule{free_label(g_, g_.rules[c->rule].label + "Sizes"), *params_, now, g_.rules[c->rule].loc});
      std::vector<Expr> args;
      for (std::size_t k = 0; k < params_->size(); ++k) args.push_back(Expr::param(static_cast<std::uint32_t>(k)));
      return g_.intern({Call{called, std::move(args)}, loc});
    }
    if (auto* r = std::get_if<Repeat>(&op); r && r->size.draws_random()) {
      const auto& mine = sizes[next++];
      // A relative size is a count (Joiner::count_line): repeatN.
      if (mine[0] && mine[0]->relative) op = RepeatN{r->axis, mine[0]->value, r->child};
      else if (mine[0]) r->size = mine[0]->value;
    }
    if (std::holds_alternative<Translate>(op) || std::holds_alternative<Scale>(op) ||
        std::holds_alternative<Rotate>(op) || std::holds_alternative<Repeat>(op) || std::holds_alternative<RepeatN>(op)) {
      NodeId* child = child_slots(op)[0];
      *child = rebuild(*child, sizes, next);
      return kept(id, std::move(op), loc);
    }
    if (auto* ch = std::get_if<Choose>(&op)) {
      for (auto& option : ch->options) option.child = rebuild(option.child, sizes, next);
      return kept(id, std::move(op), loc);
    }
    return id;
  }

  // The node itself where nothing changed.
  NodeId kept(NodeId id, Operation op, SourceLoc loc) {
    if (op == g_.op(id)) return id;
    return g_.intern({std::move(op), loc});
  }

  static constexpr std::size_t kMaxSteps = 1'000'000;
  std::size_t steps_ = 0;
  Grammar& g_;
  const std::vector<std::string>* params_ = nullptr;
  std::unordered_map<NodeId, RuleId> choice_rules_;  // a changed choice -> the rule made for it
  std::vector<bool> recursive_;
  std::vector<std::uint32_t> visits_;
  std::vector<Region> regions_;
};

// One varying size of a region, its value in each example that shows it.
struct Quantity {
  std::size_t occurrence = 0, part = 0;
  bool relative = false;
  std::vector<double> values;  // per example of the region
};

// A quantity's value in an example that did not run its split.
constexpr double kAbsent = std::numeric_limits<double>::quiet_NaN();

std::vector<double> present_values(const std::vector<double>& v) {
  std::vector<double> out;
  for (double x : v)
    if (!std::isnan(x)) out.push_back(x);
  return out;
}

// The examples showing both: their x and y values.
std::pair<std::vector<double>, std::vector<double>> paired(const std::vector<double>& x, const std::vector<double>& y) {
  std::pair<std::vector<double>, std::vector<double>> out;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isnan(x[i]) && !std::isnan(y[i])) {
      out.first.push_back(x[i]);
      out.second.push_back(y[i]);
    }
  return out;
}

// One split of a region as the examples ran it.
struct SplitLengths {
  std::vector<std::vector<double>> length, value;  // per part, per example (kAbsent where not run)
  std::vector<bool> random, relative;              // per part: its size draws; it is a share
  std::size_t present = 0;                         // examples that ran it
};

// Shares that are metres (issue 23, items 1 and 2). Merging writes a part
// whose length varies as a share of its container; but a part that is,
// to the tolerance, a straight line in metres of another size drawn in
// the derivation (a tower 1.5 times its podium's height plus 6 m, the
// nave 3.5 m above the aisles' walls, in another split) is metres: its
// share of a container that varies on its own says nothing. Both are then
// read in metres, leader and follower, where the shares do not say the
// same already (two parts of one split in one proportion, or containers
// that do not vary, are shares), and as long as every split keeps a share
// to take the rest. The follower may be a share written as one weight
// whose length still varies (check reports such sizes beside the draws:
// the scale merging read the split's other weights in), the leader only a
// draw. The lines themselves are then found, as any other, by the
// region's fit below.
std::vector<std::pair<std::size_t, std::size_t>> read_in_metres(const std::vector<SplitLengths>& at,
                                                                std::size_t min_examples, double tolerance) {
  // Varying parts in derivation order, with the examples that show each
  // as bits: a line needs min_examples shown by both, so parts shown by
  // fewer are left out and pairs sharing fewer are skipped before any
  // values are paired. Examples that each run their own alternative (a
  // real facade set: 378 facades, thousands of parts, each shown once)
  // made every pair be paired, most of a 378-facade infer's ten minutes.
  std::vector<std::pair<std::size_t, std::size_t>> order;
  std::vector<std::vector<std::uint64_t>> shown;
  for (std::size_t o = 0; o < at.size(); ++o) {
    if (at[o].present < min_examples) continue;
    for (std::size_t i = 0; i < at[o].random.size(); ++i) {
      // A share written as one weight whose length still varies (the
      // scale the split's other weights were read in: storeys 2u + 4.5 m
      // beside an arcade u high) may follow a drawn part too.
      if (!at[o].random[i]) {
        const std::vector<double> seen = present_values(at[o].length[i]);
        if (!at[o].relative[i] || seen.empty() || !varies(seen, tolerance)) continue;
      }
      const std::vector<double>& values = at[o].length[i];
      std::vector<std::uint64_t> bits((values.size() + 63) / 64, 0);
      std::size_t count = 0;
      for (std::size_t e = 0; e < values.size(); ++e) {
        if (std::isnan(values[e])) continue;
        bits[e / 64] |= std::uint64_t{1} << (e % 64);
        ++count;
      }
      if (count < min_examples) continue;
      order.push_back({o, i});
      shown.push_back(std::move(bits));
    }
  }
  auto shown_by_both = [&](std::size_t p, std::size_t q) {
    std::size_t count = 0;
    for (std::size_t w = 0; w < shown[p].size() && w < shown[q].size(); ++w)
      count += static_cast<std::size_t>(std::popcount(shown[p][w] & shown[q][w]));
    return count;
  };
  std::vector<std::vector<bool>> metres(at.size());
  std::vector<std::size_t> shares(at.size(), 0);
  for (std::size_t o = 0; o < at.size(); ++o) {
    metres[o].assign(at[o].random.size(), false);
    shares[o] = static_cast<std::size_t>(std::ranges::count(at[o].relative, true));
  }
  // Per split, once: each part's share of the split's shares' lengths,
  // and the longest the split ran over the examples (at least 1 m).
  std::vector<std::vector<std::vector<double>>> share(at.size());
  std::vector<double> longest(at.size(), 1.0);
  for (std::size_t o = 0; o < at.size(); ++o) {
    if (at[o].present < min_examples) continue;  // none of its parts is in `order`
    const std::size_t parts = at[o].length.size(), examples = parts == 0 ? 0 : at[o].length[0].size();
    share[o].assign(parts, std::vector<double>(examples, kAbsent));
    for (std::size_t e = 0; e < examples; ++e) {
      double shares_sum = 0, sum = 0;
      for (std::size_t k = 0; k < parts; ++k) {
        if (at[o].relative[k]) shares_sum += at[o].length[k][e];
        sum += std::isnan(at[o].length[k][e]) ? 0 : at[o].length[k][e];
      }
      longest[o] = std::max(longest[o], sum);
      if (shares_sum > 0)
        for (std::size_t k = 0; k < parts; ++k) share[o][k][e] = at[o].length[k][e] / shares_sum;
    }
  }
  auto exact_line = [&](const std::vector<double>& xs, const std::vector<double>& ys, double tol) {
    const auto [x, y] = paired(xs, ys);
    if (x.size() < min_examples || !shows_a_line(x, tol)) return false;
    const Fit f = line_fit(x, y);
    return worst_miss(x, y, f.a, f.b) <= tol / 4;
  };
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t q = 0; q < order.size(); ++q) {
    const auto [qo, qi] = order[q];
    if (!at[qo].relative[qi] || metres[qo][qi]) continue;
    for (std::size_t p = 0; p < order.size(); ++p) {
      if (p == q) continue;
      const auto [po, pi] = order[p];
      if (!at[po].random[pi]) continue;  // only a draw leads
      const bool p_share = at[po].relative[pi] && !metres[po][pi];
      // Each split keeps a share to take its rest.
      const std::size_t leaving_q = 1 + (p_share && po == qo ? 1 : 0);
      if (shares[qo] <= leaving_q || (p_share && po != qo && shares[po] <= 1)) continue;
      if (shown_by_both(p, q) < min_examples) continue;
      if (!exact_line(at[po].length[pi], at[qo].length[qi], tolerance)) continue;
      // Where the shares say the same (containers that do not vary, or
      // two parts of one split in one proportion), they stay shares.
      // A share misses by its miss in metres over its container's length;
      // staying a share needs the tolerance only, not a quarter of it: the
      // shares' lengths carry the rounding of every part they sum.
      const double share_tolerance = 4 * tolerance / std::max(longest[po], longest[qo]);
      if (exact_line(p_share ? share[po][pi] : at[po].length[pi], share[qo][qi], share_tolerance)) continue;
      metres[qo][qi] = true;
      --shares[qo];
      out.push_back({qo, qi});
      if (p_share) {
        metres[po][pi] = true;
        --shares[po];
        out.push_back({po, pi});
      }
      break;
    }
  }
  return out;
}

// The support a parameter's distribution gives it.
std::pair<double, double> support(const Distribution& d) {
  switch (d.kind) {
    case DistributionKind::Constant: return {d.values[0], d.values[0]};
    case DistributionKind::Choice: return {d.values.front(), d.values.back()};
    default: return {d.lo, d.hi};
  }
}

double lowest(const Linear& f, const std::vector<std::pair<double, double>>& ranges) {
  double v = f.c0;
  for (std::size_t k = 0; k < f.c.size(); ++k) v += f.c[k] * (f.c[k] > 0 ? ranges[k].first : ranges[k].second);
  return v;
}

class Joiner {
 public:
  Joiner(Grammar& g, const JointSizesOptions& o) : g_(g), opt_(o) {}

  // What the examples' derivations placed at each path, per example.
  using Seen = std::unordered_map<std::uint64_t, std::vector<MatchedPart>>;
  // The examples whose derivations ran each path, in order.
  using Runners = std::unordered_map<std::uint64_t, std::vector<std::size_t>>;

  // Rewrites one region; the new call that replaces its root, or none.
  std::optional<NodeId> region(Regions& regions, const Region& r, const std::vector<Seen>& seen,
                               const Runners& runners, JointSizes& out) {
    // The examples that ran the region, and its parts' lengths in each
    // (none for a split in an alternative the example did not take). Only
    // those that ran one of its splits are looked at: examples of other
    // structures each make a region of their own, and a thousand of them
    // looked up in every region was quadratic.
    std::vector<std::size_t> ran_it;
    for (const Occurrence& o : r.splits)
      if (const auto it = runners.find(o.path); it != runners.end())
        ran_it.insert(ran_it.end(), it->second.begin(), it->second.end());
    std::sort(ran_it.begin(), ran_it.end());
    ran_it.erase(std::unique(ran_it.begin(), ran_it.end()), ran_it.end());
    std::vector<std::vector<const std::vector<MatchedPart>*>> rows;
    for (const std::size_t example : ran_it) {
      const Seen& s = seen[example];
      std::vector<const std::vector<MatchedPart>*> row;
      bool ran = false;
      for (const Occurrence& o : r.splits) {
        const auto it = s.find(o.path);
        row.push_back(it != s.end() ? &it->second : nullptr);
        ran = ran || it != s.end();
      }
      if (ran) rows.push_back(std::move(row));
    }
    if (rows.size() < std::min(opt_.min_examples, opt_.min_equal)) return std::nullopt;
    const std::size_t n = rows.size();

    // Per occurrence: per part, its length in each example.
    std::vector<SplitLengths> at(r.splits.size());
    for (std::size_t o = 0; o < r.splits.size(); ++o) {
      const Split split = sized_view(g_.op(r.splits[o].split));
      const std::size_t parts = split.parts.size();
      SplitLengths& s = at[o];
      s.length.assign(parts, std::vector<double>(n, kAbsent));
      s.value = s.length;
      s.random.assign(parts, false);
      s.relative.assign(parts, false);
      for (std::size_t i = 0; i < parts; ++i) {
        s.random[i] = split.parts[i].size.value.draws_random();
        s.relative[i] = split.parts[i].size.relative;
      }
      // Inside a repeat, each tile runs the split: its sizes are one
      // building's where every tile shows the same, and some building
      // shows two tiles or more; else the tiles draw anew, and the split
      // is left as it is.
      bool kept = true, seen_twice = false;
      for (std::size_t e = 0; e < n; ++e) {
        if (!rows[e][o]) continue;
        ++s.present;
        std::vector<int> count(parts, 0);
        for (const MatchedPart& m : *rows[e][o]) {
          if (m.part >= parts) return std::nullopt;
          if (!m.random) {
            // A size written as a number, reported beside the draws (the
            // scale they were read in): its first length, read only by
            // read_in_metres.
            if (!s.random[m.part] && std::isnan(s.length[m.part][e])) {
              s.length[m.part][e] = m.length;
              s.value[m.part][e] = m.value;
            }
            continue;
          }
          if (count[m.part]++ > 0) {
            kept = kept && std::abs(m.length - s.length[m.part][e]) <= opt_.tolerance &&
                   std::abs(m.value - s.value[m.part][e]) <= opt_.tolerance;
            seen_twice = true;
            continue;
          }
          s.length[m.part][e] = m.length;
          s.value[m.part][e] = m.value;
        }
        for (std::size_t i = 0; i < parts; ++i) {
          if (r.splits[o].tiled && s.random[i] && count[i] >= 1) continue;
          if (count[i] != (s.random[i] ? 1 : 0)) return std::nullopt;  // run twice, or not lined up
        }
      }
      if (r.splits[o].tiled && (!kept || !seen_twice)) {
        s.present = 0;
        for (auto& l : s.length) std::ranges::fill(l, kAbsent);
        for (auto& v : s.value) std::ranges::fill(v, kAbsent);
      }
    }
    // One slot in sibling alternatives is one set of sizes (pooled_slots).
    const std::vector<std::size_t> leader_of = pool_slots(regions, r, at, rows);
    // Shares that are metres: they leave the shares (see read_in_metres).
    // A weight that follows a draw in metres is a size like the draws.
    std::set<std::pair<std::size_t, std::size_t>> weights_in_metres;
    for (const auto& [o, i] : read_in_metres(at, opt_.min_examples, opt_.tolerance)) {
      at[o].relative[i] = false;
      if (!at[o].random[i]) weights_in_metres.insert({o, i});
    }
    for (std::size_t o = 0; o < at.size(); ++o) at[o].relative = at[leader_of[o]].relative;

    std::vector<Quantity> quantities;
    std::vector<std::vector<std::optional<Linear>>> formula(r.splits.size());
    struct Rest {
      std::size_t occurrence, part;
      double total;
    };
    std::vector<Rest> rests;
    for (std::size_t o = 0; o < r.splits.size(); ++o) {
      SplitLengths& s = at[o];
      const std::size_t parts = s.random.size();
      formula[o].resize(parts);
      if (s.present == 0) continue;  // an alternative no example took: left as it is
      const auto& length = s.length;
      auto& value = s.value;
      const auto& random = s.random;
      const std::size_t present = s.present;
      std::vector<std::size_t> relative, relative_random;
      for (std::size_t i = 0; i < parts; ++i) {
        if (!s.relative[i]) continue;
        relative.push_back(i);
        if (random[i]) relative_random.push_back(i);
      }
      const bool shares_only = relative.size() >= 2 && relative_random.size() == relative.size();
      double total = 0;
      if (shares_only) {
        for (std::size_t e = 0; e < n; ++e)
          if (rows[e][o])
            for (std::size_t i : relative) total += length[i][e] / static_cast<double>(present);
        if (!(total > 0)) return std::nullopt;
        total = shortest_decimal(total, total * 0.01);
        for (std::size_t e = 0; e < n; ++e) {
          if (!rows[e][o]) continue;
          double sum = 0;
          for (std::size_t i : relative) sum += length[i][e];
          if (!(sum > 0)) return std::nullopt;
          for (std::size_t i : relative) value[i][e] = total * length[i][e] / sum;
        }
        rests.push_back({o, relative.back(), total});
      }
      for (std::size_t i = 0; i < parts; ++i) {
        if ((!random[i] && !weights_in_metres.count({o, i})) || (shares_only && i == relative.back())) continue;
        // A lone relative part takes the rest whatever its size says.
        if (s.relative[i] && relative.size() == 1) continue;
        quantities.push_back({o, i, s.relative[i], s.relative[i] ? value[i] : length[i]});
      }
    }

    // Each size against the ones before it.
    std::vector<Distribution> drawn;  // per parameter: its distribution, or a deviation's
    std::vector<std::vector<double>> drawn_values;
    std::vector<std::size_t> drawn_at;  // the occurrence that first uses it
    std::vector<std::size_t> leaders;   // quantities that are parameters
    std::vector<std::size_t> leader_param;
    // Per parameter: drawn inside a repeat's tiles, where every tile of a
    // building showed the same value (a door bay's place on every storey,
    // a balcony kept on every floor): drawn once per building, by the
    // region, not anew in each tile where it stood.
    std::vector<bool> per_building;
    // Draws that are one number at their place, seen there in enough
    // examples: a door merged from two places (1.5 m on the ground floor,
    // 1.2 m on the balconies) is written choice(1.2, 1.5), and each place
    // keeps its own.
    std::size_t gained = 0, linked = 0, fixed_in_place = 0;
    std::set<std::size_t> counts;  // occurrences: repeats whose count is a line of a size (count_line)
    FitOptions fit;
    fit.resolution = opt_.tolerance;
    fit.floor = 0;
    fit.uniform_only = opt_.uniform_distributions;
    for (std::size_t q = 0; q < quantities.size(); ++q) {
      const Quantity& Q = quantities[q];
      Linear f;
      const std::vector<double> seen_values = present_values(Q.values);
      if (seen_values.empty()) continue;
      const auto [lo, hi] = std::ranges::minmax(seen_values);
      // The same in every example that shows it: a constant, as merging
      // writes it, however few show it.
      if (hi - lo <= opt_.tolerance) {
        f.c0 = shortest_decimal((lo + hi) / 2, opt_.tolerance / 4);
        formula[Q.occurrence][Q.part] = f;
        ++gained;
        fixed_in_place += seen_values.size() >= opt_.min_examples ? 1 : 0;
        continue;
      }
      // Against each earlier drawn size, over the examples showing both.
      std::optional<std::size_t> best;
      Fit best_fit;
      std::vector<double> best_x, best_y;
      // A repeat's tiles are no draw (ceil(L / s) tiles of L / n): tile
      // sizes follow only one another, where equal (the storeys of both
      // fronts), and no other size follows them.
      const bool tiles = is_tile_size(r, Q.occurrence);
      if (tiles) {
        if (const auto counted = count_line(r, quantities, leaders, leader_param, at[Q.occurrence])) {
          formula[Q.occurrence][Q.part] = *counted;
          counts.insert(Q.occurrence);
          ++gained;
          ++linked;
          continue;
        }
      }
      for (std::size_t l = 0; l < leaders.size(); ++l) {
        if (is_tile_size(r, quantities[leaders[l]].occurrence) != tiles) continue;
        auto [x, y] = paired(quantities[leaders[l]].values, Q.values);
        Fit t;
        if (tiles) {
          if (x.size() < opt_.min_equal || worst_miss(x, y, 0, 1) > opt_.tolerance / 4 || !varies(x, opt_.tolerance))
            continue;
          t.b = 1;
          t.r = 1;
        } else if (x.size() >= opt_.min_examples && shows_a_line(x, opt_.tolerance)) {
          t = line_fit(x, y);
        } else if (((x.size() >= opt_.min_examples && worst_miss(x, y, 0, 1) <= opt_.tolerance / 4) ||
                    (n < opt_.min_examples && x.size() >= opt_.min_equal)) &&
                   varies(x, opt_.tolerance)) {
          // Equality needs no line: two values seen (a door bay after two
          // or three bays) with the other size equal in every example;
          // and from so few examples only equality is evidence, where
          // there are no more to see (in a region seen more often, a pair
          // that so few show stays apart, as a line through them would).
          t.b = 1;
          t.r = 1;
        } else {
          continue;
        }
        t.worst = worst_miss(x, y, t.a, t.b);
        if (!best || t.worst < best_fit.worst) {
          best = l;
          best_fit = t;
          best_x = std::move(x);
          best_y = std::move(y);
        }
      }
      const bool exact = best && best_fit.worst <= opt_.tolerance / 4;
      // Equal, in every example showing both, to an earlier size that is
      // itself a function of the draws (two lodges' party wall, cut in
      // their storeys' band and again in their roofs' band, each a loose
      // line of the lodges' width): the same function, so the cuts stay
      // one.
      if (!exact) {
        if (const auto same = equal_to_earlier(q, quantities, formula, r)) {
          formula[Q.occurrence][Q.part] = *same;
          ++gained;
          ++linked;
          continue;
        }
      }
      const bool loose = best && !exact && !tiles && std::abs(best_fit.r) >= kCorrelated && best_x.size() >= kMinNoisy &&
                         quantities[leaders[*best]].occurrence != Q.occurrence;
      if (exact || loose) {
        const Quantity& L = quantities[leaders[*best]];
        const Fit s = short_line(best_x, best_y, best_fit, opt_.tolerance / 4);
        f.c0 = s.a;
        f.add(leader_param[*best], s.b);
        if (loose) {
          // The deviation: a parameter too, for the rest of its split
          // may need it again.
          const double e = shortest_decimal(s.worst + opt_.tolerance / 4, opt_.tolerance / 4, +1);
          std::vector<double> misses;
          for (std::size_t i = 0; i < best_x.size(); ++i) misses.push_back(best_y[i] - s.a - s.b * best_x[i]);
          f.add(drawn.size(), 1);
          drawn.push_back(Distribution{DistributionKind::Uniform, {}, -e, e});
          drawn_values.push_back(std::move(misses));
          drawn_at.push_back(Q.occurrence);
          per_building.push_back(r.splits[Q.occurrence].tiled);
        }
        formula[Q.occurrence][Q.part] = f;
        ++gained;
        // Within one split, share_splits draws shares that vary in one
        // way once; lengths in metres linked there are this step's.
        if (L.occurrence != Q.occurrence || !Q.relative) ++linked;
        continue;
      }
      std::vector<Observation> obs;
      for (double v : seen_values) obs.push_back({v, 1});
      leaders.push_back(q);
      leader_param.push_back(drawn.size());
      // A size merging wrote as a choice of values (pooled over every
      // place the same piece stood: a door bay after one, two or three
      // bays) keeps it, where the region's examples took only those; a
      // region's few examples would fit a range.
      const SplitPart written = sized_view(g_.op(r.splits[Q.occurrence].split)).parts[Q.part];
      const auto as_written = written.size.relative == Q.relative ? written_distribution(written.size.value) : std::nullopt;
      const bool among = as_written && as_written->kind == DistributionKind::Choice &&
                         std::ranges::all_of(seen_values, [&](double v) {
                           return std::ranges::any_of(as_written->values, [&](double c) { return std::abs(c - v) <= opt_.tolerance; });
                         });
      drawn.push_back(among   ? *as_written
                      : tiles ? tile_size_draw(at[Q.occurrence], fit, obs)
                              : fit_distribution(obs, fit));
      drawn_values.push_back(seen_values);
      drawn_at.push_back(Q.occurrence);
      per_building.push_back(r.splits[Q.occurrence].tiled);
      f.add(leader_param.back(), 1);
      formula[Q.occurrence][Q.part] = f;
    }
    // Splits that vary on their own are share_splits' (one rule each, not
    // one per region).
    if (linked == 0 && fixed_in_place == 0 && std::ranges::none_of(per_building, [](bool b) { return b; }))
      return std::nullopt;
    // A slot pooled: every alternative's split sized as its leader's.
    for (std::size_t o = 0; o < at.size(); ++o)
      if (leader_of[o] != o) formula[o] = formula[leader_of[o]];

    // The rest of a split of shares: its total less the others' shares.
    for (const Rest& rest : rests) {
      Linear f;
      f.c0 = rest.total;
      for (std::size_t i = 0; i < formula[rest.occurrence].size(); ++i) {
        const auto& other = formula[rest.occurrence][i];
        if (i == rest.part || !other) continue;
        if (!at[rest.occurrence].relative[i]) continue;
        f.c0 -= other->c0;
        for (std::size_t k = 0; k < other->c.size(); ++k) f.add(k, -other->c[k]);
      }
      f.c0 = shortest_decimal(f.c0, opt_.tolerance / 4);
      for (double& c : f.c) c = shortest_decimal(c, 1e-9);  // sums of short decimals, not float noise
      formula[rest.occurrence][rest.part] = f;
      for (std::size_t o = 0; o < at.size(); ++o)
        if (leader_of[o] == rest.occurrence && o != rest.occurrence) formula[o][rest.part] = f;
    }

    // A parameter used in one size only is drawn there; the others are
    // the new rule's parameters. check() pins a parameter down at the
    // first split that uses it, so each split may bring one.
    // A pooled slot's alternatives count once: each derivation runs one.
    std::vector<std::size_t> uses(drawn.size(), 0);
    for (std::size_t o = 0; o < formula.size(); ++o)
      for (const auto& f : formula[o])
        if (f && leader_of[o] == o)
          for (std::size_t k = 0; k < f->c.size(); ++k) uses[k] += f->c[k] != 0 ? 1 : 0;
    // A split brings one parameter at most (check solves for one unknown
    // per split). Where its rest would make it bring more, shares used
    // nowhere else becoming parameters only to be subtracted there, the
    // rest is drawn on its own instead, as its shares were seen: the
    // sizes the split shares with the rest of the region (a wing's height
    // with the other wing's) still join, where the region was given up.
    for (const Rest& rest : rests) {
      std::size_t brings = 0;
      for (std::size_t k = 0; k < drawn.size(); ++k) brings += drawn_at[k] == rest.occurrence && uses[k] >= 2 ? 1 : 0;
      if (brings <= 1) continue;
      auto& f = formula[rest.occurrence][rest.part];
      for (std::size_t k = 0; k < f->c.size(); ++k) uses[k] -= f->c[k] != 0 ? 1 : 0;
      const std::vector<double> seen_values = present_values(at[rest.occurrence].value[rest.part]);
      std::vector<Observation> obs;
      for (double v : seen_values) obs.push_back({v, 1});
      f = Linear{};
      f->add(drawn.size(), 1);
      drawn.push_back(fit_distribution(obs, fit));
      drawn_values.push_back(seen_values);
      drawn_at.push_back(rest.occurrence);
      per_building.push_back(r.splits[rest.occurrence].tiled);
      uses.push_back(1);
    }
    std::vector<std::pair<double, double>> ranges;
    for (const Distribution& d : drawn) ranges.push_back(support(d));
    // Room for every part: a size no example showed at 0 stays above it;
    // one shown at 0 (a run of no tiles before a door bay at the start,
    // empty_runs.hpp) may be 0.
    auto no_room = [&](std::size_t o, std::size_t i) {
      const auto& f = formula[o][i];
      if (!f || counts.count(o)) return false;  // no tiles where the count is 0
      const double low = lowest(*f, ranges);
      const auto& shown = at[leader_of[o]].length[i];
      const bool zero_seen =
          std::ranges::any_of(shown, [&](double v) { return !std::isnan(v) && std::abs(v) <= opt_.tolerance; });
      // A run of tiles may be no tiles (its part is then not derived):
      // the storeys' bays before their balcony bay, drawn with the ground
      // floor's bays before its door, which the examples showed at 0.
      const auto* split = std::get_if<Split>(&g_.op(r.splits[o].split));
      const bool run = split && holds_run(g_, split->parts[i].child);
      return zero_seen || run ? low < -opt_.tolerance : !(low > 0);
    };
    auto any_without_room = [&] {
      for (std::size_t o = 0; o < formula.size(); ++o)
        for (std::size_t i = 0; i < formula[o].size(); ++i)
          if (no_room(o, i)) return true;
      return false;
    };
    if (any_without_room()) {
      // Variants would get no room: keep to the values seen. A choice of
      // the values seen (a door bay after no, one or two bays of 3.8 m:
      // choice(0, 3.8, 7.6)) keeps to them already, and stays a choice: a
      // range between them would put the door bay off the bays' grid.
      for (std::size_t k = 0; k < drawn.size(); ++k) {
        if (drawn[k].kind == DistributionKind::Choice || drawn[k].kind == DistributionKind::Constant) continue;
        const auto [lo, hi] = std::ranges::minmax(drawn_values[k]);
        drawn[k] = Distribution{DistributionKind::Uniform, {}, lo, hi};
        ranges[k] = {lo, hi};
      }
    }
    if (any_without_room()) return std::nullopt;
    std::vector<std::optional<std::uint32_t>> param(drawn.size());
    std::vector<Expr> args;
    std::vector<std::string> names;
    std::vector<std::size_t> brought(r.splits.size(), 0);
    for (std::size_t k = 0; k < drawn.size(); ++k) {
      // Used once and drawn per tile: drawn where it stands.
      if (uses[k] == 0 || (uses[k] == 1 && !per_building[k])) continue;
      param[k] = static_cast<std::uint32_t>(args.size());
      args.push_back(distribution_expr(short_decimals(drawn[k], opt_.tolerance / 4)));
      names.push_back("s" + std::to_string(args.size()));
      if (++brought[drawn_at[k]] > 1) return std::nullopt;
    }

    std::vector<std::vector<std::optional<Size>>> sizes(r.splits.size());
    for (std::size_t o = 0; o < r.splits.size(); ++o) {
      const Split split = sized_view(g_.op(r.splits[o].split));
      sizes[o].resize(split.parts.size());
      for (std::size_t i = 0; i < split.parts.size(); ++i) {
        const auto& f = formula[o][i];
        if (!f) continue;
        Linear renamed;
        renamed.c0 = f->c0;
        for (std::size_t k = 0; k < f->c.size(); ++k) {
          if (f->c[k] == 0) continue;
          if (param[k]) renamed.add(*param[k], f->c[k]);
          // Used here only, with coefficient 1 (a leader or a deviation):
          // drawn in place.
          else renamed.draws.push_back(distribution_expr(short_decimals(drawn[k], opt_.tolerance / 4)));
        }
        // A repeat's count is written as a relative size: rebuild makes
        // the repeat a repeatN of it.
        sizes[o][i] = counts.count(o) ? Size{count_line_expr(renamed), true} : Size{linear_expr(renamed), at[o].relative[i]};
      }
    }
    const NodeId body = regions.rebuild(r.root, sizes, names);
    Rule rule;
    rule.label = free_label(g_, g_.rules[r.rule].label + "Sizes");
    rule.params = names;
    rule.body = body;
    rule.loc = g_.rules[r.rule].loc;
    const RuleId id = static_cast<RuleId>(g_.rules.size());
    g_.rules.push_back(std::move(rule));
    out.regions += 1;
    out.joined += gained + rests.size();
    return g_.intern({Call{id, std::move(args)}, g_.node(r.root).loc});
  }

 private:
  // Slots alike in sibling alternatives (issue 23, item 1): a choice's
  // alternatives that differ below some place (a door bay after one, two
  // or three bays, on the ground floor and every storey alike) each hold
  // the split round it, and each alternative's few examples sized it on
  // their own (a storey band 1.5 times the ground floor's height plus
  // 2.5 m in one, a fixed 14.5 m in another). A split at the same ordinal
  // in alternatives of one choice, of one form (axis, parts, which parts
  // draw, which are shares, the same constants), which no example runs
  // twice, is one slot: its lengths are pooled into the first's (the
  // leader), and the others take the leader's sizes. Per occurrence: its
  // leader (itself where not pooled).
  std::vector<std::size_t> pool_slots(const Regions& regions, const Region& r, std::vector<SplitLengths>& at,
                                      std::vector<std::vector<const std::vector<MatchedPart>*>>& rows) const {
    std::vector<std::size_t> leader_of(at.size());
    for (std::size_t o = 0; o < at.size(); ++o) leader_of[o] = o;
    auto form = [&](std::size_t o) {
      const Split s = sized_view(g_.op(r.splits[o].split));
      std::vector<double> key{static_cast<double>(s.axis.literal_axis().value_or(99)),
                              static_cast<double>(s.parts.size())};
      for (const SplitPart& p : s.parts) {
        key.push_back(p.size.relative ? 1 : 0);
        key.push_back(p.size.value.draws_random() ? std::numeric_limits<double>::infinity()
                                                  : p.size.value.literal().value_or(-1));
      }
      return key;
    };
    std::vector<std::vector<double>> forms;
    for (std::size_t o = 0; o < at.size(); ++o) forms.push_back(form(o));
    for (std::size_t o = 0; o < at.size(); ++o) {
      const Occurrence& occ = r.splits[o];
      if (occ.tiled || at[o].present == 0 || occ.alternative == Region::kNoRegion) continue;
      const Region& alt = regions.at(occ.alternative);
      if (alt.parent == Region::kNoRegion || &alt == &r) continue;
      for (std::size_t l = 0; l < o; ++l) {
        if (leader_of[l] != l) continue;
        const Occurrence& lead = r.splits[l];
        if (lead.tiled || lead.alternative == occ.alternative || lead.alternative == Region::kNoRegion) continue;
        const Region& lead_alt = regions.at(lead.alternative);
        if (lead_alt.parent != alt.parent || lead_alt.choice != alt.choice || lead.ordinal != occ.ordinal) continue;
        if (forms[l] != forms[o]) continue;
        // No example runs both (alternatives of one choice, run once).
        bool apart = true;
        for (std::size_t e = 0; e < rows.size() && apart; ++e) apart = !rows[e][o] || !rows[e][l];
        if (!apart) continue;
        for (std::size_t e = 0; e < rows.size(); ++e)
          if (rows[e][o]) rows[e][l] = rows[e][o];
        for (std::size_t i = 0; i < at[o].length.size(); ++i)
          for (std::size_t e = 0; e < at[o].length[i].size(); ++e)
            if (!std::isnan(at[o].length[i][e])) {
              at[l].length[i][e] = at[o].length[i][e];
              at[l].value[i][e] = at[o].value[i][e];
            }
        at[l].present += at[o].present;
        at[o].present = 0;
        for (auto& v : at[o].length) std::ranges::fill(v, kAbsent);
        for (auto& v : at[o].value) std::ranges::fill(v, kAbsent);
        leader_of[o] = l;
        break;
      }
    }
    return leader_of;
  }

  // A run of tiles beside a special tile of the same length (shop bays
  // before and after an entrance bay at any place): where the count of a
  // repeat's tiles, in every example showing four or more, is a straight
  // line of a size drawn before it (the run's share, ~s1 of a row of
  // bays ~4.4 each: s1 / 4.4 tiles; the rest's, 5 - s1 / 4.4), the
  // repeat takes that count, and its tiles are the run's own. Drawn, the
  // tile size put runs of tiles unlike the entrance beside it.
  std::optional<Linear> count_line(const Region& r, const std::vector<Quantity>& quantities,
                                   const std::vector<std::size_t>& leaders,
                                   const std::vector<std::size_t>& leader_param, const SplitLengths& tiles) const {
    const std::vector<double>& count = tiles.value[0];
    for (std::size_t l = 0; l < leaders.size(); ++l) {
      const Quantity& L = quantities[leaders[l]];
      if (is_tile_size(r, L.occurrence)) continue;
      const auto [x, y] = paired(L.values, count);
      if (x.size() < opt_.min_examples || !shows_a_line(x, opt_.tolerance) || !varies(y, 0.5)) continue;
      const Fit fit = line_fit(x, y);
      if (worst_miss(x, y, fit.a, fit.b) > 1e-6) continue;
      const Fit s = short_line(x, y, Fit{fit.a, fit.b, 0, 1}, 1e-6);
      Linear f;
      f.c0 = s.a;
      f.add(leader_param[l], s.b);
      return f;
    }
    return std::nullopt;
  }

  // The formula of an earlier quantity that Q equals in every example
  // showing both (at least min_equal, while it varies), where that one is
  // a function of the draws and not one itself; none else.
  std::optional<Linear> equal_to_earlier(std::size_t q, const std::vector<Quantity>& quantities,
                                         const std::vector<std::vector<std::optional<Linear>>>& formula,
                                         const Region& r) const {
    const Quantity& Q = quantities[q];
    for (std::size_t e = 0; e < q; ++e) {
      const Quantity& E = quantities[e];
      const auto& f = formula[E.occurrence][E.part];
      if (!f || f->c.empty() || is_tile_size(r, E.occurrence) != is_tile_size(r, Q.occurrence)) continue;
      if (E.relative != Q.relative) continue;
      const auto [x, y] = paired(E.values, Q.values);
      if (x.size() < opt_.min_equal || !varies(x, opt_.tolerance)) continue;
      if (worst_miss(x, y, 0, 1) <= opt_.tolerance / 4) return f;
    }
    return std::nullopt;
  }

  bool is_tile_size(const Region& r, std::size_t occurrence) const {
    return std::holds_alternative<Repeat>(g_.op(r.splits[occurrence].split));
  }

  // The draw of a repeat's tile size from its tiles (tile_draws.hpp).
  Distribution tile_size_draw(const SplitLengths& s, const FitOptions& fit, const std::vector<Observation>& lengths) const {
    std::vector<TileRun> runs;
    for (std::size_t e = 0; e < s.length[0].size(); ++e)
      if (!std::isnan(s.length[0][e]) && !std::isnan(s.value[0][e])) runs.push_back({s.length[0][e], s.value[0][e]});
    return tile_size_distribution(runs, lengths, fit, opt_.tolerance);
  }

  Grammar& g_;
  const JointSizesOptions& opt_;
};

}  // namespace

JointSizes join_sizes(Grammar& g, const std::vector<Example>& examples, const JointSizesOptions& options) {
  JointSizes out;
  if (examples.size() < std::min(options.min_examples, options.min_equal)) return out;
  std::vector<Example> placed;
  for (const Example& e : examples) placed.push_back(boxes_at_origin(e));
  CheckOptions check;
  check.tolerance = options.tolerance;
  check.witness = false;  // the parts' lengths are all this step reads
  check.learned_order = true;  // any derivation's lengths will do
  auto check_all = [&](const Grammar& grammar, std::vector<CheckResult>& results) {
    return derives_examples(grammar, placed, check, options.threads, results);
  };
  std::vector<CheckResult> results;
  if (!check_all(g, results)) return out;
  // Every return below leaves a grammar checked: this one, or the
  // rewritten one checked again.
  out.derives_examples = true;

  std::vector<Joiner::Seen> seen(results.size());
  Joiner::Runners runners;
  for (std::size_t i = 0; i < results.size(); ++i)
    for (const MatchedPart& m : results[i].parts) {
      std::vector<MatchedPart>& at = seen[i][m.path];
      if (at.empty()) runners[m.path].push_back(i);
      at.push_back(m);
    }

  // Regions whose sizes follow each other, then splits that vary in one
  // way only; checked once for both (checking is most of this step's
  // time), and again only if that fails.
  const Grammar before = g;
  auto regions_joined = [&] {
    Regions regions(g);
    Joiner joiner(g, options);
    std::vector<NodeId> replace;
    // Outer regions first: one rewritten holds its alternatives' sizes
    // already, and its copy no longer holds their roots.
    std::vector<bool> done(regions.all().size(), false);
    for (std::size_t k = 0; k < regions.all().size(); ++k) {
      const Region& r = regions.all()[k];
      if (r.parent != Region::kNoRegion && done[r.parent]) {
        done[k] = true;
        continue;
      }
      if (r.splits.empty() || !regions.unique(r)) continue;
      const auto call = joiner.region(regions, r, seen, runners, out);
      if (!call) continue;
      done[k] = true;
      if (replace.size() <= r.root) replace.resize(r.root + 1, kNoReplacement);
      replace[r.root] = *call;
    }
    if (out.regions == 0) return;
    for (Rule& rule : g.rules) rule.body = substitute(g, rule.body, replace);
  };
  auto splits_shared = [&] {
    // The runs seen in regions just rewritten no longer happen; they only
    // widen the shares of the splits still called elsewhere.
    const std::size_t shared =
        share_splits(g, results, {options.tolerance, options.uniform_distributions, options.threads});
    out.joined += shared;
    return shared;
  };
  regions_joined();
  splits_shared();
  if (out.joined == 0) return out;
  drop_unused_rules(g);
  check.answer_only = true;  // from here on, only whether every example derives
  std::vector<CheckResult> again;
  if (check_all(g, again)) return out;
  // Most likely a region's order of draws that check cannot follow: the
  // splits alone.
  g = before;
  out = {};
  out.derives_examples = true;
  if (splits_shared() > 0) {
    drop_unused_rules(g);
    if (check_all(g, again)) return out;
  }
  g = before;
  return {0, 0, true};
}

}  // namespace vern
