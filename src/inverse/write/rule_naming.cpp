#include "inverse/write/rule_naming.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <unordered_map>
#include <unordered_set>

#include "base/overload.hpp"
#include "graph/reserved_words.hpp"

namespace vern {

namespace {

// A label as one word of a camel-case name: "right_angle" -> "RightAngle"
// (first: "rightAngle").
std::string word(const std::string& label, bool first) {
  std::string w;
  bool upper = !first;
  for (char c : label) {
    if (!std::isalnum(static_cast<unsigned char>(c))) {
      upper = true;
      continue;
    }
    w += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return w;
}

// What the node does, after its labels: Z for split(z), RowX, Choice, ...
std::string suffix(const Grammar& g, NodeId id) {
  auto axis_letter = [](const Expr& e) -> std::string {
    const ExprNode& n = e.node(e.root());
    return n.kind == ExprKind::Axis ? std::string(1, static_cast<char>('X' + n.op)) : std::string();
  };
  return std::visit(Overload{
                        // An axis given by a parameter (twin_rules.hpp): no letter.
                        [&](const Split& s) {
                          const std::string a = axis_letter(s.axis);
                          return a.empty() ? std::string("Split") : a;
                        },
                        [&](const RepeatN& r) { return "Row" + axis_letter(r.axis); },
                        [&](const Repeat& r) { return "Row" + axis_letter(r.axis); },
                        [&](const Choose&) { return std::string("Choice"); },
                        [&](const Rotate&) { return std::string("Turned"); },
                        [&](const auto&) { return std::string("Part"); },
                    },
                    g.op(id));
}

// The labels' words and the node's suffix (kind, where given, in its
// place): rectRoofZ.
std::string base_name(const Grammar& g, const std::vector<LabelId>& labels, NodeId id, const std::string& kind) {
  std::string base;
  for (std::size_t i = 0; i < labels.size(); ++i) base += word(g.label(labels[i]), i == 0);
  if (base.empty() || !std::isalpha(static_cast<unsigned char>(base[0]))) base = "empty" + base;
  return base + (kind.empty() ? suffix(g, id) : kind);
}

class RuleMaker {
 public:
  RuleMaker(const Grammar& from, const NamingOptions& o)
      : from_(from), opt_(o), uses_(from.node_count(), 0), rules_(from.node_count(), kNone),
        leaf_copies_(from.node_count(), kNone), labels_(from.node_count()) {
    out_.scope = from.scope;
    out_.primitives = from.primitives;
    // The copy has at most the graph's nodes and a call per rule: room for
    // them up front, so the copy's arena is never moved as it grows.
    out_.reserve(from.node_count() + from.node_count() / 8);
  }

  Grammar run(NodeId root) {
    count_uses(root);
    uses_[root] = 2;  // the root is always a rule
    RuleId start = rule_for(root, opt_.start);
    out_.start_rule = start;
    // Rules are filled in discovery order; bodies may discover more.
    for (std::size_t i = 0; i < pending_.size(); ++i) {
      const auto [rule, node] = pending_[i];
      out_.rules[rule].body = copy(node, /*as_body=*/true);
    }
    return std::move(out_);
  }

 private:
  void count_uses(NodeId id) {
    if (uses_[id]++ > 0) return;
    // A recursive rule inference made (self_nesting.hpp): its body is
    // reached through the call.
    if (const auto* call = std::get_if<Call>(&from_.op(id))) count_uses(from_.rules[call->rule].body);
    for_each_child(from_.op(id), [&](NodeId child) { count_uses(child); });
  }

  bool is_leaf(NodeId id) const {
    const Operation& op = from_.op(id);
    return std::holds_alternative<Primitive>(op) || std::holds_alternative<Nil>(op) ||
           std::holds_alternative<Colour>(op);
  }

  bool needs_rule(NodeId id) const {
    if (std::holds_alternative<Choose>(from_.op(id))) return true;
    return !is_leaf(id) && uses_[id] > 1;
  }

  // The first three primitive labels beneath a node, in order of first
  // appearance (depth first). Kept per node: a rule's name would otherwise
  // search its whole subgraph when it holds fewer than three labels, every
  // rule again. A node's list is its children's lists run together, since
  // a label past a child's third comes after three distinct ones.
  const std::vector<LabelId>& labels_below(NodeId id) {
    Labels& known = labels_[id];  // labels_ never grows: the reference stays valid
    if (known.done) return known.labels;
    if (const auto* p = std::get_if<Primitive>(&from_.op(id))) {
      known.labels.push_back(p->label);
    } else {
      for_each_child(from_.op(id), [&](NodeId child) {
        if (known.labels.size() >= 3) return;  // the rest cannot add one
        for (LabelId l : labels_below(child))
          if (known.labels.size() < 3 && std::find(known.labels.begin(), known.labels.end(), l) == known.labels.end())
            known.labels.push_back(l);
      });
    }
    known.done = true;
    return known.labels;
  }

  std::string name_for(NodeId id, const std::string& kind = {}) {
    return unique(base_name(from_, labels_below(id), id, kind));
  }

  // base, else base2, base3, ...: the first name not taken. Each base
  // remembers where its search stopped (names are never given back), so a
  // thousand rules of one base cost a thousand tries, not half a million.
  std::string unique(const std::string& base) {
    auto [it, fresh] = next_suffix_.try_emplace(base, 2);
    int& n = it->second;
    std::string name = fresh ? base : base + std::to_string(n++);
    while (taken_.count(name) || is_operation_word(name)) name = base + std::to_string(n++);
    taken_.insert(name);
    return name;
  }

  // suffix, where given, names the rule's kind in place of its operation's.
  RuleId rule_for(NodeId id, const std::string& forced_name = {}, const std::string& suffix = {}) {
    if (rules_[id] != kNone) return rules_[id];
    const auto rule = static_cast<RuleId>(out_.rules.size());
    out_.rules.push_back({forced_name.empty() ? name_for(id, suffix) : unique(forced_name), {}, 0, {}});
    rules_[id] = rule;
    pending_.emplace_back(rule, id);
    return rule;
  }

  // Copies a node; children that are rules become calls. A leaf is copied
  // once, however often it is used. `depth`: how deep the node sits in the
  // rule body being written; a node at kMaxBodyDepth becomes a rule of its
  // own, so that no body nests deeper than the grammar reader accepts
  // (graph/parser.cpp reads operations nested at most 256 deep) however
  // deep an example's cuts go, and no body is too deep to read.
  NodeId copy(NodeId id, bool as_body, int depth = 0) {
    if (const auto* call = std::get_if<Call>(&from_.op(id))) {
      // A recursion that counts its levels (self_nesting.hpp) keeps its
      // parameters: its body reads them.
      const Rule& called = from_.rules[call->rule];
      const RuleId made = rule_for(called.body, "", "Nest");
      out_.rules[made].params = called.params;
      return out_.intern({Call{made, call->args}, {}});
    }
    if (!as_body && (needs_rule(id) || (depth >= kMaxBodyDepth && !is_leaf(id))))
      return out_.intern({Call{rule_for(id), {}}, {}});
    if (leaf_copies_[id] != kNone) return leaf_copies_[id];
    Operation op = from_.op(id);
    const auto child = [&](NodeId c) { return copy(c, false, depth + 1); };
    std::visit(Overload{
                   [&](Split& s) {
                     for (auto& p : s.parts) p.child = child(p.child);
                   },
                   [&](Repeat& r) { r.child = child(r.child); },
                   [&](RepeatN& r) { r.child = child(r.child); },
                   [&](Choose& c) {
                     for (auto& o : c.options) o.child = child(o.child);
                   },
                   [&](Primitive& p) { p.label = out_.label_id(from_.label(p.label)); },
                   [&](Translate& t) { t.child = child(t.child); },
                   [&](Scale& s) { s.child = child(s.child); },
                   [&](Rotate& r) { r.child = child(r.child); },
                   [&](Comp& c) {
                     for (auto& p : c.parts) p.child = child(p.child);
                   },
                   [](auto&) {},
               },
               op);
    // A choose that is not a rule's body must be one: handled by needs_rule.
    const NodeId out = out_.intern({std::move(op), {}});
    if (is_leaf(id)) leaf_copies_[id] = out;
    return out;
  }

  static constexpr std::uint32_t kNone = static_cast<std::uint32_t>(-1);
  // Far below the reader's 256, leaving room for the sizes' expressions
  // and for what later steps wrap around a body (a choice, a turn); and
  // deeper than any grammar a person reads comfortably.
  static constexpr int kMaxBodyDepth = 48;

  struct Labels {
    std::vector<LabelId> labels;  // at most three
    bool done = false;
  };

  const Grammar& from_;
  const NamingOptions& opt_;
  Grammar out_;
  std::vector<int> uses_;          // by node id
  std::vector<RuleId> rules_;      // by node id: its rule, or kNone
  std::vector<NodeId> leaf_copies_;  // by node id: a leaf's copy in out_, or kNone
  std::vector<Labels> labels_;     // by node id: see labels_below
  std::vector<std::pair<RuleId, NodeId>> pending_;
  std::unordered_set<std::string> taken_;
  std::unordered_map<std::string, int> next_suffix_;  // base -> the suffix to try next
};

}  // namespace

Grammar rules_for(const Grammar& graph, NodeId root, const NamingOptions& options) {
  return RuleMaker(graph, options).run(root);
}

std::string node_name(const Grammar& g, NodeId id) {
  // The first three labels depth first, through the rules it calls.
  std::vector<LabelId> labels;
  std::vector<NodeId> stack{id};
  std::unordered_set<NodeId> seen;
  while (!stack.empty() && labels.size() < 3) {
    const NodeId n = stack.back();
    stack.pop_back();
    if (!seen.insert(n).second) continue;
    const Operation& op = g.op(n);
    if (const auto* p = std::get_if<Primitive>(&op)) {
      if (std::find(labels.begin(), labels.end(), p->label) == labels.end()) labels.push_back(p->label);
      continue;
    }
    if (const auto* c = std::get_if<Call>(&op)) stack.push_back(g.rules[c->rule].body);
    std::vector<NodeId> children;
    for_each_child(op, [&](NodeId child) { children.push_back(child); });
    stack.insert(stack.end(), children.rbegin(), children.rend());
  }
  return base_name(g, labels, id, {});
}

std::string free_label(const Grammar& g, const std::string& base) {
  std::string label = base;
  for (int k = 2; g.find_rule(label) || is_operation_word(label); ++k) label = base + std::to_string(k);
  return label;
}

}  // namespace vern
