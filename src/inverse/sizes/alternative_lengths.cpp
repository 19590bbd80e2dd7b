#include "inverse/sizes/alternative_lengths.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "graph/nodes_below.hpp"
#include "inverse/merge/substitute.hpp"

namespace vern {

namespace {

// An option seen at one length: its parts' lengths (the relative weights,
// which inference writes in metres) and their sum, the scope it filled.
struct Seen {
  std::size_t option = 0;
  std::vector<double> lengths;
  double total = 0;
};

std::optional<Seen> seen_at_one_length(const Split& s, std::size_t option) {
  Seen out{option, {}, 0};
  for (const SplitPart& p : s.parts) {
    const auto v = p.size.value.literal();
    if (!p.size.relative || !v || *v <= 0) return std::nullopt;
    out.lengths.push_back(*v);
    out.total += *v;
  }
  return out;
}

bool lengths_differ(const std::vector<Seen>& options, double tolerance) {
  double shortest = options[0].total, longest = shortest;
  for (const Seen& o : options) {
    shortest = std::min(shortest, o.total);
    longest = std::max(longest, o.total);
  }
  return longest - shortest > tolerance;
}

// A stretching repeat along the split's axis with a literal tile: what
// an option's run of storeys may become. holds: the tiles it may make
// (its child, or each option of its child's choice).
struct Stretch {
  NodeId node = 0;
  double tile = 0;
  std::vector<NodeId> holds;
};

std::optional<Stretch> stretch_of(const Grammar& g, NodeId id, std::uint8_t axis) {
  const auto* r = std::get_if<Repeat>(&g.op(id));
  if (!r || r->axis.literal_axis() != axis) return std::nullopt;
  const auto tile = r->size.literal();
  if (!tile || *tile <= 0) return std::nullopt;
  Stretch out{id, *tile, {}};
  if (const auto* c = std::get_if<Choose>(&g.op(r->child))) {
    for (const ChooseOption& o : c->options) {
      if (!o.condition.empty()) return std::nullopt;
      out.holds.push_back(o.child);
    }
  } else {
    out.holds.push_back(r->child);
  }
  return out;
}

// The parts [first, last) of s with each repeatN of a literal count along
// the split's axis spelled out as its tiles (inference writes a run of
// equal storeys beside an unlike one as repeatN(z, 2){ ... }).
std::vector<SplitPart> tiles_of(const Grammar& g, const Split& s, std::size_t first, std::size_t last,
                                std::uint8_t axis) {
  std::vector<SplitPart> out;
  for (std::size_t i = first; i < last; ++i) {
    const SplitPart& p = s.parts[i];
    const auto* r = std::get_if<RepeatN>(&g.op(p.child));
    const auto n = r ? r->count.literal() : std::nullopt;
    const auto length = p.size.value.literal();
    const bool along = r && r->axis.literal_axis() == axis;
    if (!along || !n || *n < 1 || *n != std::round(*n) || !length || !p.size.relative) {
      out.push_back(p);
      continue;
    }
    for (double k = 0; k < *n; ++k) out.push_back({{Expr::number(*length / *n), true}, r->child});
  }
  return out;
}

// Can a run of relative parts be one part holding the stretch? Only if
// the repeat, on their length, makes as many tiles as there are parts,
// each as long as they were (so each example derives as it did), the
// parts are about a tile long (within a quarter: a 1 m parapet is no
// storey of 4.9 m) and it may make each of them.
bool run_fits(const std::vector<SplitPart>& run, const Stretch& stretch, double tolerance) {
  if (run.empty()) return false;
  double length = 0;
  for (const SplitPart& p : run) {
    const auto v = p.size.value.literal();
    if (!p.size.relative || !v) return false;
    length += *v;
  }
  const double each = length / static_cast<double>(run.size());
  for (const SplitPart& p : run) {
    if (std::abs(*p.size.value.literal() - each) > tolerance) return false;
    if (std::find(stretch.holds.begin(), stretch.holds.end(), p.child) == stretch.holds.end()) return false;
  }
  return std::abs(each - stretch.tile) <= stretch.tile / 4 &&
         repeat_tile_count(length, stretch.tile) == static_cast<double>(run.size());
}

// Whether an option keeps every cut within the tolerance with the parts
// `absolute` in metres and the rest sharing what they leave.
bool keeps_cuts(const Seen& o, const std::map<std::size_t, double>& absolute, double tolerance) {
  double fixed = 0, weights = 0;
  for (std::size_t i = 0; i < o.lengths.size(); ++i) {
    if (const auto it = absolute.find(i); it != absolute.end()) fixed += it->second;
    else weights += o.lengths[i];
  }
  const double rest = o.total - fixed;
  if (rest <= 0 || weights <= 0) return false;
  double was = 0, now = 0;
  for (std::size_t i = 0; i < o.lengths.size(); ++i) {
    was += o.lengths[i];
    const auto it = absolute.find(i);
    now += it != absolute.end() ? it->second : o.lengths[i] * rest / weights;
    if (std::abs(was - now) > tolerance) return false;
  }
  return true;
}

// Which parts of each option become absolute, and at what length: a
// leading and a trailing run of positions where every option's length
// agrees. Empty when none does, or when the options' parts would move by
// more than the tolerance (lengths that agree only within it add up).
std::vector<std::map<std::size_t, double>> plan(const std::vector<Seen>& options, double tolerance) {
  std::size_t fewest = options[0].lengths.size();
  for (const Seen& o : options) fewest = std::min(fewest, o.lengths.size());
  // The length all options give the part at index_of(option), if they agree.
  auto agreed = [&](auto index_of) -> std::optional<double> {
    double lo = options[0].lengths[index_of(options[0])], hi = lo;
    for (const Seen& o : options) {
      lo = std::min(lo, o.lengths[index_of(o)]);
      hi = std::max(hi, o.lengths[index_of(o)]);
    }
    if (hi - lo > tolerance) return std::nullopt;
    return (lo + hi) / 2;
  };
  std::vector<double> leading, trailing;
  while (leading.size() + 1 < fewest) {
    const std::size_t i = leading.size();
    const auto v = agreed([i](const Seen&) { return i; });
    if (!v) break;
    leading.push_back(*v);
  }
  while (leading.size() + trailing.size() + 1 < fewest) {
    const std::size_t j = trailing.size();
    const auto v = agreed([j](const Seen& o) { return o.lengths.size() - 1 - j; });
    if (!v) break;
    trailing.push_back(*v);
  }
  if (leading.empty() && trailing.empty()) return {};
  std::vector<std::map<std::size_t, double>> out;
  for (const Seen& o : options) {
    std::map<std::size_t, double> absolute;
    for (std::size_t i = 0; i < leading.size(); ++i) absolute[i] = leading[i];
    for (std::size_t j = 0; j < trailing.size(); ++j) absolute[o.lengths.size() - 1 - j] = trailing[j];
    // Where each cut falls now, against where the example had it.
    if (!keeps_cuts(o, absolute, tolerance)) return {};
    out.push_back(std::move(absolute));
  }
  return out;
}

// The metres that options already settled give their leading and
// trailing parts along the axis (a choice whose other options were seen
// at several lengths: 4.4 m of ground floor, 2.8 m of roof), where all
// such options agree; empty where none has any.
struct Ends {
  std::vector<double> leading, trailing;
};

Ends settled_ends(const Grammar& g, const Choose& choose, std::uint8_t axis, double tolerance) {
  std::optional<Ends> agreed;
  auto same = [&](const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (std::abs(a[i] - b[i]) > tolerance) return false;
    return true;
  };
  for (const ChooseOption& o : choose.options) {
    const auto* s = std::get_if<Split>(&g.op(o.child));
    if (!s || s->axis.literal_axis() != axis) continue;
    Ends ends;
    std::size_t i = 0;
    for (; i < s->parts.size() && !s->parts[i].size.relative && s->parts[i].size.value.literal(); ++i)
      ends.leading.push_back(*s->parts[i].size.value.literal());
    for (std::size_t j = s->parts.size(); j > i && !s->parts[j - 1].size.relative && s->parts[j - 1].size.value.literal();
         --j)
      ends.trailing.push_back(*s->parts[j - 1].size.value.literal());
    if (i == s->parts.size() || (ends.leading.empty() && ends.trailing.empty())) continue;
    if (!agreed) agreed = ends;
    else if (!same(agreed->leading, ends.leading) || !same(agreed->trailing, ends.trailing)) return {};
  }
  return agreed.value_or(Ends{});
}

// An option seen at one length whose leading and trailing parts are as
// long as the settled options' metres: those parts, at those lengths
// (the caller checks that no cut moves). Empty where none agrees.
std::map<std::size_t, double> anchored(const Seen& o, const Ends& ends, double tolerance) {
  std::map<std::size_t, double> absolute;
  for (std::size_t i = 0; i < ends.leading.size() && i + 1 < o.lengths.size(); ++i) {
    if (std::abs(o.lengths[i] - ends.leading[i]) > tolerance) break;
    absolute[i] = ends.leading[i];
  }
  for (std::size_t j = 0; j < ends.trailing.size() && absolute.size() + 1 < o.lengths.size(); ++j) {
    const std::size_t i = o.lengths.size() - 1 - j;
    if (absolute.count(i) || std::abs(o.lengths[i] - ends.trailing[j]) > tolerance) break;
    absolute[i] = ends.trailing[j];
  }
  return absolute;
}

}  // namespace

NodeId absolute_across_alternatives(Grammar& g, NodeId root, double tolerance) {
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  std::vector<NodeId> chooses = nodes_below(g, root);
  std::erase_if(chooses, [&](NodeId id) { return !std::holds_alternative<Choose>(g.op(id)); });
  bool any = false;
  for (const NodeId id : chooses) {
    Choose choose = std::get<Choose>(g.op(id));
    std::map<std::uint8_t, std::vector<Seen>> by_axis;
    for (std::size_t k = 0; k < choose.options.size(); ++k) {
      const auto* s = std::get_if<Split>(&g.op(choose.options[k].child));
      const auto axis = s ? s->axis.literal_axis() : std::nullopt;
      if (!axis) continue;
      if (auto seen = seen_at_one_length(*s, k)) by_axis[*axis].push_back(std::move(*seen));
    }
    bool changed = false;
    for (const auto& [axis, options] : by_axis) {
      const bool apart = options.size() >= 2 && lengths_differ(options, tolerance);
      std::vector<std::map<std::size_t, double>> absolute;
      if (apart) absolute = plan(options, tolerance);
      absolute.resize(options.size());  // no plan: no part is absolute
      // Options seen at one length beside options already settled in
      // metres (a house seen once, at one height, beside houses seen at
      // many): their ends as the settled options' where as long.
      const Ends ends = settled_ends(g, choose, axis, tolerance);
      bool anchors = false;
      for (std::size_t k = 0; k < options.size(); ++k) {
        std::map<std::size_t, double> more = absolute[k];
        for (const auto& [i, v] : anchored(options[k], ends, tolerance)) more.emplace(i, v);
        if (more.size() > absolute[k].size() && keeps_cuts(options[k], more, tolerance)) {
          absolute[k] = std::move(more);
          anchors = true;
        }
      }
      if (!apart && !anchors) continue;
      std::vector<Split> splits;
      std::vector<Stretch> stretches;
      for (std::size_t k = 0; k < options.size(); ++k) {
        splits.push_back(std::get<Split>(g.op(choose.options[options[k].option].child)));
        for (const auto& [i, v] : absolute[k]) splits[k].parts[i].size = {Expr::number(v), false};
        for (const SplitPart& p : splits[k].parts)
          if (auto stretch = stretch_of(g, p.child, axis)) stretches.push_back(std::move(*stretch));
      }
      std::sort(stretches.begin(), stretches.end(), [](const Stretch& a, const Stretch& b) { return a.node < b.node; });
      for (std::size_t k = 0; k < options.size(); ++k) {
        Split& split = splits[k];
        // What is left between the absolute parts stretches with the plot:
        // a sibling's repeat of storeys may stand for a run of them.
        std::size_t first = 0;
        while (absolute[k].count(first)) ++first;
        std::size_t last = split.parts.size();
        while (last > first && absolute[k].count(last - 1)) --last;
        bool rebuilt = !absolute[k].empty();
        const bool already = last - first == 1 && stretch_of(g, split.parts[first].child, axis);
        for (const Stretch& stretch : already ? std::vector<Stretch>{} : stretches) {
          if (!run_fits(tiles_of(g, split, first, last, axis), stretch, tolerance)) continue;
          double length = 0;
          for (std::size_t i = first; i < last; ++i) length += *split.parts[i].size.value.literal();
          split.parts.erase(split.parts.begin() + static_cast<std::ptrdiff_t>(first) + 1,
                            split.parts.begin() + static_cast<std::ptrdiff_t>(last));
          split.parts[first] = {{Expr::number(length), true}, stretch.node};
          rebuilt = true;
          break;
        }
        if (!rebuilt) continue;
        ChooseOption& option = choose.options[options[k].option];
        // A split left with one part is that part's operation.
        option.child = split.parts.size() == 1 ? split.parts[0].child
                                               : g.intern({std::move(split), g.node(option.child).loc});
        changed = true;
      }
    }
    if (!changed) continue;
    replace[id] = g.intern({std::move(choose), g.node(id).loc});
    any = true;
  }
  return any ? substitute_until_settled(g, root, replace) : root;
}

}  // namespace vern
