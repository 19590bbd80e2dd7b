#include "inverse/merge/self_nesting.hpp"

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "graph/structural.hpp"
#include "inverse/merge/merge.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/sizes/fit_distribution.hpp"
#include "inverse/sizes/levels_left.hpp"
#include "inverse/sizes/size_plan.hpp"

namespace vern {

namespace {

// Where the context F holds the rest of the chain.
constexpr NodeId kHole = static_cast<NodeId>(-2);
// Longest context looked for: a tier is three splits (z, then x and y
// round the inset).
constexpr std::size_t kMaxPeriod = 4;
// How far down a spine is followed: 64 tiers of a four-split context.
constexpr std::size_t kMaxSpine = 256;

// One way of reading a node as F applied k times to B.
struct Reading {
  std::size_t key = 0;  // which (F, B)
  std::size_t k = 0;
};

// F (its p splits, sizes blanked, the hole marked) and B.
struct Key {
  std::vector<Operation> context;
  NodeId base = 0;
  std::vector<bool> loose;  // per level of F: every chain's level there lone (flags unsettled)
  friend bool operator==(const Key&, const Key&) = default;
};

class Nester {
 public:
  Nester(Grammar& g, SampleBook& book, double tolerance, const RowBook& rows)
      : g_(g), book_(book), tol_(tolerance), rows_(rows), read_(g.node_count(), false), readings_(g.node_count()) {}

  SelfNesting run(NodeId root) {
    read_all(root);
    // A key folds only where some example nests F twice over: F[B] alone
    // is any node, and says nothing about recursion.
    std::vector<bool> nests(keys_.size(), false);
    for (const auto& node_readings : readings_)
      for (const Reading& r : node_readings) nests[r.key] = nests[r.key] || r.k >= 2;
    prefer_one_phase(nests);
    const std::vector<std::vector<std::size_t>> groups = groups_of_contexts(nests);
    std::vector<bool> placed(g_.node_count(), false);
    place(root, nests, placed);
    SelfNesting out;
    std::vector<NodeId> replace(g_.node_count(), kNoReplacement);
    for (const std::vector<std::size_t>& group : groups) {
      std::vector<std::pair<NodeId, std::size_t>> chains;  // every chain of the group, with its base's key
      for (std::size_t key : group)
        for (const auto& [top, k] : occurrences_[key]) chains.emplace_back(top, key);
      if (chains.empty()) continue;
      const std::optional<Nest> nest = recursive_rule(group);
      if (!nest) continue;
      ++out.rules;
      std::vector<Expr> args;
      if (nest->counted) args.push_back(count_drawn(group));
      const NodeId call = g_.intern({Call{nest->rule, std::move(args)}, {}});
      for (const auto& [top, key] : chains) replace[top] = call;
    }
    out.root = out.rules ? substitute(g_, root, replace, &out.rebuilt) : root;
    return out;
  }

  // The part of a split where its spine goes on: its one child that is a
  // split, else its one child that is not empty space (the innermost
  // tier's box, inset in its air), else none.
  std::optional<std::size_t> spine_part(NodeId id) const {
    const auto* s = std::get_if<Split>(&g_.op(id));
    if (!s) return std::nullopt;
    std::optional<std::size_t> split, solid;
    std::size_t splits = 0, solids = 0;
    for (std::size_t i = 0; i < s->parts.size(); ++i) {
      const Operation& child = g_.op(s->parts[i].child);
      if (std::holds_alternative<Split>(child)) {
        split = i;
        ++splits;
      }
      if (!std::holds_alternative<Nil>(child)) {
        solid = i;
        ++solids;
      }
    }
    if (splits == 1) return split;
    if (splits == 0 && solids == 1) return solid;
    return std::nullopt;
  }

  // The split with its ranges blanked and its spine child a hole: what
  // two levels of one context share.
  Operation shape(NodeId id, std::size_t hole) const {
    Split s = std::get<Split>(g_.op(id));
    for (SplitPart& p : s.parts)
      if (literal_range(p.size.value)) p.size.value = Expr::number(0);
    s.parts[hole].child = kHole;
    return s;
  }

  // One example's split, never unified: its relative flags say nothing
  // (self_nesting.hpp).
  bool lone(NodeId id) const { return lone_split(g_, id, rows_); }

