// What `serve` shows: a grammar (from a file, or inferred from examples
// when it starts) and the examples, read once when it starts.
//
// The editor changes the grammar's text in the browser; the server never
// writes the file (every file a run reads is an input): the page offers the
// text to save where the user wants.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "forward/derive.hpp"
#include "forward/primitive_library.hpp"
#include "inverse/load/example.hpp"

namespace vern {

struct ServeSession {
  std::string grammar_name;  // the file's name, or "inferred.grm"
  std::string grammar_text;  // as the editor starts with it
  std::optional<std::filesystem::path> grammar_file;
  std::vector<Example> examples;
  // Meshes the grammar's labels insert: built-ins, the grammar file's
  // @primitives, or the examples' own parts' (inferred).
  PrimitiveLibrary primitives = PrimitiveLibrary::builtin();
  // Each derivation stops here: a runaway grammar typed in the editor is
  // an error shown at its line, the server goes on.
  DeriveLimits limits{200, 200'000, 20'000'000};
  // Parts an answer holds at most: past them the buildings that reach it,
  // and a note (a browser draws a few hundred thousand at a time).
  std::uint64_t most_parts = 300'000;
  // The inference view's check of each example: within this many steps
  // (check's own default is ten million; a page asks again at each edit).
  std::uint64_t check_steps = 1'000'000;
  // The painting order of overlapping parts (serve --stack, as infer's).
  std::vector<std::string> stack;
};

// The session of `serve ARGS...`: at most one .grm file, and example files
// or folders (infer's), whose overlapping parts are painted in `stack`'s
// order. With examples and no grammar, the grammar is inferred from them.
// Throws vern::Error (Usage) for two grammars or nothing given, and as
// infer and the grammar reader do.
ServeSession open_session(const std::vector<std::string>& args, const ExampleLimits& limits,
                          const std::vector<std::string>& stack = {});

}  // namespace vern
