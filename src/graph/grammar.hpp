// The operation graph: rules, constants and the node arena they share.
//
// Both directions meet here (docs/inference.md). The reader builds a Grammar from
// text, inference builds one from examples, derivation runs one, and the
// writer prints one. A rule is a label, its parameter names and one body
// node; several alternatives of a label are one Choose body.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/name_index.hpp"
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
  // @primitives "path": as written, relative to the grammar file, and where
  // (for messages about the file it names).
  std::string primitives;
  SourceLoc primitives_loc;

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

  // What the grammar held at one moment, to go back to: the arena only
  // grows and its nodes never change, so the nodes are kept as a count
  // and the rest (rules, constants, headers: small) as a copy. Inference
  // keeps one of its unmerged graph to merge again (a copy of every node
  // cost a tenth of a second per million parts, and their memory).
  struct Checkpoint;
  Checkpoint checkpoint() const;
  // Forgets every node, label, rule and constant added since (ids taken
  // since are free again) and restores the headers: node ids below the
  // checkpoint's count, and what intern() returns for their operations,
  // are as they were.
  void rollback(const Checkpoint& c);

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
  // Everything but the arena and the labels: what a checkpoint copies.
  void copy_headers(const Grammar& from);

  std::vector<Node> nodes_;
  std::vector<std::string> labels_;
  NameIndex<LabelId> label_ids_;  // labels_ by name
  std::vector<InternSlot> interned_;  // size a power of two, at most half full
  std::size_t interned_count_ = 0;
};

struct Grammar::Checkpoint {
  std::size_t nodes = 0, labels = 0;
  Grammar headers;  // rules, constants, @start, @scope, ...: no nodes
};

}  // namespace vern
