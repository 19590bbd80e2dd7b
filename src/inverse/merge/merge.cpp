#include "inverse/merge/merge.hpp"

#include "inverse/merge/equal_options.hpp"
#include "inverse/merge/empty_runs.hpp"
#include "inverse/merge/generalise.hpp"
#include "inverse/merge/inset_runs.hpp"
#include "inverse/merge/repeat_folding.hpp"
#include "inverse/merge/sample_book.hpp"
#include "inverse/merge/self_nesting.hpp"
#include "inverse/merge/size_clusters.hpp"
#include "inverse/merge/tile_choices.hpp"
#include "inverse/merge/tile_lengths.hpp"
#include "inverse/sizes/alternative_lengths.hpp"
#include "inverse/sizes/drawn_sizes.hpp"
#include "inverse/sizes/fit_distribution.hpp"
#include "inverse/sizes/settle_repeats.hpp"
#include "inverse/sizes/size_plan.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <span>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "base/overload.hpp"
#include "graph/nodes_below.hpp"
#include "graph/structural.hpp"

namespace vern {

std::optional<Range> literal_range(const Expr& e) {
  if (auto v = e.literal()) return Range{*v, *v};
  const ExprNode& root = e.node(e.root());
  if (root.kind != ExprKind::Call || static_cast<Function>(root.op) != Function::Rand || root.argc != 2 ||
      e.nodes().size() != 3)
    return std::nullopt;
  const ExprNode& a = e.node(0);
  const ExprNode& b = e.node(1);
  if (a.kind != ExprKind::Number || b.kind != ExprKind::Number) return std::nullopt;
  return Range{std::min(a.number, b.number), std::max(a.number, b.number)};
}

bool lone_split(const Grammar& g, NodeId id, const RowBook& rows) {
  if (rows.count(id)) return false;
  for (const auto& p : std::get<Split>(g.op(id)).parts) {
    const auto r = literal_range(p.size.value);
    if (!r || r->lo != r->hi) return false;
  }
  return true;
}

Expr range_expr(Range r, double tolerance) {
  if (r.hi - r.lo <= tolerance) return Expr::number(r.lo);
  return Expr::call(Function::Rand, {Expr::number(r.lo), Expr::number(r.hi)});
}

namespace {

// In how many examples each node occurs: a value seen in three examples
// is three observations of the style, while one example's six equal
// windows are one decision, observed once.
struct ExampleCounts {
  std::vector<double> counts;       // by node id: how many examples it occurs in
  std::vector<std::int64_t> only;   // by node id: the one example, where it occurs in one (else -1)
  double of(NodeId id) const { return id < counts.size() && counts[id] > 0 ? counts[id] : 1.0; }
  std::int64_t example_of(NodeId id) const { return id < only.size() && counts[id] == 1 ? only[id] : -1; }
};

ExampleCounts example_counts(const Grammar& g, const std::vector<NodeId>& roots) {
  std::vector<double> counts(g.node_count(), 0.0);
  std::vector<std::uint32_t> seen_in(g.node_count(), 0);  // 1 + the last example that reached it
  for (std::uint32_t e = 0; e < roots.size(); ++e) {
    std::vector<NodeId> stack{roots[e]};
    while (!stack.empty()) {
      const NodeId id = stack.back();
      stack.pop_back();
      if (seen_in[id] == e + 1) continue;
      seen_in[id] = e + 1;
      counts[id] += 1;
      for_each_child(g.op(id), [&](NodeId c) { stack.push_back(c); });
    }
  }
  std::vector<std::int64_t> only(g.node_count(), -1);
  for (NodeId id = 0; id < g.node_count(); ++id)
    if (counts[id] == 1) only[id] = static_cast<std::int64_t>(seen_in[id]) - 1;
  return {std::move(counts), std::move(only)};
}

// Unifies nodes of equal structure anywhere below a root (thesis 10.3):
// the same operation, axis, relative flags, counts and children (after
// unification), whatever their sizes. Each group becomes one node whose
// sizes are ranges over its members, so parents whose children now
// coincide fall into one group in turn. Bottom-up, one pass: a node's key
// names its children's groups, which are settled before it.
class Unifier {
 public:
  // counts: in how many examples each node occurs (example_counts); a
  // node beyond it counts once.
  // copied: by node id, the nodes of placed groups (MergeOptions::placed).
  Unifier(Grammar& g, const MergeOptions& o, SampleBook& book, RowBook& rows, TileCounts& tile_counts,
          const ExampleCounts& counts, const std::vector<bool>& copied)
      : g_(g),
        opt_(o),
        book_(book),
        rows_(rows),
        tile_counts_(tile_counts),
        counts_(counts),
        copied_(copied),
        group_of_(g.node_count(), kNoGroup) {}

  NodeId run(NodeId root) {
    tile_lengths_ = TileLengths(g_, root);
    // Level by level from the leaves: a node's key names its children's
    // groups, and a group is settled (split into its size kinds) only once
    // all its members are known, so children's groups are final before any
    // parent is keyed. A node's level is its height above the leaves.
    std::vector<NodeId> order;
    std::vector<bool> seen(g_.node_count(), false);
    collect(root, seen, order);
    std::vector<std::uint32_t> height(g_.node_count(), 0);
    for (NodeId id : order)
      for_each_child(g_.op(id), [&](NodeId c) { height[id] = std::max(height[id], height[c] + 1); });
    const std::vector<std::size_t> level_starts = sort_by_height(order, height);
    for (std::size_t l = 0; l + 1 < level_starts.size(); ++l)
      settle(order.data() + level_starts[l], order.data() + level_starts[l + 1]);
    std::vector<NodeId> built(groups_.size(), 0);
    for (std::size_t k = 0; k < groups_.size(); ++k) built[k] = build(groups_[k], built);  // each group once
    return built[group_of_.at(root)];
  }

 private:
  static constexpr std::size_t kNoGroup = static_cast<std::size_t>(-1);
  // The form every plain choose shares: no operation's form has this id.
  static constexpr std::size_t kChooseForm = static_cast<std::size_t>(-1);

