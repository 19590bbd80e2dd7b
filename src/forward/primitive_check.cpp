#include "forward/primitive_check.hpp"

#include "base/suggest.hpp"

namespace vern {

namespace {

// Past this many unknown names the primitives are missing, not misspelt:
// each further warning lists the known ones instead of comparing its name
// with every one of them (the product of the two counts: 20,000 names
// against a library of as many took 10 s).
constexpr std::size_t kSuggested = 100;

}  // namespace

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
                                      "unknown primitive '" + shown_name(name) + "': inserting a box labelled '" +
                                          shown_name(name) + "'; " +
                                          (warnings.size() < kSuggested ? suggest(name, known, "the known primitives")
                                                                        : listed(known, "the known primitives"))));
  }
  return warnings;
}

}  // namespace vern