  // Is level b (a shape) a level of context level a: the same, or the
  // same but for relative flags where b is lone?
  static bool fits(const Operation& a, const Operation& b, bool b_lone) {
    if (a == b) return true;
    if (!b_lone) return false;
    Split flagged = std::get<Split>(b);
    const Split& with = std::get<Split>(a);
    if (flagged.parts.size() != with.parts.size()) return false;
    for (std::size_t i = 0; i < flagged.parts.size(); ++i) flagged.parts[i].size.relative = with.parts[i].size.relative;
    return Operation{std::move(flagged)} == a;
  }

  // The node and the spine below it: spine.size() == shapes.size() + 1;
  // loose[i]: level i is lone.
  void spine_of(NodeId id, std::vector<NodeId>& spine, std::vector<Operation>& shapes, std::vector<bool>& loose) const {
    spine.assign(1, id);
    shapes.clear();
    loose.clear();
    while (shapes.size() < kMaxSpine) {
      const auto part = spine_part(spine.back());
      if (!part) break;
      loose.push_back(lone(spine.back()));
      shapes.push_back(shape(spine.back(), *part));
      spine.push_back(std::get<Split>(g_.op(spine.back())).parts[*part].child);
    }
  }

  std::size_t key_id(Key key) {
    std::size_t h = key.base;
    for (const Operation& f : key.context) h = h * 1000003u ^ shallow_hash(f);
    auto& same_hash = key_by_hash_[h];
    for (std::size_t i : same_hash)
      if (keys_[i] == key) return i;
    same_hash.push_back(keys_.size());
    keys_.push_back(std::move(key));
    occurrences_.emplace_back();
    return keys_.size() - 1;
  }

  // Every reading of every node below root, for each period p: F its
  // first p levels, k how often they repeat, B the spine node after them.
  void read_all(NodeId root) {
    std::vector<NodeId> stack{root}, spine;
    std::vector<Operation> shapes, context;
    std::vector<bool> loose;
    while (!stack.empty()) {
      const NodeId id = stack.back();
      stack.pop_back();
      if (read_[id]) continue;
      read_[id] = true;
      for_each_child(g_.op(id), [&](NodeId c) { stack.push_back(c); });
      spine_of(id, spine, shapes, loose);
      for (std::size_t p = 1; p <= kMaxPeriod && p <= shapes.size(); ++p) {
        // The context is the first p levels, each replaced by the first
        // settled level a whole number of periods below it while it is
        // lone: a lone top tier reads as the levels under it.
        context.assign(shapes.begin(), shapes.begin() + static_cast<std::ptrdiff_t>(p));
        std::vector<bool> settled(p);
        for (std::size_t j = 0; j < p; ++j) settled[j] = !loose[j];
        std::size_t k = 1;
        while ((k + 1) * p <= shapes.size()) {
          bool same = true;
          for (std::size_t j = 0; j < p && same; ++j) {
            const std::size_t at = k * p + j;
            same = settled[j] ? fits(context[j], shapes[at], loose[at]) : fits(shapes[at], context[j], true);
          }
          if (!same) break;
          for (std::size_t j = 0; j < p; ++j)
            if (!settled[j] && !loose[k * p + j]) {
              context[j] = shapes[k * p + j];
              settled[j] = true;
            }
          ++k;
        }
        std::vector<bool> unsettled(p);
        for (std::size_t j = 0; j < p; ++j) unsettled[j] = !settled[j];
        Key key{context, spine[k * p], std::move(unsettled)};
        readings_[id].push_back({key_id(std::move(key)), k});
      }
    }
  }

  // One nesting read from two places a split apart is one context turned
  // (z, x, y and x, y, z: towers that fill their plot's height, and towers
  // under air, whose chains start at the inset). Of the keys whose
  // contexts are turns of each other, only the one with the smallest base
  // folds (the chains end at the innermost tier's box, not at a partial
  // context round it); a node read only by the others is passed, and its
  // spine reaches that key's chain a split or two lower.
  void prefer_one_phase(std::vector<bool>& nests) const {
    std::vector<std::size_t> nesting;
    for (std::size_t k = 0; k < keys_.size(); ++k)
      if (nests[k]) nesting.push_back(k);
    std::vector<std::size_t> size(keys_.size(), 0);
    for (std::size_t k : nesting) size[k] = subgraph_size(keys_[k].base);
    for (std::size_t a : nesting)
      for (std::size_t b : nesting) {
        if (a == b || keys_[a].context == keys_[b].context || !turned(keys_[a].context, keys_[b].context)) continue;
        if (size[b] < size[a] || (size[b] == size[a] && b < a)) nests[a] = false;
      }
  }

