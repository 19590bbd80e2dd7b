#include "forward/rule_chain.hpp"

namespace vern {

std::string rule_chain_text(const Grammar& g, std::size_t depth, const std::function<RuleId(std::size_t)>& rule,
                            const std::function<std::string(std::size_t, std::size_t)>& arg) {
  auto call_text = [&](std::size_t i) {
    const Rule& r = g.rules[rule(i)];
    std::string t = r.label;
    if (!r.params.empty()) {
      t += "(";
      for (std::size_t k = 0; k < r.params.size(); ++k) t += (k ? ", " : "") + arg(i, k);
      t += ")";
    }
    return t;
  };
  std::string text;
  for (std::size_t i = 0; i < depth; ++i) {
    if (depth > 12 && i == 4) {
      text += " > ... (" + std::to_string(depth - 10) + " more) ...";
      i = depth - 6;
      continue;
    }
    text += (i ? " > " : "") + call_text(i);
  }
  return text.empty() ? "(none)" : text;
}

}  // namespace vern
