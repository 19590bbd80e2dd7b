#include "inverse/rule_naming.hpp"

#include <cctype>
#include <functional>
#include <set>
#include <unordered_map>

#include "graph/overload.hpp"
#include "graph/reserved_words.hpp"

namespace vern {

namespace {

class RuleMaker {
 public:
  RuleMaker(const Grammar& from, const NamingOptions& o) : from_(from), opt_(o) {
    out_.scope = from.scope;
    out_.primitives = from.primitives;
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
    for (NodeId child : node_children(from_.op(id))) count_uses(child);
  }

  bool is_leaf(NodeId id) const {
    const Operation& op = from_.op(id);
    return std::holds_alternative<Primitive>(op) || std::holds_alternative<Nil>(op) ||
           std::holds_alternative<Colour>(op);
  }

  bool needs_rule(NodeId id) const {
    if (std::holds_alternative<Choose>(from_.op(id))) return true;
    return !is_leaf(id) && uses_.at(id) > 1;
  }

  // The primitive labels beneath a node, in order of first appearance.
  void labels_below(NodeId id, std::vector<std::string>& out, std::set<NodeId>& seen) const {
    if (!seen.insert(id).second || out.size() >= 3) return;
    if (const auto* p = std::get_if<Primitive>(&from_.op(id))) {
      const std::string& l = from_.label(p->label);
      if (std::find(out.begin(), out.end(), l) == out.end()) out.push_back(l);
      return;
    }
    for (NodeId child : node_children(from_.op(id))) labels_below(child, out, seen);
  }

  static std::string word(const std::string& label, bool first) {
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

  std::string suffix(NodeId id) const {
    auto axis_letter = [](const Expr& e) -> std::string {
      const ExprNode& n = e.node(e.root());
      return n.kind == ExprKind::Axis ? std::string(1, static_cast<char>('X' + n.op)) : std::string();
    };
    return std::visit(Overload{
                          [&](const Split& s) { return axis_letter(s.axis); },
                          [&](const RepeatN& r) { return "Row" + axis_letter(r.axis); },
                          [&](const Repeat& r) { return "Row" + axis_letter(r.axis); },
                          [&](const Choose&) { return std::string("Choice"); },
                          [&](const Rotate&) { return std::string("Turned"); },
                          [&](const auto&) { return std::string("Part"); },
                      },
                      from_.op(id));
  }

  std::string name_for(NodeId id) {
    std::vector<std::string> labels;
    std::set<NodeId> seen;
    labels_below(id, labels, seen);
    std::string base;
    for (std::size_t i = 0; i < labels.size(); ++i) base += word(labels[i], i == 0);
    if (base.empty() || !std::isalpha(static_cast<unsigned char>(base[0]))) base = "empty" + base;
    base += suffix(id);
    return unique(base);
  }

  std::string unique(const std::string& base) {
    std::string name = base;
    for (int n = 2; taken_.count(name) || is_operation_word(name); ++n) name = base + std::to_string(n);
    taken_.insert(name);
    return name;
  }

  RuleId rule_for(NodeId id, const std::string& forced_name = {}) {
    if (auto it = rules_.find(id); it != rules_.end()) return it->second;
    const auto rule = static_cast<RuleId>(out_.rules.size());
    out_.rules.push_back({forced_name.empty() ? name_for(id) : unique(forced_name), {}, 0, {}});
    rules_.emplace(id, rule);
    pending_.emplace_back(rule, id);
    return rule;
  }

  // Copies a node; children that are rules become calls.
  NodeId copy(NodeId id, bool as_body) {
    if (!as_body && needs_rule(id)) return out_.intern({Call{rule_for(id), {}}, {}});
    Operation op = from_.op(id);
    std::visit(Overload{
                   [&](Split& s) {
                     for (auto& p : s.parts) p.child = copy(p.child, false);
                   },
                   [&](Repeat& r) { r.child = copy(r.child, false); },
                   [&](RepeatN& r) { r.child = copy(r.child, false); },
                   [&](Choose& c) {
                     for (auto& o : c.options) o.child = copy(o.child, false);
                   },
                   [&](Primitive& p) { p.label = out_.label_id(from_.label(p.label)); },
                   [&](Translate& t) { t.child = copy(t.child, false); },
                   [&](Scale& s) { s.child = copy(s.child, false); },
                   [&](Rotate& r) { r.child = copy(r.child, false); },
                   [&](Comp& c) {
                     for (auto& p : c.parts) p.child = copy(p.child, false);
                   },
                   [&](Call&) { throw Error(ErrorKind::Internal, "rules_for: the graph already calls rules"); },
                   [](auto&) {},
               },
               op);
    // A choose that is not a rule's body must be one: handled by needs_rule.
    return out_.intern({std::move(op), {}});
  }

  const Grammar& from_;
  const NamingOptions& opt_;
  Grammar out_;
  std::unordered_map<NodeId, int> uses_;
  std::unordered_map<NodeId, RuleId> rules_;
  std::vector<std::pair<RuleId, NodeId>> pending_;
  std::set<std::string> taken_;
};

}  // namespace

Grammar rules_for(const Grammar& graph, NodeId root, const NamingOptions& options) {
  return RuleMaker(graph, options).run(root);
}

}  // namespace vern
