// infer and InferResult::save: inference behind the public API.
#include "vernacular/infer.hpp"

#include <algorithm>

#include "api/api_data.hpp"
#include "graph/reserved_words.hpp"
#include "graph/writer.hpp"
#include "inverse/infer.hpp"
#include "inverse/write/inferred_files.hpp"
#include "inverse/write/test_buildings.hpp"

namespace vernacular {

InferResult infer(const std::vector<Example>& examples, const InferOptions& options) {
  return detail::guarded([&] {
    if (examples.empty())
      vern::fail(vern::ErrorKind::Usage, "", {}, "no examples given", "read some with read_examples()");
    if (!vern::is_rule_label(options.start))
      vern::fail(vern::ErrorKind::Usage, "", {}, "the start label '" + options.start + "' cannot be a rule's",
                 "a label is a letter or '_' followed by letters, digits and '_', and not an operation word such "
                 "as split");
    if (!(options.tolerance >= 0))
      vern::fail(vern::ErrorKind::Usage, "", {}, "the tolerance must be >= 0", "0 takes the examples' own precision");
    std::vector<vern::Example> internal;
    internal.reserve(examples.size());
    for (const Example& e : examples) internal.push_back(e.data().example);
    const vern::PrimitiveLibrary library = vern::PrimitiveLibrary::builtin();
    vern::InferOptions o;
    o.tolerance = options.tolerance;
    o.start = options.start;
    o.uniform_distributions = options.uniform_distributions;
    o.joint_sizes = options.joint_sizes;
    o.twin_rules = options.twin_rules;
    o.stack = options.stack;
    o.threads = options.threads;
    o.primitives = &library;
    vern::Inference r = vern::infer(internal, o);
    InferResult out;
    out.tolerance = r.tolerance;
    out.examples = examples.size();
    out.warnings = std::move(r.warnings);
    if (r.unturned_parts > 0)
      out.warnings.push_back("warning: " + std::to_string(r.unturned_parts) +
                             " parts whose mesh is not their label's turned by quarter turns: written unturned");
    // A grammar that cannot derive is a bug, better found here than by the
    // user: derive a few buildings (as infer does) and pass on what they say.
    std::size_t parts = 0, largest = 0;
    for (const vern::Example& e : internal) {
      parts += e.boxes.size();
      largest = std::max(largest, e.boxes.size());
    }
    const vern::TestBuildingsOptions tests = vern::test_buildings_for(parts, largest, 1);
    for (std::string& w : vern::derive_test_buildings(r.grammar, tests)) out.warnings.push_back(std::move(w));
    auto data = std::make_shared<detail::GrammarData>();
    data->grammar = std::move(r.grammar);
    data->meshes = std::move(r.primitives);
    out.grammar = Grammar(std::move(data));
    return out;
  });
}

void InferResult::save(const std::filesystem::path& file) const {
  detail::guarded([&] {
    if (file.extension() != ".grm")
      vern::fail(vern::ErrorKind::Usage, file.string(), {}, "an inferred grammar is saved as a .grm file",
                 "name it STYLE.grm: its meshes go beside it as STYLE.prims.obj");
    const std::filesystem::path meshes = vern::meshes_path_for(file);
    vern::Grammar g = grammar.data().grammar;
    g.primitives = vern::path_from(file, meshes);
    const vern::PrimitiveLibrary none = vern::PrimitiveLibrary::builtin();
    const auto& own = grammar.data().meshes;
    vern::write_inferred(own ? *own : none, vern::inferred_header(examples, tolerance, file), vern::write_grammar(g),
                         file, meshes);
  });
}

}  // namespace vernacular
