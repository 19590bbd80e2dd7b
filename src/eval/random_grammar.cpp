#include "eval/random_grammar.hpp"

#include <cmath>
#include <vector>

#include "base/error.hpp"
#include "base/number_format.hpp"
#include "forward/random_stream.hpp"

namespace vern {

namespace {

class GrammarMaker {
 public:
  explicit GrammarMaker(const GrammarOptions& o) : o_(o), rng_(mix64(o.seed ^ 0x96a3u)) {}

  std::string run() {
    // Each rule but the first is called from one earlier rule: a random
    // recursive tree of calls, about ln(rules) deep.
    const std::size_t n = o_.rules;
    std::vector<std::vector<std::size_t>> calls(n);
    for (std::size_t r = 1; r < n; ++r) calls[static_cast<std::size_t>(rng_.uniform() * static_cast<double>(r))].push_back(r);

    std::string out = "# A random grammar: " + std::to_string(n) + " rules, seed " + std::to_string(o_.seed) +
                      " (vern_bench --make-grammar).\n@start r0\n" +
                      (o_.varied_plots ? "@scope rand(28, 52), rand(21, 39), rand(42, 78)\n\n" : "@scope 40, 30, 60\n\n");
    for (std::size_t r = 0; r < n; ++r) {
      const bool alternatives = r > 0 && rng_.uniform() < 0.125;
      out += rule(r, calls[r], alternatives ? " : 2" : "");
      if (alternatives) out += rule(r, calls[r], " : 1");
    }
    return out;
  }

 private:
  std::string rule(std::size_t r, const std::vector<std::size_t>& calls, const char* priority) {
    const int axis = static_cast<int>(rng_.uniform() * 3);
    std::string body;
    // A leaf rule sometimes tiles a primitive instead of splitting.
    if (calls.empty() && rng_.uniform() < 0.3) {
      body = rng_.uniform() < 0.5 ? "repeat(" + axis_name(axis) + ", " + number(rng_.uniform(1.0, 4.0)) + "){ " + primitive() + " }"
                                  : "repeatN(" + axis_name(axis) + ", " + std::to_string(2 + static_cast<int>(rng_.uniform() * 5)) +
                                        "){ " + primitive() + " }";
    } else {
      // The calls, and primitives or nil to fill up to a random part count.
      std::vector<std::string> parts;
      for (std::size_t c : calls) parts.push_back("r" + std::to_string(c));
      const auto k = std::max<std::size_t>(parts.size(), 2 + static_cast<std::size_t>(rng_.uniform() * (o_.branching - 1)));
      while (parts.size() < k) parts.push_back(rng_.uniform() < 0.1 ? "nil" : primitive());
      // Shuffle so calls are not always first (Fisher-Yates on our stream).
      for (std::size_t i = parts.size(); i > 1; --i) std::swap(parts[i - 1], parts[static_cast<std::size_t>(rng_.uniform() * static_cast<double>(i))]);
      body = "split(" + axis_name(axis) + "){ ";
      for (std::size_t i = 0; i < parts.size(); ++i) body += (i == 0 ? "" : " | ") + size() + " : " + parts[i];
      body += " }";
    }
    return "r" + std::to_string(r) + " --> " + body + priority + "\n";
  }

  std::string size() {
    const double u = rng_.uniform();
    if (u < 0.6) return "~" + number(rng_.uniform(1.0, 3.0));
    if (u < 0.8) return "~rand(" + number(rng_.uniform(0.5, 1.0)) + ", " + number(rng_.uniform(1.0, 2.0)) + ")";
    return number(rng_.uniform(0.5, 2.0));  // absolute
  }

  std::string primitive() { return std::string("I(") + kWorkloadLabels[static_cast<std::size_t>(rng_.uniform() * kWorkloadLabels.size())] + ")"; }

  static std::string axis_name(int axis) { return std::string(1, static_cast<char>('x' + axis)); }

  // Two decimals, as a person writes sizes.
  static std::string number(double v) { return format_number(std::round(v * 100) / 100); }

  const GrammarOptions& o_;
  RandomStream rng_;
};

}  // namespace

std::string random_grammar(const GrammarOptions& options) {
  if (options.rules == 0 || options.branching < 2) {
    fail(ErrorKind::Usage, "--make-grammar", {}, "grammar options out of range", "give at least 1 rule and --branching >= 2");
  }
  return GrammarMaker(options).run();
}

}  // namespace vern
