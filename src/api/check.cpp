// check: the checker's verdict on an example behind the public API.
#include "vernacular/check.hpp"

#include "api/api_data.hpp"
#include "inverse/check/example_verdict.hpp"

namespace vernacular {

Verdict check(const Grammar& grammar, const Example& example, const CheckOptions& options) {
  return detail::guarded([&] {
    vern::CheckOptions o;
    o.tolerance = options.tolerance;
    o.max_steps = options.max_steps;
    vern::CheckResult r =
        vern::example_verdict(grammar.data().grammar, example.data().example, options.stack,
                              options.plot ? std::optional<glm::dvec3>(glm::dvec3((*options.plot)[0], (*options.plot)[1],
                                                                                  (*options.plot)[2]))
                                           : std::nullopt,
                              o);
    Verdict v;
    v.derivable = r.derivable;
    v.witness = std::move(r.witness);
    v.reason = std::move(r.mismatch);
    return v;
  });
}

}  // namespace vernacular