  // The keys that fold into one rule: those of one context, whatever the
  // base each chain ends at (tiers capped by a roof, a hip or a pyramid
  // are one recursion whose last step chooses the cap). A key that does
  // not nest joins its context's group where its base is no larger than
  // one the group's nesting chains end at (a two-tier tower under the
  // cap only it has), and folds with it. Groups in the order of their
  // first key.
  std::vector<std::vector<std::size_t>> groups_of_contexts(std::vector<bool>& nests) const {
    // Contexts are looked up by a hash blind to relative flags, which a
    // lone level's do not settle.
    std::unordered_map<std::size_t, std::vector<std::size_t>> by_context;
    auto hash_of = [&](std::size_t k) {
      std::size_t h = 0;
      for (const Operation& f : keys_[k].context) {
        Split blind = std::get<Split>(f);
        for (SplitPart& part : blind.parts) part.size.relative = true;
        h = h * 1000003u ^ shallow_hash(Operation{std::move(blind)});
      }
      return h;
    };
    auto alike = [&](std::size_t a, std::size_t b) {
      const Key& ka = keys_[a];
      const Key& kb = keys_[b];
      if (ka.context.size() != kb.context.size()) return false;
      for (std::size_t j = 0; j < ka.context.size(); ++j) {
        if (ka.loose[j]) {
          if (!fits(kb.context[j], ka.context[j], true)) return false;
        } else if (!fits(ka.context[j], kb.context[j], kb.loose[j])) {
          return false;
        }
      }
      return true;
    };
    auto loose_levels = [&](std::size_t k) { return std::count(keys_[k].loose.begin(), keys_[k].loose.end(), true); };
    for (std::size_t k = 0; k < keys_.size(); ++k) by_context[hash_of(k)].push_back(k);
    std::vector<std::vector<std::size_t>> groups;
    std::vector<bool> grouped(keys_.size(), false);
    for (std::size_t a = 0; a < keys_.size(); ++a) {
      if (grouped[a] || !nests[a]) continue;
      std::vector<std::size_t> candidates;  // the keys of a's context, a first
      for (std::size_t b : by_context.at(hash_of(a)))
        if (!grouped[b] && (b == a || alike(a, b))) candidates.push_back(b);
      std::vector<std::size_t> group;
      std::size_t largest = 0;
      for (std::size_t b : candidates)
        if (nests[b]) {
          group.push_back(b);
          grouped[b] = true;
          largest = std::max(largest, subgraph_size(keys_[b].base));
        }
      for (std::size_t b : candidates)
        if (!nests[b] && subgraph_size(keys_[b].base) <= largest) {
          group.push_back(b);
          grouped[b] = true;
          nests[b] = true;
        }
      // The context written is the most settled one's.
      std::stable_sort(group.begin(), group.end(),
                       [&](std::size_t x, std::size_t y) { return loose_levels(x) < loose_levels(y); });
      groups.push_back(std::move(group));
    }
    return groups;
  }

  // Is b's context a's turned by some number of levels (or the same)?
  static bool turned(const std::vector<Operation>& a, const std::vector<Operation>& b) {
    const std::size_t p = a.size();
    if (b.size() != p) return false;
    for (std::size_t r = 0; r < p; ++r) {
      bool same = true;
      for (std::size_t i = 0; i < p && same; ++i) same = a[i] == b[(i + r) % p];
      if (same) return true;
    }
    return false;
  }

  std::size_t subgraph_size(NodeId root) const {
    std::vector<NodeId> stack{root};
    std::unordered_set<NodeId> seen;
    while (!stack.empty()) {
      const NodeId id = stack.back();
      stack.pop_back();
      if (!seen.insert(id).second) continue;
      for_each_child(g_.op(id), [&](NodeId c) { stack.push_back(c); });
    }
    return seen.size();
  }

