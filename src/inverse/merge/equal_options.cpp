#include "inverse/merge/equal_options.hpp"

#include <algorithm>
#include <optional>
#include <unordered_map>


namespace vern {

namespace {

std::optional<double> plain_weight(const ChooseOption& o) {
  if (!o.condition.empty()) return std::nullopt;
  return o.priority.empty() ? std::optional<double>(1) : o.priority.literal();
}

}  // namespace

bool join_equal_options(Choose& c) {
  std::unordered_map<NodeId, std::size_t> where;  // child -> its kept option: a choice may have thousands
  std::vector<ChooseOption> kept;
  kept.reserve(c.options.size());
  bool joined = false;
  for (ChooseOption& o : c.options) {
    const auto weight = plain_weight(o);
    if (!weight) {
      kept.push_back(std::move(o));
      continue;
    }
    const auto [it, fresh] = where.try_emplace(o.child, kept.size());
    if (fresh) {
      kept.push_back(std::move(o));
      continue;
    }
    ChooseOption& first = kept[it->second];
    first.priority = Expr::number(*plain_weight(first) + *weight);
    joined = true;
  }
  c.options = std::move(kept);
  return joined;
}

bool plain_option(const ChooseOption& o) { return o.condition.empty() && o.priority.literal().has_value(); }

bool plain_choice(const Choose& c) {
  return c.options.size() >= 2 && std::all_of(c.options.begin(), c.options.end(), plain_option);
}

}  // namespace vern
