#include "inverse/sizes/repeat_alternatives.hpp"

#include <algorithm>
#include <map>
#include <optional>

#include "graph/nodes_below.hpp"
#include "inverse/merge/equal_options.hpp"
#include "inverse/merge/repeat_folding.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/sizes/settle_repeats.hpp"
#include "inverse/write/unused_rules.hpp"

namespace vern {

namespace {

// A run of tiles: its axis, what it repeats, its tile size (none for
// repeatN), and the runs it was seen with.
struct TileRun {
  NodeId node = 0;
  std::uint8_t axis = 0;
  NodeId tile = 0;
  std::optional<double> size;
  const std::vector<TileSeen>* seen = nullptr;
};

std::optional<TileRun> tile_run(const Grammar& g, NodeId node, const TileCounts& tile_counts) {
  const auto known = tile_counts.find(node);
  if (known == tile_counts.end() || known->second.empty()) return std::nullopt;
  TileRun run{node, 0, 0, std::nullopt, &known->second};
  if (const auto* r = std::get_if<Repeat>(&g.op(node))) {
    const auto axis = r->axis.literal_axis();
    run.size = r->size.literal();
    if (!axis || !run.size) return std::nullopt;
    run.axis = *axis;
    run.tile = r->child;
  } else if (const auto* n = std::get_if<RepeatN>(&g.op(node))) {
    const auto axis = n->axis.literal_axis();
    if (!axis || !n->count.literal()) return std::nullopt;
    run.axis = *axis;
    run.tile = n->child;
  } else {
    return std::nullopt;
  }
  return run;
}

// The rule a call without arguments runs, if node is one.
std::optional<RuleId> called_rule(const Grammar& g, NodeId node) {
  const auto* call = std::get_if<Call>(&g.op(node));
  if (!call || !call->args.empty() || call->rule >= g.rules.size()) return std::nullopt;
  return call->rule;
}

// The runs a place holds: its child, where that is a run, or each option
// of a choice of runs there (storeys of one kind of row or another), or
// the same in the body of the rule it calls without arguments.
std::vector<TileRun> runs_at(const Grammar& g, NodeId node, const TileCounts& tile_counts) {
  if (auto run = tile_run(g, node, tile_counts)) return {*run};
  if (const auto rule = called_rule(g, node)) node = g.rules[*rule].body;
  if (auto run = tile_run(g, node, tile_counts)) return {*run};
  const auto* c = std::get_if<Choose>(&g.op(node));
  if (!c) return {};
  std::vector<TileRun> runs;
  for (const ChooseOption& o : c->options) {
    auto run = plain_option(o) ? tile_run(g, o.child, tile_counts) : std::nullopt;
    if (!run) return {};
    runs.push_back(*run);
  }
  return runs;
}

// A place holding runs inside an option: the places that lead to it
// through splits (the option's split, the part's split, ...; none: the
// option itself), those splits, and the runs.
struct Site {
  std::size_t option = 0;
  std::vector<std::size_t> path;
  std::vector<NodeId> splits;
  NodeId held = 0;  // the place's child
  std::vector<TileRun> runs;
};

// Places this deep in splits are looked at: a house's storeys under its
// roof, in a plot beside its lodges.
constexpr std::size_t kDeepest = 4;

void find_sites(const Grammar& g, NodeId node, const TileCounts& tile_counts, Site& at, std::vector<Site>& out) {
  if (auto runs = runs_at(g, node, tile_counts); !runs.empty()) {
    at.held = node;
    at.runs = std::move(runs);
    out.push_back(at);
    return;
  }
  const auto* s = std::get_if<Split>(&g.op(node));
  if (!s || at.path.size() >= kDeepest) return;
  at.splits.push_back(node);
  for (std::size_t p = 0; p < s->parts.size(); ++p) {
    at.path.push_back(p);
    find_sites(g, s->parts[p].child, tile_counts, at, out);
    at.path.pop_back();
  }
  at.splits.pop_back();
}

// Whether two sites are one place of alternatives alike around it: the
// same path, through splits along the same axes with the same parts
// elsewhere (their sizes aside: each alternative keeps its own).
bool same_place(const Grammar& g, const Site& a, const Site& b) {
  if (a.path != b.path) return false;
  for (std::size_t k = 0; k < a.path.size(); ++k) {
    const Split& sa = std::get<Split>(g.op(a.splits[k]));
    const Split& sb = std::get<Split>(g.op(b.splits[k]));
    if (!(sa.axis == sb.axis) || sa.parts.size() != sb.parts.size()) return false;
    for (std::size_t p = 0; p < sa.parts.size(); ++p)
      if (p != a.path[k] && sa.parts[p].child != sb.parts[p].child) return false;
  }
  return true;
}

// Whether the runs are already one repeat of one tile size.
bool one_repeat(const std::vector<const TileRun*>& runs) {
  for (const TileRun* r : runs)
    if (!r->size || *r->size != *runs[0]->size) return false;
  return true;
}

// The tile that gives every count the runs were seen with on its length,
// if one does (none for runs that are already one repeat: nothing to do).
std::optional<double> pooled_tile(const std::vector<const TileRun*>& runs, double tolerance) {
  if (runs.size() < 2 || one_repeat(runs)) return std::nullopt;
  std::vector<TileSeen> all;
  for (const TileRun* r : runs) all.insert(all.end(), r->seen->begin(), r->seen->end());
  return common_tile(all, tolerance);
}

// Each run becomes a repeat of the tile (its runs noted in tile_counts).
void map_to_tile(Grammar& g, const std::vector<const TileRun*>& runs, double tile, TileCounts& tile_counts,
                 std::map<NodeId, NodeId>& out) {
  for (const TileRun* r : runs) {
    std::vector<TileSeen> seen = *r->seen;  // a copy: noting below may move it
    const NodeId repeat = g.intern({Repeat{Expr::axis(static_cast<Axis>(r->axis)), Expr::number(tile), r->tile}, {}});
    if (repeat == r->node) continue;
    std::vector<TileSeen>& into = tile_counts[repeat];
    into.insert(into.end(), seen.begin(), seen.end());
    out[r->node] = repeat;
  }
}

std::map<std::uint8_t, std::vector<const TileRun*>> by_axis(const std::vector<const TileRun*>& runs) {
  std::map<std::uint8_t, std::vector<const TileRun*>> out;
  for (const TileRun* r : runs) out[r->axis].push_back(r);
  return out;
}

// Runs seen at one place of the alternatives: each becomes a repeat of
// the tile that explains them all, where one does (the runs along one
// axis first, else those of one tile each), unless their axis is settled
// already. Returns the repeats by run node; a run absent is as it was.
std::map<NodeId, NodeId> settle(Grammar& g, const std::vector<const TileRun*>& runs, TileCounts& tile_counts,
                                double tolerance, const std::map<std::uint8_t, double>& settled = {}) {
  std::map<NodeId, NodeId> out;
  for (const auto& [axis, along] : by_axis(runs)) {
    if (const auto it = settled.find(axis); it != settled.end()) {
      map_to_tile(g, along, it->second, tile_counts, out);
      continue;
    }
    if (const auto tile = pooled_tile(along, tolerance)) {
      map_to_tile(g, along, *tile, tile_counts, out);
      continue;
    }
    std::map<NodeId, std::vector<const TileRun*>> by_tile;
    for (const TileRun* r : along) by_tile[r->tile].push_back(r);
    for (const auto& [tile_node, alike] : by_tile)
      if (const auto tile = pooled_tile(alike, tolerance)) map_to_tile(g, alike, *tile, tile_counts, out);
  }
  return out;
}

// A node (a run, or a choice of runs) with its runs replaced.
NodeId replaced(Grammar& g, NodeId node, const std::map<NodeId, NodeId>& repeats) {
  auto now = [&](NodeId n) {
    const auto it = repeats.find(n);
    return it == repeats.end() ? n : it->second;
  };
  if (!std::holds_alternative<Choose>(g.op(node))) return now(node);
  Choose c = std::get<Choose>(g.op(node));
  for (ChooseOption& o : c.options) o.child = now(o.child);
  return g.intern({std::move(c), g.node(node).loc});
}

// The site's split at level k rebuilt with the place's child replaced.
NodeId rebuilt(Grammar& g, const Site& site, std::size_t k, NodeId child) {
  if (k == site.path.size()) return child;
  Split s = std::get<Split>(g.op(site.splits[k]));  // a copy: interning below may grow the arena
  s.parts[site.path[k]].child = rebuilt(g, site, k + 1, child);
  return g.intern({std::move(s), g.node(site.splits[k]).loc});
}

// The runs every repeat made in the examples' derivations: each a count on
// a length. Complete: every place a repeat stands in a derivation.
TileCounts runs_derived(const std::vector<CheckResult>& results) {
  TileCounts out;
  for (const CheckResult& r : results)
    for (const CheckStep& step : r.steps)
      if (step.kind == CheckStep::Kind::Tiles && step.value >= 1)
        out[step.node].push_back({static_cast<std::uint32_t>(step.value), step.value * step.length});
  return out;
}

// The runs of a group of sites.
std::vector<const TileRun*> runs_of(const std::vector<Site>& group) {
  std::vector<const TileRun*> runs;
  for (const Site& site : group)
    for (const TileRun& r : site.runs) runs.push_back(&r);
  return runs;
}

// Whether any choice has two options or more holding a repeat or repeatN
// at the same path through splits, not all one repeat: the only choices
// this step may change. Found before any example is checked, so that a
// grammar without them costs no check.
bool any_candidate(const Grammar& g, const std::vector<NodeId>& nodes) {
  const TileCounts every = [&] {
    TileCounts all;  // every repeat counted as seen once: candidates only
    for (const NodeId n : nodes)
      if (std::holds_alternative<Repeat>(g.op(n)) || std::holds_alternative<RepeatN>(g.op(n)))
        all[n].push_back({1, 1});
    return all;
  }();
  for (const NodeId n : nodes) {
    const auto* c = std::get_if<Choose>(&g.op(n));
    if (!c || c->options.size() < 2) continue;
    std::vector<Site> sites;
    for (std::size_t i = 0; i < c->options.size(); ++i) {
      if (!plain_option(c->options[i])) continue;
      Site at;
      at.option = i;
      find_sites(g, c->options[i].child, every, at, sites);
    }
    for (std::size_t a = 0; a < sites.size(); ++a)
      for (std::size_t b = a + 1; b < sites.size(); ++b) {
        if (sites[a].option == sites[b].option || !same_place(g, sites[a], sites[b])) continue;
        if (!one_repeat(runs_of({sites[a], sites[b]}))) return true;
      }
  }
  return false;
}

// The places alike across two or more options of one choice, each group's
// sites; an option is in one group at most (rebuilt for one place, its
// other sites are gone).
std::vector<std::vector<Site>> places_alike(const Grammar& g, const Choose& c, const TileCounts& tile_counts) {
  std::vector<Site> sites;
  for (std::size_t i = 0; i < c.options.size(); ++i) {
    if (!plain_option(c.options[i])) continue;
    Site at;
    at.option = i;
    find_sites(g, c.options[i].child, tile_counts, at, sites);
  }
  std::vector<std::vector<Site>> groups;
  std::vector<bool> placed(sites.size(), false), grouped_option(c.options.size(), false);
  for (std::size_t a = 0; a < sites.size(); ++a) {
    if (placed[a]) continue;
    std::vector<std::size_t> alike{a};
    for (std::size_t b = a + 1; b < sites.size(); ++b)
      if (!placed[b] && sites[b].option != sites[a].option && same_place(g, sites[a], sites[b])) alike.push_back(b);
    for (const std::size_t k : alike) placed[k] = true;
    if (alike.size() < 2 ||
        std::any_of(alike.begin(), alike.end(), [&](std::size_t k) { return grouped_option[sites[k].option]; }))
      continue;
    std::vector<Site> group;
    for (const std::size_t k : alike) {
      grouped_option[sites[k].option] = true;
      group.push_back(sites[k]);
    }
    if (!one_repeat(runs_of(group))) groups.push_back(std::move(group));
  }
  return groups;
}

// c's options at the group's sites with their runs replaced by repeats.
// A place that calls a rule holding the runs keeps its call, and the
// rule's body is rewritten (bodies, by rule; the runs counted are every
// place the rule's runs stood, so every caller keeps its counts); a rule
// rewritten for one group is not rewritten again.
bool apply(Grammar& g, Choose& c, const std::vector<Site>& group, const std::map<NodeId, NodeId>& repeats,
           std::map<RuleId, NodeId>& bodies) {
  bool changed = false;
  for (const Site& site : group) {
    if (const auto rule = called_rule(g, site.held)) {
      if (bodies.count(*rule)) continue;
      const NodeId body = replaced(g, g.rules[*rule].body, repeats);
      if (body == g.rules[*rule].body) continue;
      bodies[*rule] = body;
      changed = true;
      continue;
    }
    const NodeId held = replaced(g, site.held, repeats);
    if (held == site.held) continue;
    c.options[site.option].child = rebuilt(g, site, 0, held);
    changed = true;
  }
  return changed;
}

}  // namespace

std::size_t join_tile_run_alternatives(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                                       Witnesses& witnesses) {
  const std::vector<NodeId> nodes = nodes_of_rules(g);
  if (!any_candidate(g, nodes)) return 0;
  if (!witnesses_of(g, examples, options, witnesses)) return 0;
  TileCounts runs = runs_derived(witnesses.results);
  const Grammar before = g;
  // The places of every choice; then, per axis, one tile for all of them
  // where one explains every run (storeys of one height in every kind of
  // house), else each place's own.
  std::vector<std::pair<NodeId, std::vector<std::vector<Site>>>> choices;
  std::vector<const TileRun*> every;
  for (const NodeId id : nodes) {  // in id order: one order every time
    const auto* c = std::get_if<Choose>(&g.op(id));
    if (!c) continue;
    auto groups = places_alike(g, *c, runs);
    if (groups.empty()) continue;
    choices.push_back({id, std::move(groups)});
    for (const auto& group : choices.back().second)
      for (const TileRun* r : runs_of(group)) every.push_back(r);
  }
  std::map<std::uint8_t, double> settled;
  for (const auto& [axis, along] : by_axis(every))
    if (const auto tile = pooled_tile(along, options.tolerance)) settled[axis] = *tile;
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  std::map<RuleId, NodeId> bodies;
  std::size_t count = 0;
  for (const auto& [id, groups] : choices) {
    Choose copy = std::get<Choose>(g.op(id));
    bool changed = false;
    for (const std::vector<Site>& group : groups)
      changed = apply(g, copy, group, settle(g, runs_of(group), runs, options.tolerance, settled), bodies) || changed;
    if (!changed) continue;
    join_equal_options(copy);
    const NodeId now = copy.options.size() == 1 ? copy.options[0].child : g.intern({std::move(copy), g.node(id).loc});
    if (replace.size() < g.node_count()) replace.resize(g.node_count(), kNoReplacement);
    replace[id] = now;
    ++count;
  }
  if (count == 0) return 0;
  for (const auto& [rule, body] : bodies) g.rules[rule].body = body;
  for (Rule& rule : g.rules) rule.body = substitute_until_settled(g, rule.body, replace);
  drop_unused_rules(g);
  std::vector<CheckResult> results;
  if (!derives_examples(g, examples, options, results)) {
    g = before;
    return 0;
  }
  witnesses.results = std::move(results);
  return count;
}

}  // namespace vern