  // Top down: a node with a reading of a nesting key is a chain, taken
  // whole (its deepest reading); below it only what F holds beside the
  // chain and B are looked at again.
  void place(NodeId id, const std::vector<bool>& nests, std::vector<bool>& placed) {
    if (placed[id]) return;
    placed[id] = true;
    const Reading* best = nullptr;
    std::size_t best_depth = 0;
    for (const Reading& r : readings_[id]) {
      const std::size_t depth = r.k * keys_[r.key].context.size();
      if (nests[r.key] && depth > best_depth) {
        best = &r;
        best_depth = depth;
      }
    }
    if (!best) {
      for_each_child(g_.op(id), [&](NodeId c) { place(c, nests, placed); });
      return;
    }
    occurrences_[best->key].emplace_back(id, best->k);
    const Key& key = keys_[best->key];
    NodeId level = id;
    for (const Operation& f : key.context) {
      const Split& s = std::get<Split>(g_.op(level));
      const Split& shaped = std::get<Split>(f);
      for (std::size_t i = 0; i < s.parts.size(); ++i)
        if (shaped.parts[i].child != kHole) place(s.parts[i].child, nests, placed);
        else level = s.parts[i].child;
    }
    place(key.base, nests, placed);
  }

  // How many levels a counted recursion is called with, wherever it is
  // called: the counts its chains showed (count_expr).
  Expr count_drawn(const std::vector<std::size_t>& group) const {
    std::vector<double> counts;
    for (std::size_t key : group)
      for (const auto& [top, k] : occurrences_[key]) counts.push_back(static_cast<double>(k));
    return count_expr(std::move(counts));
  }

  // A recursive rule made for a key: called nest(k) for a chain of k
  // contexts where it counts them, else nest.
  struct Nest {
    RuleId rule = 0;
    bool counted = false;
  };

  // Where a group's chains stop: their one base, or a choice of the bases
  // weighted by how many chains stopped at each.
  NodeId base_of(const std::vector<std::size_t>& group) {
    Choose bases;
    for (std::size_t key : group)
      if (!occurrences_[key].empty())
        bases.options.push_back(
            {Expr{}, Expr::number(static_cast<double>(occurrences_[key].size())), keys_[key].base});
    if (bases.options.size() == 1) return bases.options[0].child;
    return g_.intern({std::move(bases), {}});
  }

