#include "graph/description_length.hpp"

#include <vector>

namespace vern {

std::size_t number_literals(const Expr& e) {
  std::size_t n = 0;
  for (const ExprNode& node : e.nodes()) n += node.kind == ExprKind::Number ? 1 : 0;
  return n;
}

DescriptionLength description_length(const Grammar& grammar) {
  DescriptionLength d;
  d.rules = grammar.rules.size();
  // Rule bodies are trees as written (calls end them), so each node is
  // counted once per place it is written.
  std::vector<NodeId> stack;
  for (const Rule& r : grammar.rules) stack.push_back(r.body);
  while (!stack.empty()) {
    const NodeId id = stack.back();
    stack.pop_back();
    ++d.operations;
    const Operation& op = grammar.op(id);
    for (const Expr* e : node_expressions(op)) d.numbers += number_literals(*e);
    for (const NodeId c : node_children(op)) stack.push_back(c);
  }
  for (const Constant& c : grammar.constants) d.numbers += number_literals(c.value);
  for (const Expr& e : grammar.scope) d.numbers += number_literals(e);
  return d;
}

}  // namespace vern