  struct Group {
    NodeId first = 0;                 // a member: the operation's form
    std::vector<std::size_t> children;  // child groups, in order
    std::vector<Range> ranges;        // per split part (a repeat: its tile size), over the members
    std::vector<double> weights;      // per child, for chooses: summed over the members
    // The values behind each range, and whether every member's are known.
    std::vector<std::vector<Observation>> samples;
    std::vector<bool> sampled;
    // The members' lengths, one row per split of the examples they stand
    // for (a member with literal sizes is one; one built in an earlier
    // round brings its rows), with the times the examples use each, and
    // whether every member's are known.
    std::vector<std::vector<double>> lengths;
    std::vector<double> row_weights;
    std::vector<std::int64_t> row_examples;  // per row: its one example, or -1
    bool rows_complete = true;
    std::size_t members = 0;
    // Repeats: the tile counts the members made where folded, and whether
    // every member's are known.
    std::vector<TileSeen> tile_counts;
    bool counted = true;
  };

  // What makes nodes one group: their form (the operation with its sizes
  // and children blanked, numbered as first seen) and their child groups.
  struct Key {
    std::size_t form = 0;
    std::vector<std::size_t> children;
    std::size_t lengths = 0;  // a repeat's kind of tile length (TileLengths)
    std::size_t sizes = 0;    // the kind of its sizes among its structure's (size_clusters)
    std::size_t copied = 0;   // a node copied as it is: its id + 1
    friend bool operator==(const Key&, const Key&) = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::size_t h =
          hash_combine(hash_combine(hash_combine(hash_combine(k.children.size(), k.form), k.lengths), k.sizes), k.copied);
      for (std::size_t c : k.children) h = hash_combine(h, c);
      return h;
    }
  };

  // A choose without conditions and with literal priorities: what merging
  // makes. Two of them over the same alternatives are one choice, whatever
  // their weights; the weights add up.
  static bool plain(const Choose& c) {
    return std::all_of(c.options.begin(), c.options.end(),
                       [](const ChooseOption& o) { return o.condition.empty() && o.priority.literal(); });
  }

  void visit_choose(NodeId id, const Choose& c, const std::vector<std::size_t>& children) {
    // Each child group's weight, the groups ascending so the key is
    // canonical: options sorted by group, stably, and summed in their
    // order (buffers reused across chooses, not a map per choose).
    auto& weight = choose_weights_;
    weight.clear();
    for (std::size_t i = 0; i < children.size(); ++i) weight.push_back({children[i], *c.options[i].priority.literal()});
    std::stable_sort(weight.begin(), weight.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < weight.size(); ++i) {
      if (distinct > 0 && weight[distinct - 1].first == weight[i].first) weight[distinct - 1].second += weight[i].second;
      else weight[distinct++] = weight[i];
    }
    weight.resize(distinct);
    Key& key = choose_key_;
    key.form = kChooseForm;
    key.children.clear();
    for (const auto& [child, w] : weight) key.children.push_back(child);
    auto it = group_by_key_.find(key);
    if (it == group_by_key_.end()) {
      it = group_by_key_.emplace(key, groups_.size()).first;
      Group group;
      group.first = id;
      group.children = key.children;
      group.weights.assign(key.children.size(), 0);
      groups_.push_back(std::move(group));
    }
    Group& group = groups_[it->second];
    for (std::size_t k = 0; k < group.children.size(); ++k) group.weights[k] += weight[k].second;
    group_of_[id] = it->second;
  }

  // Sorts nodes by height, keeping their order within a height (what a
  // stable sort does, by counting: no merge buffers); returns where each
  // height starts, and the end.
  static std::vector<std::size_t> sort_by_height(std::vector<NodeId>& order, const std::vector<std::uint32_t>& height) {
    std::uint32_t top = 0;
    for (NodeId id : order) top = std::max(top, height[id]);
    std::vector<std::size_t> starts(order.empty() ? 1 : top + 2, 0);
    for (NodeId id : order) ++starts[height[id] + 1];
    for (std::size_t h = 1; h < starts.size(); ++h) starts[h] += starts[h - 1];
    std::vector<std::size_t> at(starts.begin(), starts.end() - 1);
    std::vector<NodeId> sorted(order.size());
    for (NodeId id : order) sorted[at[height[id]]++] = id;
    order = std::move(sorted);
    return starts;
  }

  bool frozen(NodeId id) const { return id < copied_.size() && copied_[id]; }

  // Every node below id once, children before parents.
  void collect(NodeId id, std::vector<bool>& seen, std::vector<NodeId>& order) const {
    if (seen[id]) return;
    seen[id] = true;
    for_each_child(g_.op(id), [&](NodeId c) { collect(c, seen, order); });
    order.push_back(id);
  }

  // What ranges in a node: split part sizes, a repeat's tile size. Read
  // in place, not gathered into a vector per member.
  class Sized {
   public:
    explicit Sized(const Operation& op) {
      if (const auto* s = std::get_if<Split>(&op)) parts_ = s->parts;
      else if (const auto* r = std::get_if<Repeat>(&op)) tile_ = &r->size;
    }
    std::size_t size() const { return tile_ ? 1 : parts_.size(); }
    bool empty() const { return size() == 0; }
    const Expr& operator[](std::size_t i) const { return tile_ ? *tile_ : parts_[i].size.value; }

   private:
    std::span<const SplitPart> parts_;
    const Expr* tile_ = nullptr;
  };