  // The rule for one group of keys: its counted form where every level
  // has one count of levels left, else nest --> B | F[nest]; B the choice
  // of their bases. Nullopt when some level's sizes are not ranges to
  // widen.
  std::optional<Nest> recursive_rule(const std::vector<std::size_t>& group) {
    const std::vector<Operation>& context = keys_[group.front()].context;
    const std::size_t p = context.size();
    // Each level of F: every node at that level in every chain.
    std::vector<std::vector<NodeId>> members(p);
    double went_on = 0, stopped = 0;
    // Each level's count of contexts left, its own (below it, the chain
    // is its subtree): one node seen at two counts has none.
    std::unordered_map<NodeId, int> left;
    bool counted = true;
    for (std::size_t key : group) {
      for (const auto& [top, k] : occurrences_[key]) {
        NodeId level = top;
        for (std::size_t j = 0; j < k * p; ++j) {
          members[j % p].push_back(level);
          const int n = static_cast<int>(k - j / p);
          const auto [at, added] = left.emplace(level, n);
          counted = counted && (added || at->second == n);
          level = std::get<Split>(g_.op(level)).parts[hole_of(context[j % p])].child;
        }
        went_on += static_cast<double>(k);
        stopped += 1;
      }
    }
    // A chain inside another (a four-tier tower's upper three tiers, also
    // seen as a three-tier tower) brings its levels once.
    for (auto& level : members) {
      std::sort(level.begin(), level.end());
      level.erase(std::unique(level.begin(), level.end()), level.end());
    }
    // The levels' sizes and their values.
    std::vector<Split> levels;
    std::vector<std::vector<std::vector<Observation>>> kept(p);
    for (std::size_t i = 0; i < p; ++i) {
      // The context's flags: a lone level's say nothing.
      Split s = std::get<Split>(g_.op(members[i][0]));
      const Split& flags = std::get<Split>(context[i]);
      for (std::size_t q = 0; q < s.parts.size(); ++q) s.parts[q].size.relative = flags.parts[q].size.relative;
      kept[i].resize(s.parts.size());
      for (std::size_t q = 0; q < s.parts.size(); ++q) {
        std::optional<Range> all;
        bool known = true;
        for (NodeId m : members[i]) {
          const Expr& size = std::get<Split>(g_.op(m)).parts[q].size.value;
          const auto r = literal_range(size);
          if (!r) {
            if (size == s.parts[q].size.value) continue;  // the same expression at every level
            return std::nullopt;
          }
          all = all ? Range{std::min(all->lo, r->lo), std::max(all->hi, r->hi)} : *r;
          const auto booked = book_.find(m);
          if (booked != book_.end() && q < booked->second.size() && !booked->second[q].empty()) {
            const auto& seen = booked->second[q];
            kept[i][q].insert(kept[i][q].end(), seen.begin(), seen.end());
          } else if (r->lo == r->hi) {
            kept[i][q].push_back({r->lo, 1});
          } else {
            known = false;
          }
        }
        if (all) s.parts[q].size.value = range_expr(*all, tol_);
        if (!known || !all) kept[i][q].clear();
      }
      if (stopped >= 2) fix_across_levels(s, members[i], kept[i]);  // two towers or more
      levels.push_back(std::move(s));
    }
    const NodeId base = base_of(group);
    if (counted) return Nest{counted_rule(context, base, members, left, levels, kept), true};
    // The rule first, so that F's innermost level can call it.
    const auto rule = static_cast<RuleId>(g_.rules.size());
    g_.rules.push_back({"nest", {}, 0, {}});
    const NodeId call = g_.intern({Call{rule, {}}, {}});
    NodeId inner = call;
    for (std::size_t i = p; i-- > 0;) {
      Split s = levels[i];
      s.parts[hole_of(context[i])].child = inner;
      inner = g_.intern({std::move(s), {}});
      book_[inner] = kept[i];
    }
    Choose nest;
    nest.options.push_back({Expr{}, Expr::number(stopped), base});
    nest.options.push_back({Expr{}, Expr::number(went_on), inner});
    g_.rules[rule].body = g_.intern({std::move(nest), {}});
    return Nest{rule, false};
  }

  // A part of the same length at every level while the levels' lengths
  // differ (a tier's margins, 1.2 m at each level set in) is that length
  // in metres. The examples alone may not say so: on plots of one depth
  // every tower's first level is as deep, and merging left the margins
  // shares; the levels, set in one inside the other, show it. Only from
  // two towers or more (the caller's part): one tower's drums may be
  // equal as shares are (each a third of a three-tier crown), and another
  // tower's, equal among themselves, of another length.
  void fix_across_levels(Split& s, const std::vector<NodeId>& members,
                         std::vector<std::vector<Observation>>& kept) const {
    std::vector<std::vector<double>> rows;
    for (const NodeId m : members) {
      std::vector<double> row;
      for (const SplitPart& part : std::get<Split>(g_.op(m)).parts) {
        const auto r = literal_range(part.size.value);
        if (!r || r->hi - r->lo > tol_) return;
        row.push_back(r->lo);
      }
      rows.push_back(std::move(row));
    }
    if (rows.size() < 2) return;
    const auto plan = plan_sizes(rows, tol_);
    if (!plan) return;
    for (std::size_t q = 0; q < s.parts.size() && q < plan->size(); ++q) {
      if (!(*plan)[q].absolute || !(*plan)[q].fixed) continue;
      s.parts[q].size = {Expr::number((*plan)[q].value), false};
      kept[q] = {{(*plan)[q].value, 1}};
    }
  }

