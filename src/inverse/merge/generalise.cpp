#include "inverse/merge/generalise.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include "graph/nodes_below.hpp"
#include "inverse/merge/choice_costs.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/merge/weighted_choice.hpp"

namespace vern {

namespace {

// The middle of a size's range (a literal is its own middle).
std::optional<double> middle(const Expr& e) {
  if (auto r = literal_range(e)) return (r->lo + r->hi) / 2;
  return std::nullopt;
}

struct Frame {
  std::vector<NodeId> members;  // distinct split nodes, in discovery order
  bool alternatives = false;    // the members are alternatives of one choice
  std::vector<bool> relative;   // each part's flag in the joined split
  std::map<NodeId, double> weights;  // alternatives: each member's weight in its choice
};

class Generaliser {
 public:
  Generaliser(Grammar& g, const MergeOptions& o, FrameKinds kinds, const RowBook& rows)
      : g_(g), opt_(o), kinds_(kinds), rows_(rows), references_(g.node_count(), 0), copied_(g.node_count(), false) {
    // Placed groups are copied as they are (MergeOptions::placed): no
    // split of theirs joins a frame.
    for (const NodeId p : o.placed)
      for (const NodeId n : nodes_below(g, p)) copied_[n] = true;
  }

  NodeId run(NodeId root, bool& changed, std::vector<std::pair<NodeId, NodeId>>* rebuilt,
             std::vector<std::pair<NodeId, NodeId>>* joined) {
    changed = false;
    collect(root);
    std::vector<NodeId> replace(g_.node_count(), kNoReplacement);  // by node id
    auto join = [&](Frame& frame) {
      // A member a frame before already replaced stays where it went.
      std::erase_if(frame.members, [&](NodeId m) { return replace[m] != kNoReplacement; });
      settle_flags(frame);
      if (frame.members.size() < 2) return;
      if (auto merged = generalise(frame)) {
        changed = true;
        for (const auto& [m, split] : *merged) {
          replace[m] = split;
          if (joined) joined->emplace_back(m, split);
        }
      }
    };
    for (auto& [key, frame] : frames_) join(frame);
    if (kinds_ == FrameKinds::AlikeAndAlternatives)
      for (auto& [key, frame] : choice_frames_) join(frame);
    return changed ? substitute(g_, root, replace, rebuilt) : root;
  }

 private:
  // Every split below root, grouped by frame; references counted, since a
  // part used in two places was seen twice.
  void collect(NodeId id) {
    if (references_[id]++ > 0) return;
    const Operation& op = g_.op(id);
    for (NodeId c : node_children(op)) collect(c);
    if (const auto* c = std::get_if<Choose>(&op)) {
      // Alternatives of one choice that are splits of one shape are one
      // frame whatever their proportions: they stand for the same place.
      for (const auto& o : c->options) {
        const auto* s = std::get_if<Split>(&g_.op(o.child));
        if (!s || copied_[o.child]) continue;
        if (auto shape = split_shape(*s, false)) {
          Frame& frame = choice_frames_["c" + std::to_string(id) + "/" + *shape];
          frame.alternatives = true;
          auto& members = frame.members;
          if (std::find(members.begin(), members.end(), o.child) == members.end()) members.push_back(o.child);
          frame.weights[o.child] += middle(o.priority).value_or(1.0);
        }
      }
      return;
    }
    const auto* s = std::get_if<Split>(&op);
    if (!s || copied_[id]) return;
    if (auto shape = split_shape(*s, true)) frames_[*shape].members.push_back(id);
  }

