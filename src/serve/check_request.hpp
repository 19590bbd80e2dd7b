// The inference view's question: does this text derive each example, and
// how (check's witness), or where does it fail (check's reason)?
//
// Request (JSON): {"text": "..."}. Answer (JSON):
//   {"ok": true, "examples": [{"name": "...", "derivable": true,
//                              "witness": ["plot: alternative 2 of 2 (split(x) at 24:10)", ...],
//                              "reason": ""}, ...]}
// or, when the text does not read, derive_request's {"ok": false, "error": ...}.
// An example the checker gives up on (its step limit) is not derivable,
// with the checker's message as the reason.
#pragma once

#include <string_view>

#include "serve/derive_request.hpp"
#include "serve/session.hpp"

namespace vern {

ApiAnswer check_request(std::string_view request, const ServeSession& session);

}  // namespace vern