  // Groups the nodes of one level: by key (operation form, child groups),
  // then each key's members by the kinds of their sizes. The level's
  // buckets, its members and the key being looked up live in buffers kept
  // across levels and nodes: allocating them per node was most of the cost.
  void settle(const NodeId* begin, const NodeId* end) {
    bucket_of_.clear();
    bucket_keys_.clear();
    bucket_at_.clear();
    for (const NodeId* at = begin; at != end; ++at) {
      const NodeId id = *at;
      const Operation& op = g_.op(id);
      probe_.children.clear();
      for_each_child(op, [&](NodeId c) { probe_.children.push_back(group_of_[c]); });
      if (const auto* c = std::get_if<Choose>(&op); c && plain(*c)) {
        visit_choose(id, *c, probe_.children);
        bucket_at_.push_back(kNoGroup);
        continue;
      }
      probe_.form = form_id(op);
      // A node of a placed group is a group of its own (MergeOptions::placed).
      probe_.copied = frozen(id) ? id + 1 : 0;
      probe_.lengths = 0;
      if (const auto* r = std::get_if<Repeat>(&op)) probe_.lengths = tile_lengths_.kind(*r);
      probe_.sizes = 0;
      auto it = bucket_of_.find(probe_);
      if (it == bucket_of_.end()) {
        it = bucket_of_.emplace(probe_, bucket_keys_.size()).first;
        bucket_keys_.push_back(probe_);
      }
      bucket_at_.push_back(it->second);
    }
    // Each bucket's members together, in order of their first member and
    // in level order within a bucket (a counting sort).
    bucket_starts_.assign(bucket_keys_.size() + 1, 0);
    for (std::size_t b : bucket_at_)
      if (b != kNoGroup) ++bucket_starts_[b + 1];
    for (std::size_t b = 1; b < bucket_starts_.size(); ++b) bucket_starts_[b] += bucket_starts_[b - 1];
    members_.resize(bucket_starts_.back());
    fill_at_.assign(bucket_starts_.begin(), bucket_starts_.end() - 1);
    for (std::size_t i = 0; i < bucket_at_.size(); ++i)
      if (bucket_at_[i] != kNoGroup) members_[fill_at_[bucket_at_[i]]++] = begin[i];
    for (std::size_t b = 0; b < bucket_keys_.size(); ++b)
      settle_bucket(bucket_keys_[b], {members_.data() + bucket_starts_[b], members_.data() + bucket_starts_[b + 1]});
  }

  // One key's members become groups, one per kind of their sizes.
  void settle_bucket(Key& key, std::span<const NodeId> members) {
    // One member is one kind (size_clusters would say so too).
    if (members.size() == 1) kinds_.assign(1, 0);
    else kinds_ = size_clusters(sized_members(members));
    std::size_t g = kNoGroup;
    for (std::size_t m = 0; m < members.size(); ++m) {
      // Members of one kind in a row are one group: looked up once.
      if (m == 0 || kinds_[m] != kinds_[m - 1]) g = group_of_key(key, kinds_[m], members[m]);
      const Sized sized(g_.op(members[m]));
      if (!sized.empty()) add_member(groups_[g], members[m], sized);
      if (std::holds_alternative<Repeat>(g_.op(members[m]))) {
        Group& group = groups_[g];
        const auto counted = tile_counts_.find(members[m]);
        if (counted == tile_counts_.end()) group.counted = false;
        else group.tile_counts.insert(group.tile_counts.end(), counted->second.begin(), counted->second.end());
      }
      group_of_[members[m]] = g;
    }
  }

  // The group of the key with this kind of sizes; a new one, first is its
  // first member, if there is none yet.
  std::size_t group_of_key(Key& key, std::size_t kind, NodeId first) {
    key.sizes = kind;
    auto it = group_by_key_.find(key);
    if (it == group_by_key_.end()) {
      it = group_by_key_.emplace(key, groups_.size()).first;
      groups_.emplace_back();
      groups_.back().first = first;
      groups_.back().children = key.children;
    }
    return it->second;
  }

  // The members' sizes as size_clusters reads them.
  const std::vector<SizedMember>& sized_members(std::span<const NodeId> members) {
    sized_.resize(members.size());
    for (std::size_t k = 0; k < members.size(); ++k) {
      const NodeId id = members[k];
      SizedMember& m = sized_[k];
      m.sizes.clear();
      m.total = 0;
      const Sized sized(g_.op(id));
      for (std::size_t i = 0; i < sized.size(); ++i) m.sizes.push_back(literal_range(sized[i]));
      m.weight = counts_.of(id);
      // A split built from examples unified has their lengths in its rows:
      // its own sizes, fixed by a plan, may be shares (~3 : ~14 : ~4 of a
      // shop window 0.6 : 2.8 : 0.8 m), which are no lengths to compare.
      if (const auto known = rows_.find(id); known != rows_.end() && std::holds_alternative<Split>(g_.op(id)))
        from_rows(m, known->second);
      // Empty space is what the other parts leave: 0.2 m or 1 m of air
      // above a house are not two kinds of house.
      if (const auto* s = std::get_if<Split>(&g_.op(id))) {
        // Shares of the split: of its relative parts' total, for relative
        // parts (what the absolute ones leave is what they share).
        bool literal = true;
        for (std::size_t i = 0; i < s->parts.size(); ++i) {
          literal = literal && m.sizes[i] && m.sizes[i]->lo == m.sizes[i]->hi;
          if (literal && s->parts[i].size.relative) m.total += m.sizes[i]->lo;
        }
        if (!literal) m.total = 0;
        for (std::size_t i = 0; i < s->parts.size(); ++i) {
          // Nor is a run of tiles: bays before a door bay, two in one
          // example and four in the next, are as long as their count
          // makes them, one kind of run.
          const Operation& child = g_.op(s->parts[i].child);
          if (std::holds_alternative<Nil>(child) || std::holds_alternative<Repeat>(child)) m.sizes[i].reset();
          // An absolute part is a length, not a share.
          else if (!s->parts[i].size.relative && m.total > 0) m.total = -1;
        }
        if (m.total < 0) m.total = 0;
      }
    }
    return sized_;
  }

