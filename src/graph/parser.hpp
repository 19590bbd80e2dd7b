// Reading grammar text into an operation graph.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "graph/grammar.hpp"

namespace vern {

// Parses a whole grammar. Names are resolved here: calls to rules (defined
// anywhere in the file), parameters, constants (a constant may use only the
// ones defined before it), functions. Throws vern::Error (Input) at the
// first problem, naming source_name:line:col, what was expected and what to
// do. Every node and expression keeps its source location.
Grammar parse_grammar(std::string_view text, const std::string& source_name = "");

// Reads and parses a grammar file (Io error if it cannot be read).
Grammar read_grammar_file(const std::filesystem::path& path);

// The named colours colour(name) accepts, as 0..1 components.
bool find_named_colour(std::string_view name, double rgb[3]);

}  // namespace vern
