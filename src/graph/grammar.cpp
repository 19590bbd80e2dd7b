#include "graph/grammar.hpp"

#include "graph/structural.hpp"

namespace vern {

NodeId Grammar::add(Node node) {
  nodes_.push_back(std::move(node));
  return static_cast<NodeId>(nodes_.size() - 1);
}

NodeId Grammar::intern(Node node) {
  const std::size_t h = shallow_hash(node.op);
  auto [begin, end] = interned_.equal_range(h);
  for (auto it = begin; it != end; ++it)
    if (nodes_[it->second].op == node.op) return it->second;
  const NodeId id = add(std::move(node));
  interned_.emplace(h, id);
  return id;
}

LabelId Grammar::label_id(std::string_view name) {
  if (auto found = find_label(name)) return *found;
  labels_.emplace_back(name);
  return static_cast<LabelId>(labels_.size() - 1);
}

std::optional<LabelId> Grammar::find_label(std::string_view name) const {
  for (std::size_t i = 0; i < labels_.size(); ++i)
    if (labels_[i] == name) return static_cast<LabelId>(i);
  return std::nullopt;
}

std::optional<RuleId> Grammar::find_rule(std::string_view label) const {
  for (std::size_t i = 0; i < rules.size(); ++i)
    if (rules[i].label == label) return static_cast<RuleId>(i);
  return std::nullopt;
}

std::optional<std::uint32_t> Grammar::find_constant(std::string_view name) const {
  for (std::size_t i = 0; i < constants.size(); ++i)
    if (constants[i].name == name) return static_cast<std::uint32_t>(i);
  return std::nullopt;
}

}  // namespace vern
