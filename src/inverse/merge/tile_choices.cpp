#include "inverse/merge/tile_choices.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "inverse/merge/merge.hpp"
#include "inverse/merge/substitute.hpp"

namespace vern {

namespace {

// A choose merging made: no conditions, literal priorities.
const Choose* plain_choose(const Operation& op) {
  const auto* c = std::get_if<Choose>(&op);
  if (!c) return nullptr;
  for (const ChooseOption& o : c->options)
    if (!o.condition.empty() || !o.priority.literal()) return nullptr;
  return c;
}

// How far apart two kinds of tile may lie in length and still be one
// kind: the longer's shortest at most this times the shorter's longest.
constexpr double kLengthGap = 1.25;

constexpr std::size_t kWholeTile = static_cast<std::size_t>(-1);

// One place in one repeat's tile where what is derived varies (or could).
struct Slot {
  NodeId repeat = 0;
  std::size_t part = kWholeTile;  // the tile itself, or this part of the tile's split
  NodeId held = 0;                // the choose there, or the lone tile
  Range tile;                     // the repeat's tile length (a range once merged)
  double tiles = 0;               // how many tiles the repeat made in the examples (0: not known)
  std::vector<std::pair<NodeId, double>> options;
};

// Where a slot sits, for linking: the repeat's axis, and the place in the
// tile (a part of a split along some axis into some number of parts).
using Place = std::tuple<std::uint8_t, std::size_t, std::size_t, std::uint8_t>;

class Uniter {
 public:
  Uniter(Grammar& g, const TileCounts* tile_counts) : g_(g), tile_counts_(tile_counts), seen_(g.node_count(), false) {}

  TileChoiceUnion run(NodeId root) {
    collect(root);
    std::vector<std::size_t> parent(slots_.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::size_t s) {
      while (parent[s] != s) s = parent[s] = parent[parent[s]];
      return s;
    };
    // Each class's tile lengths: two classes join only where their lengths
    // leave no gap wider than a quarter between them. A block's strips of
    // buildings and a tower cluster's strips of towers a third as wide
    // stay apart, though both hold plain boxes.
    std::vector<Range> lengths;
    for (const Slot& slot : slots_) lengths.push_back(slot.tile);
    auto join = [&](std::size_t a, std::size_t b) {
      a = find(a);
      b = find(b);
      if (a == b) return;
      const Range& x = lengths[a];
      const Range& y = lengths[b];
      if (std::max(x.lo, y.lo) > kLengthGap * std::min(x.hi, y.hi)) return;
      parent[b] = a;
      lengths[a] = {std::min(x.lo, y.lo), std::max(x.hi, y.hi)};
    };
    std::map<std::pair<Place, NodeId>, std::vector<std::size_t>> holders;  // (place, alternative) -> slots
    for (std::size_t s = 0; s < slots_.size(); ++s)
      for (const auto& [alternative, weight] : slots_[s].options) holders[{places_[s], alternative}].push_back(s);
    for (const auto& [key, held_by] : holders)
      for (std::size_t i = 1; i < held_by.size(); ++i) join(held_by[0], held_by[i]);
    // Each class's union, alternatives in order of first appearance; a
    // choose shared by several repeats counts once.
    std::unordered_map<std::size_t, std::vector<std::size_t>> members;
    std::vector<std::size_t> classes;
    for (std::size_t s = 0; s < slots_.size(); ++s) {
      auto& m = members[find(s)];
      if (m.empty()) classes.push_back(find(s));
      m.push_back(s);
    }
    std::unordered_map<std::size_t, NodeId> united;  // class -> its choose
    for (std::size_t c : classes) {
      std::vector<std::pair<NodeId, double>> options;
      auto add = [&](NodeId alternative, double weight) {
        auto it = std::find_if(options.begin(), options.end(), [&](const auto& o) { return o.first == alternative; });
        if (it == options.end()) options.emplace_back(alternative, weight);
        else it->second += weight;
      };
      // Slots that all hold one thing have nothing to unite (weighing it
      // again by tiles would only round its weights anew).
      const NodeId first = slots_[members[c].front()].held;
      if (std::all_of(members[c].begin(), members[c].end(), [&](std::size_t s) { return slots_[s].held == first; }))
        continue;
      const bool by_tiles =
          std::all_of(members[c].begin(), members[c].end(), [&](std::size_t s) { return slots_[s].tiles > 0; });
      std::vector<NodeId> counted;
      for (std::size_t s : members[c]) {
        if (by_tiles) {
          // Each repeat's tiles shared out by its choice's weights: a row
          // of twelve plain buildings weighs twelve, not one, against the
          // rows that held plain and roofed ones.
          double total = 0;
          for (const auto& held : slots_[s].options) total += held.second;
          for (const auto& [alternative, weight] : slots_[s].options)
            add(alternative, slots_[s].tiles * weight / total);
          continue;
        }
        if (std::find(counted.begin(), counted.end(), slots_[s].held) != counted.end()) continue;
        counted.push_back(slots_[s].held);
        for (const auto& [alternative, weight] : slots_[s].options) add(alternative, weight);
      }
      if (options.size() < 2) continue;
      if (by_tiles)
        for (auto& option : options) option.second = std::max(1.0, std::round(option.second));
      if (std::get<1>(places_[c]) == kWholeTile && one_frame(options)) continue;
      Choose choose;
      for (const auto& [alternative, weight] : options)
        choose.options.push_back({Expr{}, Expr::number(weight), alternative});
      united[c] = g_.intern({std::move(choose), {}});
    }
    // Each repeat with its slots' choices united.
    TileChoiceUnion out;
    std::vector<NodeId> replace(g_.node_count(), kNoReplacement);
    for (std::size_t s = 0; s < slots_.size();) {
      const NodeId repeat = slots_[s].repeat;
      Repeat r = std::get<Repeat>(g_.op(repeat));
      Operation tile = g_.op(r.child);
      bool changed = false;
      for (; s < slots_.size() && slots_[s].repeat == repeat; ++s) {
        const auto it = united.find(find(s));
        if (it == united.end() || it->second == slots_[s].held) continue;
        changed = true;
        if (slots_[s].part == kWholeTile) r.child = it->second;
        else std::get<Split>(tile).parts[slots_[s].part].child = it->second;
      }
      if (!changed) continue;
      if (std::holds_alternative<Split>(tile) && r.child == std::get<Repeat>(g_.op(repeat)).child)
        r.child = g_.intern({std::move(tile), {}});
      const NodeId rebuilt = g_.intern({std::move(r), g_.node(repeat).loc});
      if (rebuilt == repeat) continue;
      replace[repeat] = rebuilt;
      out.replaced.emplace_back(repeat, rebuilt);
    }
    out.root = out.replaced.empty() ? root : substitute(g_, root, replace, &out.replaced);
    return out;
  }