  // A member's sizes as the ranges of its rows' lengths, and its weight
  // as theirs, where every row has a length for every part.
  static void from_rows(SizedMember& m, const std::vector<LengthRow>& rows) {
    for (const LengthRow& r : rows)
      if (r.lengths.size() != m.sizes.size()) return;
    double weight = 0;
    for (std::size_t i = 0; i < m.sizes.size(); ++i) {
      if (!m.sizes[i]) continue;
      Range range{rows[0].lengths[i], rows[0].lengths[i]};
      for (const LengthRow& r : rows) range = {std::min(range.lo, r.lengths[i]), std::max(range.hi, r.lengths[i])};
      m.sizes[i] = range;
    }
    for (const LengthRow& r : rows) weight += r.weight;
    if (weight > 0) m.weight = weight;
  }

  // Widens the group's ranges by a member's sizes and notes their values.
  void add_member(Group& group, NodeId id, const Sized& sizes) {
    // Each range starts at the first member's own value.
    const bool first_member = group.ranges.empty();
    if (first_member) {
      group.ranges.resize(sizes.size());
      group.samples.resize(sizes.size());
      group.sampled.assign(sizes.size(), true);
    }
    ++group.members;
    const auto booked = book_.find(id);
    std::vector<double>& row = row_;
    row.clear();
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      const auto r = literal_range(sizes[i]);
      if (!r) continue;  // non-literal sizes are part of the key
      Range& range = group.ranges[i];
      range = first_member ? *r : Range{std::min(range.lo, r->lo), std::max(range.hi, r->hi)};
      if (booked != book_.end() && i < booked->second.size() && !booked->second[i].empty()) {
        const auto& values = booked->second[i];
        group.samples[i].insert(group.samples[i].end(), values.begin(), values.end());
      } else if (r->lo == r->hi) {
        group.samples[i].push_back({r->lo, counts_.of(id), counts_.example_of(id)});
      } else {
        group.sampled[i] = false;  // a range whose values were not kept
      }
      if (r->lo == r->hi) row.push_back(r->lo);
    }
    // A member built from a group keeps its members' rows: its own sizes,
    // fixed by a plan (a share ~18.7 of every width seen), are no lengths.
    if (const auto rows = rows_.find(id); rows != rows_.end()) {
      for (const LengthRow& r : rows->second) {
        group.lengths.push_back(r.lengths);
        group.row_weights.push_back(r.weight);
        group.row_examples.push_back(r.example);
      }
    } else if (row.size() == sizes.size()) {
      group.lengths.push_back(row);
      group.row_weights.push_back(counts_.of(id));
      group.row_examples.push_back(counts_.example_of(id));
    } else {
      group.rows_complete = false;
    }
  }

  // Everything that must agree for two nodes to be one, sizes and children
  // excepted: the operation with its numbers blanked. Two blank forms with
  // one hash may still differ: each distinct form gets its own id by
  // comparing with the forms seen under that hash.
  std::size_t form_id(const Operation& op) {
    // The common form, a split along x, y or z whose sizes are all literal
    // or literal ranges, is named by its axis and relative flags alone,
    // without copying the split. (Its blank form cannot equal any other
    // node's: another has a non-literal axis or size, which stays.)
    if (const auto* s = std::get_if<Split>(&op)) {
      const ExprNode& axis = s->axis.node(s->axis.root());
      if (s->axis.nodes().size() == 1 && axis == ExprNode{.kind = ExprKind::Axis, .op = axis.op} &&
          std::all_of(s->parts.begin(), s->parts.end(), [](const SplitPart& p) { return literal_range(p.size.value); })) {
        std::vector<std::uint8_t>& key = split_key_;  // reused: most nodes' form is known
        key.assign(1, axis.op);
        for (const auto& p : s->parts) key.push_back(p.size.relative ? 1 : 0);
        if (const auto it = split_forms_.find(key); it != split_forms_.end()) return it->second;
        split_forms_.emplace(key, forms_);
        return forms_++;
      }
    }
    Operation blank = op;
    if (auto* s = std::get_if<Split>(&blank)) {
      for (auto& p : s->parts) {
        if (literal_range(p.size.value)) p.size.value = Expr::number(0);
        p.child = 0;
      }
    } else {
      // A repeat's literal tile size ranges like a split's sizes.
      if (auto* r = std::get_if<Repeat>(&blank); r && literal_range(r->size)) r->size = Expr::number(0);
      for (auto* child : child_slots(blank)) *child = 0;
    }
    auto& seen = forms_by_hash_[shallow_hash(blank)];
    for (const auto& [form, id] : seen)
      if (form == blank) return id;
    seen.emplace_back(std::move(blank), forms_++);
    return forms_ - 1;
  }


  // Builds the group's node; its rows move into the row book (the group
  // is done with once built).
  NodeId build(Group& group, const std::vector<NodeId>& built) {
    if (!group.weights.empty()) {
      Choose choose;
      for (std::size_t k = 0; k < group.children.size(); ++k)
        choose.options.push_back({Expr{}, Expr::number(group.weights[k]), built[group.children[k]]});
      if (choose.options.size() == 1) return choose.options[0].child;
      return g_.intern({std::move(choose), {}});
    }
    Operation op = g_.op(group.first);
    auto slots = child_slots(op);
    for (std::size_t i = 0; i < slots.size(); ++i) *slots[i] = built[group.children[i]];
    std::vector<std::vector<Observation>> kept(group.ranges.size());  // the values behind ranges built
    auto ranged = [&](std::size_t i) {
      if (group.sampled[i]) kept[i] = group.samples[i];
      return range_expr(group.ranges[i], opt_.tolerance);
    };
    bool planned = false;
    if (auto* s = std::get_if<Split>(&op)) {
      // Splits of different lengths: parts of one length are absolute.
      std::optional<std::vector<PartPlan>> plan;
      planned = group.rows_complete && group.lengths.size() >= 2;
      if (planned) plan = plan_sizes(group.lengths, opt_.tolerance);
      for (std::size_t i = 0; i < s->parts.size() && i < group.ranges.size(); ++i) {
        if (!literal_range(s->parts[i].size.value)) continue;
        if (plan && (*plan)[i].fixed) {
          s->parts[i].size = {Expr::number((*plan)[i].value), !(*plan)[i].absolute};
        } else {
          s->parts[i].size.value = ranged(i);
        }
      }
    } else if (auto* r = std::get_if<Repeat>(&op); r && !group.ranges.empty() && literal_range(r->size)) {
      r->size = ranged(0);
    }
    const NodeId out = g_.intern({std::move(op), {}});
    if (planned) {
      std::vector<LengthRow>& rows = rows_[out];
      rows.clear();
      rows.reserve(group.lengths.size());
      for (std::size_t m = 0; m < group.lengths.size(); ++m)
        rows.push_back({std::move(group.lengths[m]), group.row_weights[m], group.row_examples[m]});
    }
    if (std::holds_alternative<Repeat>(g_.op(out)) && group.counted && !group.tile_counts.empty())
      tile_counts_[out] = group.tile_counts;
    // The group's samples already hold its members' (a member built in an
    // earlier round brings its book entry): replace, never add, or a node
    // that unifies with itself round after round would count its values
    // again each time.
    if (!kept.empty()) book_[out] = std::move(kept);
    return out;
  }