  // nest(n) --> B where n <= 0, F[nest(n - 1)] where n > 0, with F's
  // sizes in n where they follow the count of levels left
  // (levels_left.hpp), else their ranges, and each chain a call nest(k),
  // k drawn from the counts the examples show. Counted even where no size
  // follows n: a pagoda of three to six tiers has three to six, where
  // stopping at each level with the odds seen gives towers of one tier
  // and of ten.
  RuleId counted_rule(const std::vector<Operation>& context, NodeId base,
                                     const std::vector<std::vector<NodeId>>& members,
                                     const std::unordered_map<NodeId, int>& left, const std::vector<Split>& ranged,
                                     const std::vector<std::vector<std::vector<Observation>>>& kept) {
    const std::size_t p = context.size();
    std::vector<std::vector<LevelPart>> levels(p);
    for (std::size_t i = 0; i < p; ++i) {
      const std::size_t parts = std::get<Split>(g_.op(members[i][0])).parts.size();
      levels[i].resize(parts);
      // Relative weights are compared as shares of each member's relative
      // total, on the scale of the largest: members merged apart (tiers
      // under a roof and tiers under a hip) write one share in weights of
      // different scales.
      const Split& flags = std::get<Split>(context[i]);  // a lone level's own say nothing
      std::vector<double> totals;
      for (NodeId m : members[i]) totals.push_back(relative_total(std::get<Split>(g_.op(m)), flags));
      const double scale = *std::max_element(totals.begin(), totals.end());
      for (std::size_t k = 0; k < members[i].size(); ++k) {
        const NodeId m = members[i][k];
        const Split& s = std::get<Split>(g_.op(m));
        for (std::size_t q = 0; q < parts; ++q) {
          LevelPart& part = levels[i][q];
          part.relative = flags.parts[q].size.relative;
          const auto r = literal_range(s.parts[q].size.value);
          if (!r || r->hi - r->lo > tol_) {
            part.ranged = true;
            continue;
          }
          const double v = (r->lo + r->hi) / 2;
          part.seen.emplace_back(left.at(m), part.relative && totals[k] > 0 ? v / totals[k] * scale : v);
        }
      }
    }
    auto sizes = sizes_by_levels_left(levels, tol_);
    if (!sizes) {
      sizes.emplace(p);
      for (std::size_t i = 0; i < p; ++i) (*sizes)[i].resize(levels[i].size());
    }
    const auto rule = static_cast<RuleId>(g_.rules.size());
    g_.rules.push_back({"nest", {"n"}, 0, {}});
    const Expr n = Expr::param(0);
    NodeId inner = g_.intern({Call{rule, {Expr::binary(BinaryOp::Sub, n, Expr::number(1))}}, {}});
    for (std::size_t i = p; i-- > 0;) {
      Split s = ranged[i];
      std::vector<std::vector<Observation>> values = kept[i];
      for (std::size_t q = 0; q < s.parts.size(); ++q) {
        if (!(*sizes)[i][q]) continue;
        s.parts[q].size = *(*sizes)[i][q];
        values[q].clear();  // a size in n, not a range of values
      }
      s.parts[hole_of(context[i])].child = inner;
      inner = g_.intern({std::move(s), {}});
      book_[inner] = std::move(values);
    }
    Choose nest;
    nest.options.push_back({Expr::binary(BinaryOp::Le, n, Expr::number(0)), Expr::number(1), base});
    nest.options.push_back({Expr::binary(BinaryOp::Gt, n, Expr::number(0)), Expr::number(1), inner});
    g_.rules[rule].body = g_.intern({std::move(nest), {}});
    return rule;
  }

  // The sum of a split's weights (the middles of ranges) at the parts
  // relative in `flags`.
  static double relative_total(const Split& s, const Split& flags) {
    double total = 0;
    for (std::size_t q = 0; q < s.parts.size(); ++q)
      if (const auto r = literal_range(s.parts[q].size.value); r && flags.parts[q].size.relative)
        total += (r->lo + r->hi) / 2;
    return total;
  }

  static std::size_t hole_of(const Operation& shaped) {
    const Split& s = std::get<Split>(shaped);
    for (std::size_t i = 0; i < s.parts.size(); ++i)
      if (s.parts[i].child == kHole) return i;
    return 0;
  }

  Grammar& g_;
  SampleBook& book_;
  double tol_;
  const RowBook& rows_;
  std::vector<bool> read_;
  std::vector<std::vector<Reading>> readings_;  // by node id
  std::vector<Key> keys_;
  std::unordered_map<std::size_t, std::vector<std::size_t>> key_by_hash_;
  std::vector<std::vector<std::pair<NodeId, std::size_t>>> occurrences_;  // by key: chain tops and their k
};

}  // namespace

SelfNesting fold_self_nesting(Grammar& g, NodeId root, SampleBook& book, double tolerance, const RowBook& rows) {
  return Nester(g, book, tolerance, rows).run(root);
}

}  // namespace vern