 private:
  bool is_nil(NodeId id) const { return std::holds_alternative<Nil>(g_.op(id)); }

  // Whole tiles that are one split but for what some parts hold (a storey
  // of a balcony and glass, one of a wall and glass): their parts are the
  // slots that unite, not the tiles (the frame's part then a choice).
  bool one_frame(const std::vector<std::pair<NodeId, double>>& options) const {
    const auto* first = std::get_if<Split>(&g_.op(options[0].first));
    if (!first) return false;
    return std::all_of(options.begin() + 1, options.end(), [&](const auto& o) {
      const auto* s = std::get_if<Split>(&g_.op(o.first));
      if (!s || s->axis != first->axis || s->parts.size() != first->parts.size()) return false;
      for (std::size_t i = 0; i < s->parts.size(); ++i)
        if (!(s->parts[i].size == first->parts[i].size)) return false;
      return true;
    });
  }

  void add_slot(NodeId repeat, std::size_t part, NodeId held, const Place& place, Range tile) {
    Slot slot{repeat, part, held, tile, 0, {}};
    if (tile_counts_)
      if (const auto seen = tile_counts_->find(repeat); seen != tile_counts_->end())
        for (const TileSeen& t : seen->second) slot.tiles += t.count;
    if (const Choose* c = plain_choose(g_.op(held))) {
      for (const ChooseOption& o : c->options) slot.options.emplace_back(o.child, *o.priority.literal());
    } else {
      slot.options.emplace_back(held, 1.0);
    }
    slots_.push_back(std::move(slot));
    places_.push_back(place);
  }

  // Every repeat below id, depth first in order: its slots.
  void collect(NodeId id) {
    if (seen_[id]) return;
    seen_[id] = true;
    for_each_child(g_.op(id), [&](NodeId c) { collect(c); });
    const auto* r = std::get_if<Repeat>(&g_.op(id));
    const auto axis = r ? r->axis.literal_axis() : std::nullopt;
    const auto tile = r ? literal_range(r->size) : std::nullopt;
    if (!axis || !tile || is_nil(r->child)) return;
    const auto* split = std::get_if<Split>(&g_.op(r->child));
    const auto split_axis = split ? split->axis.literal_axis() : std::nullopt;
    if (!split_axis) {
      add_slot(id, kWholeTile, r->child, {*axis, kWholeTile, 0, 0}, *tile);
      return;
    }
    // The whole tile too, as a choice of one: a row whose bays all came
    // out windows is the row whose bays are each a window or a balcony
    // (unless the tiles are one frame: one_frame).
    add_slot(id, kWholeTile, r->child, {*axis, kWholeTile, 0, 0}, *tile);
    for (std::size_t i = 0; i < split->parts.size(); ++i) {
      const NodeId child = std::get<Split>(g_.op(r->child)).parts[i].child;
      if (!is_nil(child)) add_slot(id, i, child, {*axis, i, split->parts.size(), *split_axis}, *tile);
    }
  }

  Grammar& g_;
  const TileCounts* tile_counts_;  // may be null
  std::vector<bool> seen_;  // by node id
  std::vector<Slot> slots_;  // grouped by repeat, in collection order
  std::vector<Place> places_;  // per slot
};

}  // namespace

TileChoiceUnion unite_tile_choices(Grammar& g, NodeId root, const TileCounts* tile_counts) {
  return Uniter(g, tile_counts).run(root);
}

}  // namespace vern
