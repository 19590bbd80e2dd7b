#include "inverse/merge/shared_frames.hpp"

#include <algorithm>
#include <unordered_map>

#include "graph/nodes_below.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/merge/weighted_choice.hpp"

namespace vern {

namespace {

// Options of one choice that are the same split but at one place.
struct Group {
  std::size_t place = 0;
  std::vector<std::size_t> options;  // indices into the choice, ascending; the first stands for all
};

// Are splits a and b the same but for the child at `place`?
bool alike_but_at(const Split& a, const Split& b, std::size_t place) {
  if (a.axis != b.axis || a.parts.size() != b.parts.size() || a.parts[place].size != b.parts[place].size) return false;
  for (std::size_t i = 0; i < a.parts.size(); ++i)
    if (i != place && a.parts[i] != b.parts[i]) return false;
  return true;
}

std::size_t part_hash(const SplitPart& p) {
  return hash_combine(hash_combine(p.size.value.hash(), p.size.relative ? 1 : 0), p.child);
}

// The groups of a choice's options, largest first (ties: the first
// option's index, then the place), each option in one group at most;
// only groups of two or more. Each (option, place) is keyed by a hash of
// the split without that place's child, from prefix and suffix hashes of
// its parts, so a choice of many wide splits is not copied place by place.
std::vector<Group> groups_of(const Grammar& g, const Choose& c) {
  std::vector<Group> all;
  std::unordered_map<std::size_t, std::vector<std::size_t>> by_hash;  // key -> indices into all
  for (std::size_t k = 0; k < c.options.size(); ++k) {
    const ChooseOption& o = c.options[k];
    const auto* s = std::get_if<Split>(&g.op(o.child));
    if (!s || !o.condition.empty() || !(o.priority.empty() || o.priority.literal())) continue;
    const std::size_t n = s->parts.size();
    std::vector<std::size_t> suffix(n + 1, 0);
    for (std::size_t i = n; i-- > 0;) suffix[i] = hash_combine(suffix[i + 1], part_hash(s->parts[i]));
    std::size_t prefix = hash_combine(s->axis.hash(), n);
    for (std::size_t place = 0; place < n; ++place) {
      const std::size_t key = hash_combine(
          hash_combine(hash_combine(prefix, place), s->parts[place].size.value.hash()), suffix[place + 1]);
      prefix = hash_combine(prefix, part_hash(s->parts[place]));
      auto& bucket = by_hash[key];
      const auto same = std::ranges::find_if(bucket, [&](std::size_t i) {
        return all[i].place == place &&
               alike_but_at(std::get<Split>(g.op(c.options[all[i].options.front()].child)), *s, place);
      });
      if (same != bucket.end()) {
        all[*same].options.push_back(k);
      } else {
        bucket.push_back(all.size());
        all.push_back({place, {k}});
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
    if (group.options.size() < 2) break;  // sorted: the rest are single
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
      std::vector<std::pair<NodeId, double>> place;
      double total = 0;
      for (std::size_t k : group.options) {
        const ChooseOption& o = c.options[k];
        place.emplace_back(std::get<Split>(g.op(o.child)).parts[group.place].child, weight(o));
        total += weight(o);
        gone[k] = true;
      }
      const NodeId representative = c.options[group.options.front()].child;
      Split frame = std::get<Split>(g.op(representative));
      frame.parts[group.place].child = weighted_choice(g, place);
      const SourceLoc loc = g.node(representative).loc;
      at[group.options.front()] = ChooseOption{Expr{}, Expr::number(total), g.intern({std::move(frame), loc})};
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