  Grammar& g_;
  const MergeOptions& opt_;
  TileLengths tile_lengths_;
  SampleBook& book_;
  RowBook& rows_;
  TileCounts& tile_counts_;            // by repeat node: the tile counts it made where folded
  const ExampleCounts& counts_;  // by node id: examples it occurs in
  const std::vector<bool>& copied_;  // by node id: in a placed group
  std::vector<Group> groups_;
  std::unordered_map<Key, std::size_t, KeyHash> group_by_key_;
  std::vector<std::size_t> group_of_;  // by node id; kNoGroup until visited
  std::unordered_map<std::size_t, std::vector<std::pair<Operation, std::size_t>>> forms_by_hash_;
  struct BytesHash {
    std::size_t operator()(const std::vector<std::uint8_t>& v) const {
      return std::hash<std::string_view>{}(std::string_view(reinterpret_cast<const char*>(v.data()), v.size()));
    }
  };
  std::unordered_map<std::vector<std::uint8_t>, std::size_t, BytesHash> split_forms_;  // axis, relative flags
  std::size_t forms_ = 0;
  // Buffers reused across levels and nodes (settle, form_id, add_member).
  Key probe_;                                        // the key of the node being settled
  std::unordered_map<Key, std::size_t, KeyHash> bucket_of_;  // this level's keys -> bucket
  std::vector<Key> bucket_keys_;                     // in order of first member
  std::vector<std::size_t> bucket_at_;               // per node of the level: its bucket, or kNoGroup
  std::vector<std::size_t> bucket_starts_, fill_at_;
  std::vector<NodeId> members_;                      // the level's nodes, bucket by bucket
  std::vector<std::size_t> kinds_;
  std::vector<SizedMember> sized_;
  std::vector<std::uint8_t> split_key_;
  std::vector<double> row_;
  Key choose_key_;
  std::vector<std::pair<std::size_t, double>> choose_weights_;
};

// ---- simplification ----

// Simplifies the graph below a node. A node that simplifies to itself (the
// common case: most of a building has nothing to flatten or repeat) is
// recognised without copying it, so the graph is not rebuilt: that needs
// the graph interned (as inference builds it), since intern would return
// the node itself.
class Simplifier {
 public:
  Simplifier(Grammar& g, const MergeOptions& o)
      : g_(g), opt_(o), memo_(g.node_count(), kNotYet), placed_(o.placed.begin(), o.placed.end()) {}

  NodeId run(NodeId id) {
    if (id >= memo_.size()) memo_.resize(g_.node_count(), kNotYet);
    if (memo_[id] != kNotYet) return memo_[id];
    const NodeId out = simplify(id);
    memo_[id] = out;
    if (placed_.count(id) > 0) placed_.insert(out);  // simplified, still the group
    return out;
  }

 private:
  static constexpr NodeId kNotYet = static_cast<NodeId>(-1);

  NodeId simplify(NodeId id) {
    if (std::holds_alternative<Split>(g_.op(id))) return simplify_split(id);
    if (std::holds_alternative<Choose>(g_.op(id))) return simplify_choose(Choose(std::get<Choose>(g_.op(id))));
    if (auto out = one_child<RepeatN>(id)) return *out;
    if (auto out = one_child<Repeat>(id)) return *out;
    if (auto out = one_child<Rotate>(id)) return *out;
    return id;
  }

  // An operation of type Op with one child: a new node only if the child
  // changed.
  template <class Op>
  std::optional<NodeId> one_child(NodeId id) {
    if (!std::holds_alternative<Op>(g_.op(id))) return std::nullopt;
    const NodeId child = run(std::get<Op>(g_.op(id)).child);
    if (child == std::get<Op>(g_.op(id)).child) return id;
    Op m = std::get<Op>(g_.op(id));  // after run: it may have moved the arena
    m.child = child;
    return g_.intern({std::move(m), {}});
  }

  bool same_size(const Size& a, const Size& b) const {
    if (a.relative != b.relative) return false;
    auto ra = literal_range(a.value);
    auto rb = literal_range(b.value);
    if (!ra || !rb) return a.value == b.value;
    return std::abs(ra->lo - rb->lo) <= opt_.tolerance && std::abs(ra->hi - rb->hi) <= opt_.tolerance;
  }

