#include "serve/check_request.hpp"

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "graph/parser.hpp"
#include "inverse/check/example_verdict.hpp"
#include "serve/api_json.hpp"

namespace vern {

using nlohmann::json;

ApiAnswer check_request(std::string_view request, const ServeSession& session) {
  const json in = json::parse(request, nullptr, false);
  if (in.is_discarded() || !in.is_object()) return bad_request("the request is not a JSON object");
  if (!in.contains("text") || !in["text"].is_string()) return bad_request("the request has no \"text\" string");
  Grammar grammar;
  try {
    grammar = parse_grammar(in["text"].get<std::string>(), kEditorSource);
  } catch (const Error& e) {
    return {200, dumped(json{{"ok", false}, {"error", error_json(e)}})};
  }
  json examples = json::array();
  for (const Example& example : session.examples) {
    json verdict = {{"name", example.source}, {"derivable", false}, {"witness", json::array()}, {"reason", ""}};
    try {
      CheckOptions options;
      options.max_steps = session.check_steps;
      const CheckResult r = example_verdict(grammar, example, session.stack, std::nullopt, options);
      verdict["derivable"] = r.derivable;
      verdict["witness"] = r.witness;
      verdict["reason"] = r.mismatch;
    } catch (const Error& e) {
      // The grammar's or the checker's limit: this example is not shown derivable.
      verdict["reason"] = std::string(e.what());
    }
    examples.push_back(std::move(verdict));
  }
  return {200, dumped(json{{"ok", true}, {"examples", std::move(examples)}})};
}

}  // namespace vern