  // Does a place whose child varies also vary in metres? A 1.2 m door or
  // a 3 m shop window: joined, the length would be drawn apart from what
  // fills it (a 3 m door). Relative parts vary with their scope anyway.
  bool lengths_follow_children(const Frame& frame,
                               const std::vector<std::vector<std::pair<NodeId, double>>>& seen) const {
    for (std::size_t i = 0; i < seen.size(); ++i) {
      if (seen[i].size() < 2 || frame.relative[i]) continue;
      double highest_lo = -std::numeric_limits<double>::infinity();
      double lowest_hi = std::numeric_limits<double>::infinity();
      for (NodeId m : frame.members) {
        const auto r = literal_range(std::get<Split>(g_.op(m)).parts[i].size.value);
        if (!r) return true;
        highest_lo = std::max(highest_lo, r->lo);
        lowest_hi = std::min(lowest_hi, r->hi);
      }
      if (highest_lo - lowest_hi > opt_.tolerance) return true;
    }
    return false;
  }

  // Does a place hold a repeat along the split's axis in one alternative
  // and tiles it makes in another (one storey, or repeatN of them)? Then
  // the alternatives differ in a count, not a choice: a house seen with
  // one storey stacks as many as its height holds, as one seen with five
  // (absolute_across_alternatives.hpp makes the run that repeat, which a
  // choice of the two at that place would hide).
  bool runs_of_tiles(const Split& first, const std::vector<std::vector<std::pair<NodeId, double>>>& seen) const {
    const auto axis = first.axis.literal_axis();
    if (!axis) return false;
    for (const auto& at : seen) {
      for (const auto& [child, w] : at) {
        const auto* r = std::get_if<Repeat>(&g_.op(child));
        if (!r || r->axis.literal_axis() != axis) continue;
        std::vector<NodeId> holds{r->child};
        if (const auto* c = std::get_if<Choose>(&g_.op(r->child)))
          for (const auto& o : c->options) holds.push_back(o.child);
        auto tile = [&](NodeId n) { return std::find(holds.begin(), holds.end(), n) != holds.end(); };
        for (const auto& [other, v] : at) {
          if (other == child) continue;
          const auto* run = std::get_if<RepeatN>(&g_.op(other));
          if (tile(other) || (run && run->axis.literal_axis() == axis && tile(run->child))) return true;
        }
      }
    }
    return false;
  }

  // How often a member was seen: its weight in the choice, for
  // alternatives; else how many places use it.
  double weight_of(const Frame& frame, NodeId m) const {
    const auto it = frame.weights.find(m);
    return it != frame.weights.end() ? it->second : references_[m];
  }

  bool lone(NodeId id) const { return lone_split(g_, id, rows_); }

  static std::vector<bool> flags_of(const Split& s) {
    std::vector<bool> relative;
    for (const auto& p : s.parts) relative.push_back(p.size.relative);
    return relative;
  }

  // The joined split's relative flags: those of the first member whose
  // flags were settled by unifying examples (else the first member's);
  // members settled otherwise stay out of the frame, and lone ones take
  // these flags.
  void settle_flags(Frame& frame) const {
    if (frame.members.empty()) return;
    const auto settled = std::find_if(frame.members.begin(), frame.members.end(), [&](NodeId m) { return !lone(m); });
    frame.relative = flags_of(std::get<Split>(g_.op(settled != frame.members.end() ? *settled : frame.members[0])));
    std::erase_if(frame.members, [&](NodeId m) {
      return !lone(m) && flags_of(std::get<Split>(g_.op(m))) != frame.relative;
    });
  }

  // A split's axis and part count, with its relative flags and
  // proportions when asked; none if it cannot be a frame member.
  std::optional<std::string> split_shape(const Split& s, bool with_proportions) const {
    if (s.parts.size() < 2) return std::nullopt;
    if (s.axis.node(s.axis.root()).kind != ExprKind::Axis) return std::nullopt;
    double total = 0;
    std::vector<double> mids;
    for (const auto& p : s.parts) {
      const auto m = middle(p.size.value);
      if (!m) return std::nullopt;
      mids.push_back(*m);
      total += *m;
    }
    if (!(total > 0)) return std::nullopt;
    std::string key = std::to_string(s.axis.node(s.axis.root()).op) + "/" + std::to_string(s.parts.size());
    // Alternatives are keyed without their flags: settle_flags sorts them.
    if (with_proportions)
      for (std::size_t i = 0; i < s.parts.size(); ++i)
        key += (s.parts[i].size.relative ? "~" : "=") + std::to_string(std::lround(1000 * mids[i] / total));
    return key;
  }

