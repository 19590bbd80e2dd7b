#include "graph/grammar.hpp"

#include <algorithm>

#include "graph/structural.hpp"

namespace vern {

NodeId Grammar::add(Node node) {
  nodes_.push_back(std::move(node));
  return static_cast<NodeId>(nodes_.size() - 1);
}

NodeId Grammar::intern(Node node) {
  if (2 * (interned_count_ + 1) > interned_.size()) grow_intern_table();
  // Fibonacci hashing: the high bits of the product mix all the hash's bits.
  const auto h = static_cast<std::uint32_t>((shallow_hash(node.op) * 0x9e3779b97f4a7c15ULL) >> 32);
  const std::size_t mask = interned_.size() - 1;
  std::size_t i = h & mask;
  for (; interned_[i].node != kEmptySlot; i = (i + 1) & mask)
    if (interned_[i].hash == h && nodes_[interned_[i].node].op == node.op) return interned_[i].node;
  const NodeId id = add(std::move(node));
  interned_[i] = {h, id};
  ++interned_count_;
  return id;
}

void Grammar::reserve(std::size_t nodes) {
  nodes_.reserve(nodes);
  std::size_t slots = std::max<std::size_t>(64, interned_.size());
  while (slots < 2 * nodes) slots *= 2;
  if (slots > interned_.size()) rehash(slots);  // once, not once per doubling
}

void Grammar::grow_intern_table() { rehash(std::max<std::size_t>(64, 2 * interned_.size())); }

void Grammar::rehash(std::size_t slots) {
  std::vector<InternSlot> old(slots);
  old.swap(interned_);
  const std::size_t mask = interned_.size() - 1;
  for (const InternSlot& s : old) {
    if (s.node == kEmptySlot) continue;
    std::size_t i = s.hash & mask;
    while (interned_[i].node != kEmptySlot) i = (i + 1) & mask;
    interned_[i] = s;
  }
}

void Grammar::copy_headers(const Grammar& from) {
  source_name = from.source_name;
  start_rule = from.start_rule;
  start_written = from.start_written;
  scope = from.scope;
  primitives = from.primitives;
  primitives_loc = from.primitives_loc;
  constants = from.constants;
  rules = from.rules;
}

Grammar::Checkpoint Grammar::checkpoint() const {
  Checkpoint c{nodes_.size(), labels_.size(), {}};
  c.headers.copy_headers(*this);
  return c;
}

void Grammar::rollback(const Checkpoint& c) {
  if (c.nodes < nodes_.size()) {
    nodes_.erase(nodes_.begin() + static_cast<std::ptrdiff_t>(c.nodes), nodes_.end());
    // Slots of forgotten nodes cannot simply be emptied (a probe would stop
    // short of entries placed after them): the table is refilled, same size.
    std::vector<InternSlot> kept(interned_.size());
    kept.swap(interned_);
    interned_count_ = 0;
    const std::size_t mask = interned_.size() - 1;
    for (const InternSlot& slot : kept) {
      if (slot.node == kEmptySlot || slot.node >= c.nodes) continue;
      std::size_t i = slot.hash & mask;
      while (interned_[i].node != kEmptySlot) i = (i + 1) & mask;
      interned_[i] = slot;
      ++interned_count_;
    }
  }
  if (c.labels < labels_.size()) {
    labels_.resize(c.labels);
    label_ids_.clear();
    for (std::size_t k = 0; k < labels_.size(); ++k) label_ids_.add(labels_[k], static_cast<LabelId>(k));
  }
  copy_headers(c.headers);
}

LabelId Grammar::label_id(std::string_view name) {
  if (auto found = find_label(name)) return *found;
  const auto id = static_cast<LabelId>(labels_.size());
  labels_.emplace_back(name);
  label_ids_.add(name, id);
  return id;
}

std::optional<LabelId> Grammar::find_label(std::string_view name) const { return label_ids_.find(name); }

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
