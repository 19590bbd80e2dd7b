// What a browser sends serve's /api/derive: any bytes. The answer must be
// JSON that reads back, 200 with buildings or a located error of the
// grammar's own (input or limit), or 400 saying what the request lacks;
// never another kind of error or a thrown exception.
#include <nlohmann/json.hpp>

#include "entries.hpp"
#include "serve/derive_request.hpp"
#include "verdict.hpp"

namespace vern::fuzz {

std::string editor_request(Bytes input) {
  return judged(
      [&]() -> std::string {
        ServeSession session;
        // Small limits: a runaway grammar stops at once.
        session.limits.max_depth = 40;
        session.limits.max_terminals = 2000;
        session.limits.max_operations = 20000;
        session.most_parts = 4000;
        const ApiAnswer answer =
            derive_request(std::string_view(reinterpret_cast<const char*>(input.data()), input.size()), session);
        const nlohmann::json body = nlohmann::json::parse(answer.body, nullptr, false);
        if (body.is_discarded() || !body.is_object() || !body.contains("ok") || !body["ok"].is_boolean())
          return "an answer that is not the JSON promised: " + excerpt(answer.body);
        if (answer.status == 400) {
          if (body["ok"].get<bool>() || !body["error"]["message"].is_string() || body["error"]["message"].get<std::string>().empty())
            return "a 400 that does not say why: " + excerpt(answer.body);
          return "";
        }
        if (answer.status != 200) return "status " + std::to_string(answer.status) + ": " + excerpt(answer.body);
        if (body["ok"].get<bool>()) {
          if (!body["buildings"].is_array() || body["buildings"].empty()) return "ok without buildings: " + excerpt(answer.body);
          return "";
        }
        const std::string kind = body["error"]["kind"].is_string() ? body["error"]["kind"].get<std::string>() : "";
        if (kind != "input" && kind != "limit") return "an error of kind '" + kind + "': " + excerpt(answer.body);
        if (!body["error"]["text"].is_string() || !body["error"]["text"].get<std::string>().starts_with("editor:"))
          return "an error that does not say where: " + excerpt(answer.body);
        return "";
      },
      {}, "");
}

}  // namespace vern::fuzz
