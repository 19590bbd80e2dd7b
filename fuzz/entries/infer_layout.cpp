// Example layouts in: inference either refuses them with an Input error
// that names the example, or writes a grammar that reads back the same and
// derives every example exactly (check_example), the oracle docs/inference.md sets
// for inference. A layout of cuts has no overlaps, so inference must not
// refuse it.
#include <sstream>

#include "entries.hpp"
#include "graph/parser.hpp"
#include "graph/structural.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "inverse/load/layered_parts.hpp"
#include "inverse/write/test_buildings.hpp"
#include "layout.hpp"
#include "verdict.hpp"

namespace vern::fuzz {

namespace {

std::string describe(const Layout& layout) {
  std::ostringstream s;
  s.precision(17);
  for (const Example& e : layout.examples) {
    s << e.source << ":\n";
    for (const LabelledBox& b : e.boxes)
      s << "  " << b.object << " [" << b.min.x << ", " << b.min.y << ", " << b.min.z << "] - [" << b.max.x << ", "
        << b.max.y << ", " << b.max.z << "]\n";
  }
  return s.str();
}

// What load_example refuses never reaches infer: no parts, or a part that
// is a single point.
bool loadable(const Example& e) {
  if (e.boxes.empty()) return false;
  const double tolerance = default_tolerance(e);
  for (const LabelledBox& b : e.boxes) {
    const glm::dvec3 size = b.max - b.min;
    if (size.x <= tolerance && size.y <= tolerance && size.z <= tolerance) return false;
  }
  return true;
}

std::string run(const Layout& layout) {
  Inference inferred;
  try {
    inferred = infer(layout.examples, {});
  } catch (const Error& e) {
    if (e.kind() == ErrorKind::Input && layout.valid_by_construction)
      return "inference refuses a layout of cuts: " + std::string(e.what()) + "\n" + describe(layout);
    throw;  // judged() decides
  }

  const std::string text = write_grammar(inferred.grammar);
  const Grammar reread = parse_grammar(text, "inferred.grm");
  if (!equal_grammars(reread, inferred.grammar))
    return "the inferred grammar reads back as a different graph:\n" + excerpt(text) + "\n" + describe(layout);

  for (const Example& laid_out : layout.examples) {
    // Parts set into parts, as check takes them (layered_parts.hpp).
    const Example e = visible_parts(laid_out, Layering{{}, example_tolerance(laid_out, 0)});
    std::vector<LabelledBox> boxes = e.boxes;
    for (LabelledBox& b : boxes) {
      b.min -= e.min;
      b.max -= e.min;
    }
    CheckOptions options;  // the default tolerance, as a user runs check
    options.max_steps = 2'000'000;
    CheckResult r;
    try {
      r = check_example(reread, boxes, example_size(e), options);
    } catch (const Error& err) {
      return "check fails on an inferred grammar: " + std::string(err.what()) + "\n" + excerpt(text) + "\n" +
             describe(layout);
    }
    if (!r.derivable)
      return "the inferred grammar does not derive " + e.source + ": " + r.mismatch + "\n--- grammar:\n" +
             excerpt(text) + "\n--- layout:\n" + describe(layout);
  }

  // As the infer command does before writing (inverse/write/test_buildings.hpp):
  // derivations must run; one that reaches a limit is a warning there, not
  // a failure. A tenth of infer's terminal limit keeps each input quick.
  TestBuildingsOptions tests;
  tests.count = 3;
  tests.limits.max_terminals = 100'000;
  try {
    derive_test_buildings(reread, tests);
  } catch (const Error& err) {
    return "the inferred grammar does not derive: " + std::string(err.what()) + "\n--- grammar:\n" + excerpt(text) +
           "\n--- layout:\n" + describe(layout);
  }
  return "";
}

}  // namespace

std::string infer_layout(Bytes input) {
  const Layout layout = decode_layout(input);
  for (const Example& e : layout.examples)
    if (!loadable(e)) return "";
  // Refusals must name the example file ("layout0.obj: error: ...").
  return judged([&] { return run(layout); }, {ErrorKind::Input}, "layout");
}

}  // namespace vern::fuzz
