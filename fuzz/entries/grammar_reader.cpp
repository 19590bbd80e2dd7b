// Grammar text in: the reader must accept it or say where it is wrong; what
// it accepts, the writer must write so that it reads back the same, and
// both graphs must derive the same building.
#include <cstdint>
#include <cstring>
#include <optional>

#include "entries.hpp"
#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "graph/structural.hpp"
#include "graph/writer.hpp"
#include "verdict.hpp"

namespace vern::fuzz {

namespace {

constexpr const char* kSource = "fuzz.grm";

// Small limits: a fuzzed grammar that recurses or repeats without end must
// stop quickly with a Limit error, not use the fuzzer's time budget.
DeriveOptions small_derivation() {
  DeriveOptions o;
  o.seed = 1;
  o.limits.max_depth = 40;
  o.limits.max_terminals = 2000;
  o.limits.max_operations = 20000;
  return o;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_scope(const Scope& a, const Scope& b) {
  for (int i = 0; i < 3; ++i) {
    if (!same_bits(a.origin[i], b.origin[i]) || !same_bits(a.size[i], b.size[i])) return false;
    for (int j = 0; j < 3; ++j)
      if (!same_bits(a.frame[i][j], b.frame[i][j])) return false;
  }
  return true;
}

// What a derivation gave: its terminals, or the kind of error that stopped it.
struct Outcome {
  std::optional<Derivation> derivation;
  ErrorKind error = ErrorKind::Internal;
  std::string message;
};

Outcome derive_outcome(const Grammar& g) {
  Outcome out;
  try {
    out.derivation = derive(g, small_derivation());
  } catch (const Error& e) {
    out.error = e.kind();
    out.message = e.what();
  }
  return out;
}

// Same terminals (labels by name, scopes bit for bit), or the same kind of
// error: structurally equal graphs derive the same building.
std::string compare(const Outcome& a, const Outcome& b) {
  if (a.derivation.has_value() != b.derivation.has_value() || (!a.derivation && a.error != b.error))
    return "the written grammar derives differently: original " +
           (a.derivation ? std::string("succeeded") : "failed: " + a.message) + "; written " +
           (b.derivation ? std::string("succeeded") : "failed: " + b.message);
  if (!a.derivation) return "";
  const Derivation& x = *a.derivation;
  const Derivation& y = *b.derivation;
  if (x.terminals.size() != y.terminals.size())
    return "the written grammar derives " + std::to_string(y.terminals.size()) + " terminals, the original " +
           std::to_string(x.terminals.size());
  for (std::size_t i = 0; i < x.terminals.size(); ++i) {
    const Terminal& s = x.terminals[i];
    const Terminal& t = y.terminals[i];
    if (x.labels[s.label] != y.labels[t.label] || s.coloured != t.coloured || !(s.colour == t.colour) ||
        !same_scope(s.scope, t.scope))
      return "the written grammar derives a different terminal " + std::to_string(i) + " (" + x.labels[s.label] +
             " vs " + y.labels[t.label] + ")";
  }
  return "";
}

std::string run(std::string_view text) {
  const Grammar g = parse_grammar(text, kSource);

  // Past this point the text was accepted: every failure is a finding.
  std::string written;
  try {
    written = write_grammar(g);
  } catch (const std::exception& e) {
    return std::string("the writer rejects a parsed grammar: ") + e.what();
  }
  std::optional<Grammar> again;
  try {
    again = parse_grammar(written, "written.grm");
  } catch (const std::exception& e) {
    return std::string("the written grammar does not parse: ") + e.what() + "\n--- written:\n" + excerpt(written);
  }
  if (!equal_grammars(g, *again)) return "the written grammar parses to a different graph:\n" + excerpt(written);
  if (write_grammar(*again) != written) return "writing the written grammar again changes it:\n" + excerpt(written);

  // Deriving: bad sizes, types and runaway recursion are Input or Limit
  // errors that name the file; crashes, hangs and other errors are findings.
  const Outcome first = derive_outcome(g);
  if (!first.derivation && first.error != ErrorKind::Input && first.error != ErrorKind::Limit)
    return "unexpected " + std::string(kind_name(first.error)) + " error while deriving: " + first.message;
  if (!first.derivation && !first.message.starts_with(kSource))
    return "a derivation error that does not say where: " + first.message;
  return compare(first, derive_outcome(*again));
}

}  // namespace

std::string grammar_reader(Bytes input) {
  const std::string_view text(reinterpret_cast<const char*>(input.data()), input.size());
  return judged([&] { return run(text); }, {ErrorKind::Input}, kSource);
}

}  // namespace vern::fuzz
