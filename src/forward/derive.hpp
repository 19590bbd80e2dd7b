// Deriving buildings: running an operation graph on a start scope.
//
// derive() is a pure function of (grammar, options): same grammar, scope and
// seed give the same terminals, bit for bit, on any thread. Limits stop
// runaway grammars with an error that names the limit, the flag that raises
// it and the chain of rules that reached it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "forward/terminal.hpp"
#include "graph/grammar.hpp"

namespace vern {

struct DeriveLimits {
  std::uint32_t max_depth = 1000;            // nested rule calls (--max-depth)
  // Terminals per derivation (--max-terminals). Each takes 144 bytes, twice
  // while the derivation hands them over: a million are some 300 MB per
  // building being derived (measured: generate to OBJ or GLB peaks at
  // 287 MB); the writers hold a bounded amount on top.
  std::uint64_t max_terminals = 1'000'000;
  std::uint64_t max_operations = 200'000'000;  // operations run, tiles included (--max-operations)
};

struct DeriveOptions {
  std::uint64_t seed = 0;
  DeriveLimits limits;
  // --strict: a label none of whose rules applies is an error, not nil.
  bool strict = false;
  // The start scope's size; when absent, the grammar's @scope, else
  // default_size. The start scope sits at the origin, axis-aligned.
  std::optional<glm::dvec3> size;
  glm::dvec3 default_size{10.0, 10.0, 10.0};
  // false: each terminal is counted (max_terminals holds) and dropped, and
  // the Derivation has none: for checking that a grammar derives (infer's
  // test building) without holding a building's terminals (a million are
  // 144 MB, plus their copy).
  bool keep_terminals = true;
  // Record what made each terminal (Derivation::traces): for an editor
  // that shows a part's rules. Off, it costs one branch a terminal.
  bool trace = false;
};

// What made one terminal: the operation that inserted it and the rules it
// was derived through, outermost first, as errors spell them with their
// arguments ("building > floor(2) > bay(1.5)").
struct TerminalTrace {
  SourceLoc at;                // the I(...) or colour(...) that inserted it
  std::vector<RuleId> rules;   // the rule of each call, outermost first (an alternative is a rule of its own)
  std::string chain;           // those calls with their arguments' values
  // Each split part and repeat tile it lies in, outermost first: the
  // operation, which part or tile, along which axis. Parts of one storey
  // share an entry along z, parts of one column one along x.
  struct Step {
    NodeId op = 0;
    std::uint32_t index = 0;
    Axis axis = Axis::X;
    friend bool operator==(const Step&, const Step&) = default;
  };
  std::vector<Step> path;
};

struct Derivation {
  Scope start;
  std::vector<std::string> labels;  // LabelId -> name (the grammar's, plus "rect" for colour())
  std::vector<Terminal> terminals;
  std::vector<std::string> warnings;
  std::vector<TerminalTrace> traces;  // one per terminal with DeriveOptions::trace, else none
};

// Throws vern::Error: Input for evaluation errors (type, division by zero,
// negative sizes), Limit for depth/terminal/operation limits, naming
// file:line:col and the rule chain.
Derivation derive(const Grammar& grammar, const DeriveOptions& options);

// The same with the grammar already compiled (forward/program.hpp), for
// callers that derive it many times.
struct Program;
Derivation derive(const Program& program, const DeriveOptions& options);

// The size of the start scope derive() would give (derivation.start.size),
// without deriving: constants and @scope only. Throws as derive() does for
// errors in those.
glm::dvec3 derive_start_size(const Program& program, const DeriveOptions& options);

}  // namespace vern
