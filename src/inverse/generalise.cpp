#include "inverse/generalise.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

#include "inverse/substitute.hpp"

namespace vern {

namespace {

// The middle of a size's range (a literal is its own middle).
std::optional<double> middle(const Expr& e) {
  if (auto r = literal_range(e)) return (r->lo + r->hi) / 2;
  return std::nullopt;
}

struct Frame {
  std::vector<NodeId> members;  // distinct split nodes, in discovery order
};

class Generaliser {
 public:
  Generaliser(Grammar& g, const MergeOptions& o)
      : g_(g), opt_(o), references_(g.node_count(), 0) {}

  NodeId run(NodeId root, bool& changed, std::vector<std::pair<NodeId, NodeId>>* rebuilt,
             std::vector<std::pair<NodeId, NodeId>>* joined) {
    changed = false;
    collect(root);
    std::vector<NodeId> replace(g_.node_count(), kNoReplacement);  // by node id
    for (auto& [key, frame] : frames_) {
      if (frame.members.size() < 2) continue;
      if (auto merged = generalise(frame)) {
        changed = true;
        for (NodeId m : frame.members) {
          replace[m] = *merged;
          if (joined) joined->emplace_back(m, *merged);
        }
      }
    }
    return changed ? substitute(g_, root, replace, rebuilt) : root;
  }

 private:
  // Every split below root, grouped by frame; references counted, since a
  // part used in two places was seen twice.
  void collect(NodeId id) {
    if (references_[id]++ > 0) return;
    const Operation& op = g_.op(id);
    for (NodeId c : node_children(op)) collect(c);
    const auto* s = std::get_if<Split>(&op);
    if (!s || s->parts.size() < 2) return;
    if (s->axis.node(s->axis.root()).kind != ExprKind::Axis) return;
    double total = 0;
    std::vector<double> mids;
    for (const auto& p : s->parts) {
      const auto m = middle(p.size.value);
      if (!m) return;
      mids.push_back(*m);
      total += *m;
    }
    if (!(total > 0)) return;
    std::string key = std::to_string(s->axis.node(s->axis.root()).op) + "/" + std::to_string(s->parts.size());
    for (std::size_t i = 0; i < s->parts.size(); ++i)
      key += (s->parts[i].size.relative ? "~" : "=") + std::to_string(std::lround(1000 * mids[i] / total));
    frames_[key].members.push_back(id);
  }

  std::optional<NodeId> generalise(const Frame& frame) {
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
      const double weight = references_[m];
      for (std::size_t i = 0; i < n; ++i) {
        auto [it, fresh] = where[i].try_emplace(s.parts[i].child, seen[i].size());
        if (fresh) seen[i].emplace_back(s.parts[i].child, weight);
        else seen[i][it->second].second += weight;
      }
    }
    for (const auto& at : seen) busiest = std::max(busiest, at.size());
    // Few fillings for the variety at each place: the places are coupled.
    if (busiest < 2 || frame.members.size() < 2 * busiest) return std::nullopt;

    // The members share their proportions (the frame's key), not their
    // lengths: relative sizes range over each member's own scaled to the
    // first member's relative total, or a front a fifth of every plot's
    // depth would become two independent draws.
    auto relative_total = [&](const Split& s) {
      double t = 0;
      for (const auto& p : s.parts)
        if (p.size.relative) t += middle(p.size.value).value_or(0.0);
      return t;
    };
    const double reference = relative_total(first);
    Split merged;
    merged.axis = first.axis;
    for (std::size_t i = 0; i < n; ++i) {
      Range range{0, 0};
      bool has_range = false;
      for (NodeId m : frame.members) {
        const Split& s = std::get<Split>(g_.op(m));
        if (auto r = literal_range(s.parts[i].size.value)) {
          const double total = relative_total(s);
          if (s.parts[i].size.relative && total > 0 && reference > 0) {
            r->lo *= reference / total;
            r->hi *= reference / total;
          }
          range = has_range ? Range{std::min(range.lo, r->lo), std::max(range.hi, r->hi)} : *r;
          has_range = true;
        }
      }
      SplitPart part;
      part.size = {range_expr(range, opt_.tolerance), first.parts[i].size.relative};
      if (seen[i].size() == 1) {
        part.child = seen[i][0].first;
      } else {
        Choose choose;
        for (const auto& [child, weight] : seen[i]) choose.options.push_back({Expr{}, Expr::number(weight), child});
        part.child = g_.intern({std::move(choose), {}});
      }
      merged.parts.push_back(std::move(part));
    }
    return g_.intern({std::move(merged), {}});
  }

  Grammar& g_;
  const MergeOptions& opt_;
  std::vector<int> references_;  // by node id, below the root
  std::map<std::string, Frame> frames_;
};

}  // namespace

NodeId generalise_free_parts(Grammar& g, NodeId root, const MergeOptions& options, bool& changed,
                             std::vector<std::pair<NodeId, NodeId>>* rebuilt,
                             std::vector<std::pair<NodeId, NodeId>>* joined) {
  return Generaliser(g, options).run(root, changed, rebuilt, joined);
}

}  // namespace vern
