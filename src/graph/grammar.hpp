// The operation graph: rules, constants and the node arena they share.
//
// Both directions meet here (DESIGN.md). The reader builds a Grammar from
// text, inference builds one from examples, derivation runs one, and the
// writer prints one. A rule is a label, its parameter names and one body
// node; several alternatives of a label are one Choose body.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "graph/name_index.hpp"
#include "graph/node.hpp"

namespace vern {

// name = value, evaluated once per derivation, in file order; a constant
// may use the ones before it.
struct Constant {
  std::string name;
  Expr value;
  SourceLoc loc;
};

struct Rule {
  std::string label;
  std::vector<std::string> params;
  NodeId body = 0;
  SourceLoc loc;
};

class Grammar {
 public:
  // Where the text came from, for messages ("" when built in memory).
  std::string source_name;

  // @start: the start rule. When no @start was written, the first rule.
  RuleId start_rule = 0;
  bool start_written = false;
  // @scope x, y, z: the default start-scope size (empty Exprs: not given).
  std::array<Expr, 3> scope;
  // @primitives "path": as written, relative to the grammar file.
  std::string primitives;

  std::vector<Constant> constants;
  std::vector<Rule> rules;

  // Room for this many nodes without moving the arena: a large graph built
  // in one go (inference) then neither copies its nodes as the arena grows
  // nor holds two arenas at once. Only address space until nodes arrive.
  void reserve(std::size_t nodes);

  // Appends a node; no sharing (each keeps its own source location).
  NodeId add(Node node);
  // Returns an existing node equal to this one (same operation, same child
  // ids) or adds it: bottom-up hash-consing, so equal subgraphs built from
  // interned children share one id.
  NodeId intern(Node node);

  const Node& node(NodeId id) const { return nodes_[id]; }
  const Operation& op(NodeId id) const { return nodes_[id].op; }
  std::size_t node_count() const { return nodes_.size(); }

  // Primitive names are interned so terminals carry a small id.
  LabelId label_id(std::string_view name);
  std::optional<LabelId> find_label(std::string_view name) const;
  const std::string& label(LabelId id) const { return labels_[id]; }
  const std::vector<std::string>& labels() const { return labels_; }

  // Both read every rule or constant: for one look-up, not one per name
  // in a text (the parser keeps its own index, name_index.hpp).
  std::optional<RuleId> find_rule(std::string_view label) const;
  std::optional<std::uint32_t> find_constant(std::string_view name) const;

 private:
  // The interned nodes by hash: open addressing with linear probing in
  // one flat array (a node-based map was a third of interning's time and
  // 40 bytes a node). A slot holds the hash's low 32 bits and the node.
  struct InternSlot {
    std::uint32_t hash = 0;
    NodeId node = kEmptySlot;
  };
  static constexpr NodeId kEmptySlot = ~NodeId{0};
  void grow_intern_table();
  void rehash(std::size_t slots);  // a power of two, more than twice the nodes interned

  std::vector<Node> nodes_;
  std::vector<std::string> labels_;
  NameIndex<LabelId> label_ids_;  // labels_ by name
  std::vector<InternSlot> interned_;  // size a power of two, at most half full
  std::size_t interned_count_ = 0;
};

}  // namespace vern