  // A run of two or more equal parts (same child, same size) is one part
  // holding repeatN: on its own scope the tiles come out the same, since
  // repeatN cuts equal tiles. Only literal sizes qualify: tiles of a range
  // are equal to each other, but the parts of a split draw independently.
  // A part holding a split along the same axis whose sizes are all
  // relative literals is that split's parts, in place: part size s and
  // inner sizes c_j give parts s * c_j / sum(c), relative or absolute as
  // the outer part was, which derive the same lengths. Inner absolute
  // sizes or ranges would not (they share space differently), so those stay.
  //
  // A placed group keeps its own split (MergeOptions::placed): check
  // derives it as one, which its parts spread into the parent could not be.
  void flatten_into(std::vector<SplitPart>& out, const SplitPart& part, const Expr& axis) {
    const auto outer = part.size.value.literal();
    const auto* inner = std::get_if<Split>(&g_.op(part.child));
    if (outer && inner && inner->axis == axis && placed_.count(part.child) == 0) {
      double total = 0;
      bool literal_relative = true;
      for (const auto& q : inner->parts) {
        const auto v = q.size.value.literal();
        literal_relative = literal_relative && q.size.relative && v;
        if (v) total += *v;
      }
      if (literal_relative && total > 0) {
        for (const auto& q : inner->parts)
          flatten_into(out, {{Expr::number(*outer * *q.size.value.literal() / total), part.size.relative}, q.child}, axis);
        return;
      }
    }
    out.push_back(part);
  }

  // The literal axis of a split, if it has one.
  static std::optional<Axis> literal_axis(const Split& s) {
    if (s.axis.node(s.axis.root()).kind != ExprKind::Axis) return std::nullopt;
    return static_cast<Axis>(s.axis.node(s.axis.root()).op);
  }

  // Would flatten_into take the inner split's parts in place of this part?
  bool flattens(const SplitPart& part, const Expr& axis) const {
    const auto* inner = std::get_if<Split>(&g_.op(part.child));
    if (!part.size.value.literal() || !inner || inner->axis != axis || placed_.count(part.child) > 0) return false;
    double total = 0;
    for (const auto& q : inner->parts) {
      const auto v = q.size.value.literal();
      if (!q.size.relative || !v) return false;
      total += *v;
    }
    return total > 0;
  }

  NodeId simplify_split(NodeId id) {
    // Children first: simplifying them may add nodes, which moves the arena.
    const auto [children, changed] = map_children(g_.op(id), [&](NodeId c) { return run(c); });
    if (!changed) {
      // Unchanged unless a part flattens, parts repeat, or one part is all.
      const Split& s = std::get<Split>(g_.op(id));
      const bool has_axis = literal_axis(s).has_value();
      bool changes = s.parts.size() == 1 && s.parts[0].size.relative;
      for (std::size_t i = 0; i < s.parts.size() && !changes; ++i) {
        changes = flattens(s.parts[i], s.axis) ||
                  (has_axis && i + 1 < s.parts.size() && s.parts[i].size.value.literal() &&
                   s.parts[i + 1].child == s.parts[i].child && same_size(s.parts[i + 1].size, s.parts[i].size));
      }
      if (!changes) return id;
    }
    const Split s = std::get<Split>(g_.op(id));  // a copy: interning below may grow the arena
    std::vector<SplitPart> parts;
    for (std::size_t i = 0; i < s.parts.size(); ++i) flatten_into(parts, {s.parts[i].size, children[i]}, s.axis);
    const Axis* axis = nullptr;
    Axis literal{};
    if (const auto a = literal_axis(s)) {
      literal = *a;
      axis = &literal;
    }
    std::vector<SplitPart> out;
    for (std::size_t i = 0; i < parts.size();) {
      std::size_t j = i + 1;
      const auto lit = parts[i].size.value.literal();
      while (axis && lit && j < parts.size() && parts[j].child == parts[i].child && same_size(parts[j].size, parts[i].size))
        ++j;
      const std::size_t run_length = j - i;
      // The run's own length, not the first part's times the count: parts
      // equal within the tolerance would otherwise shift every part after
      // the run by up to count times the tolerance (found by fuzzing).
      double run_total = 0;
      for (std::size_t k = i; run_length >= 2 && k < j; ++k) run_total += parts[k].size.value.literal().value_or(*lit);
      if (run_length >= 2 && !std::holds_alternative<Nil>(g_.op(parts[i].child))) {
        RepeatN rep{Expr::axis(*axis), Expr::number(static_cast<double>(run_length)), parts[i].child};
        const NodeId tiles = g_.intern({std::move(rep), {}});
        out.push_back({{Expr::number(run_total), parts[i].size.relative}, tiles});
      } else if (run_length >= 2) {
        // Adjacent empty parts are one empty part.
        out.push_back({{Expr::number(run_total), parts[i].size.relative}, parts[i].child});
      } else {
        out.push_back(parts[i]);
      }
      i = j;
    }
    // A split that is one relative part is that part's operation.
    if (out.size() == 1 && out[0].size.relative) return out[0].child;
    Split m{s.axis, std::move(out)};
    return g_.intern({std::move(m), {}});
  }

  // Identical alternatives are one, with their priorities added; nested
  // unconditional chooses are flattened (an option's share of the inner
  // choose times its own priority); a choose of one option is its child.
  NodeId simplify_choose(const Choose& c) {
    bool plain = true;                               // literal priorities, no conditions
    for (const auto& o : c.options) plain = plain && o.condition.empty() && o.priority.literal();
    if (!plain) {
      Choose m = c;
      for (auto& o : m.options) o.child = run(o.child);
      return g_.intern({std::move(m), {}});
    }
    Choose m;
    for (const auto& o : c.options) {
      const NodeId child = run(o.child);
      const double priority = *o.priority.literal();
      const auto* inner = std::get_if<Choose>(&g_.op(child));
      bool inner_plain = inner != nullptr;
      double total = 0;
      if (inner)
        for (const auto& io : inner->options) {
          inner_plain = inner_plain && io.condition.empty() && io.priority.literal();
          if (inner_plain) total += *io.priority.literal();
        }
      if (inner_plain && total > 0) {
        for (const auto& io : inner->options)
          m.options.push_back({Expr{}, Expr::number(priority * *io.priority.literal() / total), io.child});
      } else {
        m.options.push_back({Expr{}, Expr::number(priority), child});
      }
    }
    join_equal_options(m);
    if (m.options.size() == 1) return m.options[0].child;
    return g_.intern({std::move(m), {}});
  }

