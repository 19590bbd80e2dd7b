#include "serve/session.hpp"

#include "base/error.hpp"
#include "base/input_file.hpp"
#include "forward/primitive_sources.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/infer.hpp"
#include "inverse/load/examples_of_files.hpp"

namespace vern {

namespace fs = std::filesystem;

ServeSession open_session(const std::vector<std::string>& args, const ExampleLimits& limits,
                          const std::vector<std::string>& stack) {
  ServeSession session;
  session.stack = stack;
  std::vector<std::string> example_args;
  for (const std::string& a : args) {
    if (fs::path(a).extension() == ".grm") {
      if (session.grammar_file)
        throw Error(ErrorKind::Usage, "serve: error: two grammars given (" + session.grammar_file->string() + ", " + a +
                                          ")\n  hint: serve one grammar at a time, with its examples if you like");
      session.grammar_file = a;
    } else {
      example_args.push_back(a);
    }
  }
  if (!session.grammar_file && example_args.empty())
    throw Error(ErrorKind::Usage, "serve: error: nothing to serve\n  hint: serve style.grm, serve examples/, or both");
  if (!example_args.empty()) {
    for (const fs::path& file : example_files(example_args)) session.examples.push_back(load_example(file, limits));
    std::vector<std::string> notes;
    session.examples = examples_of_files(std::move(session.examples), BuildingsMode::Apart, limits.tolerance, notes);
  }
  if (session.grammar_file) {
    session.grammar_name = session.grammar_file->filename().string();
    std::vector<unsigned char> bytes;
    if (const std::optional<ReadRefusal> refused = read_regular_file(*session.grammar_file, 64 << 20, bytes))
      throw Error(refused->kind, session.grammar_file->string() + ": error: the grammar " + refused->problem);
    session.grammar_text.assign(bytes.begin(), bytes.end());
    const Grammar grammar = parse_grammar(session.grammar_text, session.grammar_file->string());
    session.primitives = primitives_for(grammar, *session.grammar_file, std::nullopt, false);
    return session;
  }
  // Examples alone: their grammar, as infer writes it, is the one edited.
  InferOptions options;
  options.tolerance = limits.tolerance;
  options.stack = stack;
  options.primitives = &session.primitives;
  Inference inferred = infer(session.examples, options);
  session.grammar_name = "inferred.grm";
  session.grammar_text = write_grammar(inferred.grammar);
  session.primitives = std::move(inferred.primitives);
  return session;
}

}  // namespace vern
