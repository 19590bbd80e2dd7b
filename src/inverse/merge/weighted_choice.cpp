#include "inverse/merge/weighted_choice.hpp"

#include <algorithm>

namespace vern {

namespace {

// The options of a plain choice with their weights, or none if n is not
// one (a condition, or a weight that is not a positive literal).
std::optional<std::vector<std::pair<NodeId, double>>> plain_options(const Grammar& g, NodeId n) {
  const auto* c = std::get_if<Choose>(&g.op(n));
  if (!c) return std::nullopt;
  std::vector<std::pair<NodeId, double>> out;
  for (const ChooseOption& o : c->options) {
    const auto w = o.priority.empty() ? std::optional<double>(1.0) : o.priority.literal();
    if (!o.condition.empty() || !w || !(*w > 0)) return std::nullopt;
    out.emplace_back(o.child, *w);
  }
  return out;
}

}  // namespace

NodeId weighted_choice(Grammar& g, const std::vector<std::pair<NodeId, double>>& held) {
  std::vector<std::pair<NodeId, double>> options;
  auto add = [&](NodeId child, double weight) {
    const auto it = std::find_if(options.begin(), options.end(), [&](const auto& o) { return o.first == child; });
    if (it != options.end()) it->second += weight;
    else options.emplace_back(child, weight);
  };
  for (const auto& [child, weight] : held) {
    const auto inner = plain_options(g, child);
    if (!inner) {
      add(child, weight);
      continue;
    }
    double total = 0;
    for (const auto& [c, w] : *inner) total += w;
    for (const auto& [c, w] : *inner) add(c, weight * w / total);
  }
  if (options.size() == 1) return options[0].first;
  Choose choose;
  for (const auto& [child, weight] : options) choose.options.push_back({Expr{}, Expr::number(weight), child});
  return g.intern({std::move(choose), {}});
}

}  // namespace vern