  Grammar& g_;
  const MergeOptions& opt_;
  std::vector<NodeId> memo_;  // by node id: what it simplified to, or kNotYet
  std::unordered_set<NodeId> placed_;  // placed groups, as given and as simplified
};

}  // namespace

namespace {

// Step 4: each range whose values were kept becomes the distribution they
// fit best. Rebuilds the graph below root (memoised: a DAG).
class Fitter {
 public:
  Fitter(Grammar& g, const MergeOptions& o, const SampleBook& book) : g_(g), opt_(o), book_(book) {}

  NodeId run(NodeId id) {
    if (auto it = memo_.find(id); it != memo_.end()) return it->second;
    Operation op = g_.op(id);  // a copy: interning below may grow the arena
    bool changed = false;
    for (NodeId* child : child_slots(op)) {
      const NodeId c = run(*child);
      changed = changed || c != *child;
      *child = c;
    }
    if (const auto booked = book_.find(id); booked != book_.end()) {
      const auto& samples = booked->second;
      auto fitted = [&](Expr& e, std::size_t i) {
        if (i >= samples.size() || samples[i].empty()) return;
        const auto r = literal_range(e);
        if (!r || r->lo == r->hi) return;
        // The values kept must be the range's own: its ends among them.
        double lo = samples[i][0].value, hi = lo;
        for (const Observation& o : samples[i]) {
          lo = std::min(lo, o.value);
          hi = std::max(hi, o.value);
        }
        if (std::abs(lo - r->lo) > opt_.tolerance || std::abs(hi - r->hi) > opt_.tolerance) return;
        e = distribution_expr(fit_size(samples[i], opt_.tolerance, opt_.uniform_distributions));
        changed = true;
      };
      if (auto* s = std::get_if<Split>(&op)) {
        for (std::size_t i = 0; i < s->parts.size(); ++i) fitted(s->parts[i].size.value, i);
      } else if (auto* r = std::get_if<Repeat>(&op)) {
        fitted(r->size, 0);
      }
    }
    const NodeId out = changed ? g_.intern({std::move(op), g_.node(id).loc}) : id;
    memo_.emplace(id, out);
    return out;
  }

 private:
  Grammar& g_;
  const MergeOptions& opt_;
  const SampleBook& book_;
  std::unordered_map<NodeId, NodeId> memo_;
};

}  // namespace

// A rebuilt repeat keeps the tile counts of the node it replaces.
void carry_tile_counts(const std::vector<std::pair<NodeId, NodeId>>& rebuilt, TileCounts& tile_counts) {
  // Several nodes rebuilt into one (two rows whose tiles now share one
  // choice) made all their tiles; a node noted before keeps its notes.
  std::unordered_map<NodeId, std::vector<NodeId>> carried;  // new node -> the old ones carried into it
  for (const auto& [old, now] : rebuilt) {
    const auto it = tile_counts.find(old);
    if (it == tile_counts.end() || old == now) continue;
    auto& from = carried[now];
    if (from.empty() && tile_counts.count(now)) continue;
    if (std::find(from.begin(), from.end(), old) != from.end()) continue;
    from.push_back(old);
    std::vector<TileSeen> counts = it->second;  // a copy: inserting below may move it
    auto& into = tile_counts[now];
    into.insert(into.end(), counts.begin(), counts.end());
  }
}

// Nodes rebuilt with new children keep their sizes: the values behind
// their ranges and their tile counts carry over to the new node.
void carry_notes(const std::vector<std::pair<NodeId, NodeId>>& rebuilt, SampleBook& book, TileCounts& tile_counts) {
  carry_samples(rebuilt, book);
  carry_tile_counts(rebuilt, tile_counts);
}

namespace {

// A member's rows: those booked for it, or, for a split whose sizes are
// all single values (one kind of split, never unified with another), that
// one row itself.
std::optional<std::vector<LengthRow>> rows_of(const Grammar& g, NodeId member, const RowBook& rows,
                                              const ExampleCounts& counts) {
  if (const auto known = rows.find(member); known != rows.end()) return known->second;
  const auto* s = std::get_if<Split>(&g.op(member));
  if (!s) return std::nullopt;
  LengthRow row{{}, counts.of(member), counts.example_of(member)};
  for (const auto& p : s->parts) {
    const auto r = literal_range(p.size.value);
    if (!r || r->lo != r->hi) return std::nullopt;
    row.lengths.push_back(r->lo);
  }
  return std::vector<LengthRow>{std::move(row)};
}

// A frame's members joined into one split: its rows are all of theirs, if
// every member's are known.
void join_rows(const Grammar& g, const std::vector<std::pair<NodeId, NodeId>>& joined, RowBook& rows,
               const ExampleCounts& counts) {
  std::unordered_map<NodeId, bool> complete;
  for (const auto& [member, split] : joined) {
    auto [it, fresh] = complete.try_emplace(split, true);
    if (fresh) rows.erase(split);
    if (!it->second) continue;
    auto known = rows_of(g, member, rows, counts);
    if (!known) {
      it->second = false;
      continue;
    }
    std::vector<LengthRow>& into = rows[split];
    into.insert(into.end(), known->begin(), known->end());
  }
  for (const auto& [split, whole] : complete)
    if (!whole) rows.erase(split);
}

void carry_rows(const std::vector<std::pair<NodeId, NodeId>>& rebuilt, RowBook& rows) {
  for (const auto& [old, now] : rebuilt) {
    if (const auto it = rows.find(old); it != rows.end() && !rows.count(now)) {
      std::vector<LengthRow> copy = it->second;  // a copy: inserting below may move it
      rows.emplace(now, std::move(copy));
    }
  }
}

}  // namespace

