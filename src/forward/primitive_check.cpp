#include "forward/primitive_check.hpp"

#include "graph/suggest.hpp"

namespace vern {

std::vector<std::string> unknown_primitive_warnings(const Grammar& grammar, const PrimitiveLibrary& library) {
  std::vector<std::string> warnings;
  std::vector<bool> reported(grammar.labels().size(), false);
  const std::vector<std::string> known = library.names();
  for (NodeId id = 0; id < grammar.node_count(); ++id) {
    const auto* p = std::get_if<Primitive>(&grammar.op(id));
    if (!p || reported[p->label]) continue;
    reported[p->label] = true;
    const std::string& name = grammar.label(p->label);
    if (library.find(name)) continue;
    warnings.push_back(format_warning(grammar.source_name, grammar.node(id).loc,
                                      "unknown primitive '" + name + "': inserting a box labelled '" + name + "'; " +
                                          suggest(name, known, "the known primitives")));
  }
  return warnings;
}

}  // namespace vern
