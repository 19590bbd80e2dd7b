#include "inverse/shared_frames.hpp"

#include <algorithm>
#include <limits>
#include <unordered_map>

#include "graph/nodes_below.hpp"
#include "graph/structural.hpp"
#include "inverse/substitute.hpp"

namespace vern {

namespace {

// Stands for the place where a group's splits differ.
constexpr NodeId kHole = std::numeric_limits<NodeId>::max();

// Options of one choice that are the same split but at one place.
struct Group {
  Split frame;                      // the split with kHole at `place`
  std::size_t place = 0;
  std::vector<std::size_t> options;  // indices into the choice, ascending
};

// The groups of a choice's options, largest first (ties: the first
// option's index, then the place), each option in one group at most;
// only groups of two or more.
std::vector<Group> groups_of(const Grammar& g, const Choose& c) {
  std::vector<Group> all;
  std::unordered_map<std::size_t, std::vector<std::size_t>> by_hash;  // frame hash -> indices into all
  for (std::size_t k = 0; k < c.options.size(); ++k) {
    const ChooseOption& o = c.options[k];
    const auto* s = std::get_if<Split>(&g.op(o.child));
    if (!s || !o.condition.empty() || !(o.priority.empty() || o.priority.literal())) continue;
    for (std::size_t place = 0; place < s->parts.size(); ++place) {
      Split frame = *s;
      frame.parts[place].child = kHole;
      auto& bucket = by_hash[shallow_hash(Operation{frame}) ^ place];
      const auto same = std::ranges::find_if(
          bucket, [&](std::size_t i) { return all[i].place == place && all[i].frame == frame; });
      if (same != bucket.end()) {
        all[*same].options.push_back(k);
      } else {
        bucket.push_back(all.size());
        all.push_back({std::move(frame), place, {k}});
      }
    }
  }
  std::stable_sort(all.begin(), all.end(), [](const Group& a, const Group& b) {
    if (a.options.size() != b.options.size()) return a.options.size() > b.options.size();
    return a.options.front() != b.options.front() ? a.options.front() < b.options.front() : a.place < b.place;
  });
  std::vector<bool> used(c.options.size(), false);
  std::vector<Group> out;
  for (Group& group : all) {
    std::erase_if(group.options, [&](std::size_t k) { return used[k]; });
    if (group.options.size() < 2) continue;
    for (std::size_t k : group.options) used[k] = true;
    out.push_back(std::move(group));
  }
  return out;
}

double weight(const ChooseOption& o) { return o.priority.empty() ? 1.0 : *o.priority.literal(); }

}  // namespace

NodeId share_frames(Grammar& g, NodeId root) {
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  std::vector<NodeId> chooses = nodes_below(g, root);
  std::erase_if(chooses, [&](NodeId id) { return !std::holds_alternative<Choose>(g.op(id)); });
  bool any = false;
  for (const NodeId id : chooses) {
    Choose c = std::get<Choose>(g.op(id));  // a copy: interning below may move the arena
    std::vector<Group> groups = groups_of(g, c);
    if (groups.empty()) continue;
    // Each group stands where its first option stood.
    std::vector<std::optional<ChooseOption>> at(c.options.size());
    std::vector<bool> gone(c.options.size(), false);
    for (Group& group : groups) {
      Choose place;
      double total = 0;
      for (std::size_t k : group.options) {
        const ChooseOption& o = c.options[k];
        place.options.push_back({Expr{}, Expr::number(weight(o)), std::get<Split>(g.op(o.child)).parts[group.place].child});
        total += weight(o);
        gone[k] = true;
      }
      group.frame.parts[group.place].child = g.intern({std::move(place), {}});
      const SourceLoc loc = g.node(c.options[group.options.front()].child).loc;
      at[group.options.front()] = ChooseOption{Expr{}, Expr::number(total), g.intern({std::move(group.frame), loc})};
    }
    Choose rebuilt;
    for (std::size_t k = 0; k < c.options.size(); ++k) {
      if (at[k]) rebuilt.options.push_back(std::move(*at[k]));
      else if (!gone[k]) rebuilt.options.push_back(std::move(c.options[k]));
    }
    replace[id] = rebuilt.options.size() == 1 ? rebuilt.options[0].child : g.intern({std::move(rebuilt), g.node(id).loc});
    any = true;
  }
  return any ? substitute_until_settled(g, root, replace) : root;
}

}  // namespace vern