NodeId merge_examples(Grammar& g, const std::vector<NodeId>& roots, const MergeOptions& options) {
  std::vector<NodeId> folded;
  const UnlikeTiles unlike = roots.size() > 1 && options.fold_unlike ? UnlikeTiles::Fold : UnlikeTiles::Keep;
  TileCounts tile_counts;
  // Tiers set in step by step are nested first (inset_runs.hpp), so that
  // recursion is found below and no run of them is read as tiles.
  // Placed groups and all below them, copied as they are: nothing folds,
  // nests, unifies or joins them (MergeOptions::placed).
  std::vector<bool> copied(g.node_count(), false);
  for (const NodeId p : options.placed)
    for (const NodeId n : nodes_below(g, p)) copied[n] = true;
  // Folded twice where a row kept a tile from folding for a label that
  // other rows show trading places, or left a built part alone that other
  // rows fold as tiles (RowsSeen): the first pass reads what the rows
  // show, the second folds with what every row showed.
  RowsSeen rows_seen;
  std::vector<NodeId> nested;
  for (NodeId r : roots) nested.push_back(nest_inset_runs(g, r, options.tolerance, &copied));
  auto fold_all = [&] {
    folded.clear();
    tile_counts.clear();
    for (NodeId r : nested)
      folded.push_back(fold_repeats(g, r, options.tolerance, unlike, &tile_counts, &copied, &rows_seen));
  };
  fold_all();
  auto any_seen = [](const auto& lone, const auto& seen) {
    return std::any_of(lone.begin(), lone.end(), [&](const auto& key) { return seen.count(key) > 0; });
  };
  if (any_seen(rows_seen.lone, rows_seen.seen) || any_seen(rows_seen.shapes_lone, rows_seen.shapes_seen) ||
      any_seen(rows_seen.lone_tiles, rows_seen.tiles))
    fold_all();
  Choose all;
  for (NodeId r : folded) all.options.push_back({Expr{}, Expr::number(1.0), r});
  const NodeId examples = g.intern({std::move(all), {}});
  // One example is reproduced as it is: ranges come only from variation
  // across examples, never from one building's own parts.
  if (roots.size() == 1) return Simplifier(g, options).run(examples);
  // Runs inside mixed rows are found at the end, once alike parts line up:
  // finding them in each example first would give rows of different
  // fillings different shapes (a | a | b is a repeat and a part, a | b | a
  // is three parts). Only runs that fill a whole split are folded first.
  SampleBook book;
  RowBook rows;
  const ExampleCounts counts = example_counts(g, folded);
  NodeId merged = Unifier(g, options, book, rows, tile_counts, counts, copied).run(examples);
  // Free combinations make parents alike, which unify, which may show more
  // free combinations above: repeat until nothing changes (a few rounds:
  // each round generalises at least one frame, and frames only merge).
  // Rows of one kind sharing their tiles' choices works the same way.
  auto generalise = [&](FrameKinds kinds) {
    for (int round = 0; round < 16; ++round) {
      bool changed = false;
      std::vector<std::pair<NodeId, NodeId>> rebuilt, joined;
      merged = generalise_free_parts(g, merged, options, kinds, rows, changed, &rebuilt, &joined);
      join_rows(g, joined, rows, counts);
      carry_notes(rebuilt, book, tile_counts);
      const TileChoiceUnion united = unite_tile_choices(g, merged, &tile_counts);
      carry_notes(united.replaced, book, tile_counts);
      merged = united.root;
      // A door bay at the start beside one after some bays: one split.
      const EmptyRuns runs = pad_empty_runs(g, merged, book, rows);
      carry_notes(runs.replaced, book, tile_counts);
      merged = runs.root;
      if (!changed && united.replaced.empty() && runs.padded == 0) break;
      carry_rows(rebuilt, rows);
      carry_rows(united.replaced, rows);
      carry_rows(runs.replaced, rows);
      merged = Unifier(g, options, book, rows, tile_counts, counts, copied).run(merged);
    }
  };
  generalise(FrameKinds::Alike);
  // Towers of every tier count become one recursive rule, so their
  // frames unify again.
  const SelfNesting nesting = fold_self_nesting(g, merged, book, options.tolerance, rows);
  if (nesting.rules > 0) {
    // The splits rebuilt above a recursion keep their examples' lengths:
    // without them sizing reads a front beside a wing as sizes drawn
    // anew (drawn_sizes.hpp, nested_split.hpp).
    carry_notes(nesting.rebuilt, book, tile_counts);
    carry_rows(nesting.rebuilt, rows);
    merged = Unifier(g, options, book, rows, tile_counts, counts, copied).run(nesting.root);
  }
  // Alternatives that differ only below some of their parts become one
  // split with choices at those parts; last, so that nested tiers are
  // folded as recursion before their levels are joined.
  generalise(FrameKinds::AlikeAndAlternatives);
  // The recursive rules' bodies are reached through calls, not children:
  // each step below runs on them as on the root.
  auto everywhere = [&](auto&& step) {
    merged = step(merged);
    for (Rule& rule : g.rules) rule.body = step(rule.body);
  };
  // Sizes that vary, in metres where they keep their length better than
  // their share, and relative parts in fixed ratios where they keep them:
  // decided once the structure is settled, so that no unification above
  // is kept apart by it.
  if (options.draw_sizes) everywhere([&](NodeId n) {
    std::vector<std::pair<NodeId, NodeId>> rebuilt;
    const NodeId drawn = draw_sizes(g, n, rows, book, options.tolerance, &rebuilt);
    carry_tile_counts(rebuilt, tile_counts);  // a repeat above a drawn split keeps its counts
    return drawn;
  });
  everywhere([&](NodeId n) { return settle_repeats(g, n, tile_counts, book, options.tolerance); });
  Fitter fitter(g, options, book);
  everywhere([&](NodeId n) { return fitter.run(n); });
  Simplifier simplifier(g, options);
  everywhere([&](NodeId n) { return simplifier.run(n); });
  // Last, on the splits as they are written (flattened): alternatives
  // seen at different lengths keep the lengths they all share (sizes in
  // metres, so only where those are asked for: MergeOptions::draw_sizes).
  if (options.draw_sizes)
    everywhere([&](NodeId n) { return absolute_across_alternatives(g, n, options.tolerance); });
  return merged;
}

}  // namespace vern
