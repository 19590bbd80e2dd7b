#include "serve/api_json.hpp"

#include "api/api_data.hpp"

namespace vern {

using nlohmann::json;

json error_json(const Error& e) {
  const vernacular::Error located = vernacular::detail::error_of(e);
  return {{"kind", vernacular::to_string(located.kind)},
          {"line", located.location.line},
          {"column", located.location.column},
          {"message", located.message},
          {"hint", located.hint},
          {"text", std::string(e.what())}};
}

ApiAnswer bad_request(const std::string& message) {
  return {400, dumped(json{{"ok", false}, {"error", {{"kind", "usage"}, {"message", message}}}})};
}

std::string dumped(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

}  // namespace vern
