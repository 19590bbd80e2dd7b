// Infers the garage's style through the installed public API, then checks
// the examples, derives and writes variants, and reads a broken grammar.
// Usage: consumer EXAMPLES_FOLDER OUT_FOLDER. Exit 0 when all went as it
// should, 1 (saying what) when not.
#include <cstdio>
#include <filesystem>
#include <vernacular/vernacular.hpp>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: consumer EXAMPLES_FOLDER OUT_FOLDER\n");
    return 2;
  }
  const fs::path out = argv[2];
  try {
    const std::vector<vernacular::Example> examples = vernacular::read_examples({argv[1]});
    const vernacular::InferResult style = vernacular::infer(examples);
    style.save(out / "garage.grm");
    // The saved grammar, read back, derives every example.
    const vernacular::Grammar grammar = vernacular::Grammar::read(out / "garage.grm");
    for (const vernacular::Example& e : examples) {
      const vernacular::Verdict v = vernacular::check(grammar, e);
      if (!v.derivable) {
        std::fprintf(stderr, "%s: not derivable: %s\n", e.source().c_str(), v.reason.c_str());
        return 1;
      }
    }
    const std::vector<vernacular::Building> variants = vernacular::derive_many(grammar, 5);
    for (const vernacular::Building& b : variants)
      if (b.parts.empty()) {
        std::fprintf(stderr, "a variant without parts\n");
        return 1;
      }
    vernacular::write_buildings(variants, grammar, out / "variants.glb");
    std::printf("vernacular %s: %zu examples -> %zu rules; %zu examples derivable; %zu variants written\n",
                vernacular::version(), examples.size(), grammar.rule_count(), examples.size(), variants.size());
  } catch (const vernacular::Failure& f) {
    std::fprintf(stderr, "unexpected failure (%s): %s\n", vernacular::to_string(f.error().kind), f.what());
    return 1;
  }
  // A broken grammar: an error value that says where.
  try {
    vernacular::Grammar::parse("house --> split(x){ 1 : wall | }\n", "broken.grm");
    std::fprintf(stderr, "a broken grammar was read\n");
    return 1;
  } catch (const vernacular::Failure& f) {
    const vernacular::Error& e = f.error();
    if (e.kind != vernacular::ErrorKind::Input || e.location.file != "broken.grm" || e.location.line != 1 ||
        e.location.column == 0 || e.message.empty()) {
      std::fprintf(stderr, "the broken grammar's error is not located: %s\n", f.what());
      return 1;
    }
    std::printf("broken grammar: %s\n", f.what());
  }
  return 0;
}