  // Alternatives of one choice: which of their places vary independently,
  // counting only the places that vary. All of them when that costs no
  // more bits than the combinations seen (alternatives that differ at one
  // place only cost the same either way, and become that place's choice:
  // the same buildings, one choice lower). Else, place by place, those
  // whose options said on their own, beside the combinations of the
  // others, cost no more (a roof of any kind on houses whose ground floor
  // and storeys keep one door bay's place together); none when none.
  std::optional<std::vector<bool>> free_places(const Frame& frame,
                                               const std::vector<std::vector<std::pair<NodeId, double>>>& seen) const {
    std::vector<std::size_t> varying;
    std::size_t entries = 0;
    for (std::size_t i = 0; i < seen.size(); ++i)
      if (seen[i].size() > 1) {
        varying.push_back(i);
        entries += seen[i].size();
      }
    std::vector<bool> free(seen.size(), false);
    auto options = [&](std::size_t i) {
      std::vector<double> w;
      for (const auto& [child, weight] : seen[i]) w.push_back(weight);
      return w;
    };
    // The bits to say the places with `free` marking those said alone.
    auto cost = [&](const std::vector<bool>& alone) {
      std::map<std::vector<NodeId>, double> fillings;
      std::size_t coupled = 0;
      std::vector<std::vector<double>> own;
      for (std::size_t i : varying) {
        if (alone[i]) own.push_back(options(i));
        else ++coupled;
      }
      for (NodeId m : frame.members) {
        const auto& s = std::get<Split>(g_.op(m));
        std::vector<NodeId> filling;
        for (std::size_t i : varying)
          if (!alone[i]) filling.push_back(s.parts[i].child);
        fillings[filling] += weight_of(frame, m);
      }
      std::vector<double> joint;
      for (const auto& [filling, w] : fillings) joint.push_back(w);
      return mixed_cost(joint, coupled, own, entries);
    };
    std::vector<bool> all = free;
    for (std::size_t i : varying) all[i] = true;
    const double coupled = cost(free), independent = cost(all);
    // Freed one at a time, the place that saves most first, while one
    // saves anything; kept only where that beats both ends.
    double best = coupled;
    for (bool saved = true; saved;) {
      saved = false;
      std::optional<std::size_t> pick;
      for (std::size_t i : varying) {
        if (free[i]) continue;
        std::vector<bool> tried = free;
        tried[i] = true;
        if (const double c = cost(tried); c < best - 1e-9) {
          best = c;
          pick = i;
        }
      }
      if (pick) {
        free[*pick] = true;
        saved = true;
      }
    }
    if (free != all && best < std::min(coupled, independent) - 1e-9) return free;
    if (independent <= coupled + 1e-9) return all;
    return std::nullopt;
  }

  // The members as splits joined where `free` says: members that hold the
  // same children at every other place become one split, whose free places
  // are a choice of what every member held there. Each member's new node.
  std::optional<std::vector<std::pair<NodeId, NodeId>>> generalise(const Frame& frame) {
    // A copy: interning below may grow the arena and move its nodes.
    const Split first = std::get<Split>(g_.op(frame.members.front()));
    const std::size_t n = first.parts.size();
    // What each position held, with how often.
    // (Each position's children in order of first appearance, found by a
    // hash index: a frame of many members must not search them linearly.)
    std::vector<std::vector<std::pair<NodeId, double>>> seen(n);
    std::vector<std::unordered_map<NodeId, std::size_t>> where(n);
    std::size_t busiest = 0;
    for (NodeId m : frame.members) {
      const auto& s = std::get<Split>(g_.op(m));
      const double weight = weight_of(frame, m);
      for (std::size_t i = 0; i < n; ++i) {
        auto [it, fresh] = where[i].try_emplace(s.parts[i].child, seen[i].size());
        if (fresh) seen[i].emplace_back(s.parts[i].child, weight);
        else seen[i][it->second].second += weight;
      }
    }
    for (const auto& at : seen) busiest = std::max(busiest, at.size());
    if (busiest < 2) return std::nullopt;
    std::vector<bool> free(n, true);
    if (frame.alternatives) {
      if (runs_of_tiles(first, seen) || lengths_follow_children(frame, seen)) return std::nullopt;
      const auto places = free_places(frame, seen);
      if (!places) return std::nullopt;
      free = *places;
    } else if (frame.members.size() < 2 * busiest) {
      return std::nullopt;
    }
    // Members by what they hold at the places that stay coupled.
    std::map<std::vector<NodeId>, std::vector<NodeId>> groups;
    std::vector<std::vector<NodeId>> order;
    for (NodeId m : frame.members) {
      std::vector<NodeId> key;
      const auto& s = std::get<Split>(g_.op(m));
      for (std::size_t i = 0; i < n; ++i)
        if (!free[i]) key.push_back(s.parts[i].child);
      auto [it, fresh] = groups.try_emplace(key);
      if (fresh) order.push_back(key);
      it->second.push_back(m);
    }
    std::vector<std::pair<NodeId, NodeId>> out;
    for (const auto& key : order) {
      const std::vector<NodeId>& members = groups.at(key);
      const NodeId joined = joined_split(frame, members, seen, free);
      for (NodeId m : members) out.emplace_back(m, joined);
    }
    return out;
  }

  // One split for `members`: at a free place a choice of what every member
  // of the frame held there (seen), elsewhere the members' own child.
  NodeId joined_split(const Frame& frame, const std::vector<NodeId>& members,
                      const std::vector<std::vector<std::pair<NodeId, double>>>& seen, const std::vector<bool>& free) {
    const Split first = std::get<Split>(g_.op(members.front()));
    const std::size_t n = first.parts.size();
    // The members share their proportions (the frame's key), not their
    // lengths: relative sizes range over each member's own scaled to the
    // first member's relative total, or a front a fifth of every plot's
    // depth would become two independent draws.
    auto relative_total = [&](const Split& s) {
      double t = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (frame.relative[i]) t += middle(s.parts[i].size.value).value_or(0.0);
      return t;
    };
    const double reference = relative_total(first);
    Split merged;
    merged.axis = first.axis;
    for (std::size_t i = 0; i < n; ++i) {
      Range range{0, 0};
      bool has_range = false;
      for (NodeId m : members) {
        const Split& s = std::get<Split>(g_.op(m));
        if (auto r = literal_range(s.parts[i].size.value)) {
          const double total = relative_total(s);
          if (frame.relative[i] && total > 0 && reference > 0) {
            r->lo *= reference / total;
            r->hi *= reference / total;
          }
          range = has_range ? Range{std::min(range.lo, r->lo), std::max(range.hi, r->hi)} : *r;
          has_range = true;
        }
      }
      SplitPart part;
      part.size = {range_expr(range, opt_.tolerance), frame.relative[i]};
      part.child = free[i] ? weighted_choice(g_, seen[i]) : first.parts[i].child;
      merged.parts.push_back(std::move(part));
    }
    return g_.intern({std::move(merged), {}});
  }

  Grammar& g_;
  const MergeOptions& opt_;
  FrameKinds kinds_;
  const RowBook& rows_;  // splits whose rows are known: built from examples unified
  std::vector<int> references_;  // by node id, below the root
  std::vector<bool> copied_;     // by node id: in a placed group
  std::map<std::string, Frame> frames_;
  std::map<std::string, Frame> choice_frames_;  // alternatives of one choice, by shape
};

}  // namespace

NodeId generalise_free_parts(Grammar& g, NodeId root, const MergeOptions& options, FrameKinds kinds,
                             const RowBook& rows, bool& changed, std::vector<std::pair<NodeId, NodeId>>* rebuilt,
                             std::vector<std::pair<NodeId, NodeId>>* joined) {
  return Generaliser(g, options, kinds, rows).run(root, changed, rebuilt, joined);
}

}  // namespace vern
