// What serve's answers share: errors as JSON, located in the editor's text,
// and JSON written whatever bytes a name holds.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "base/error.hpp"
#include "serve/derive_request.hpp"

namespace vern {

// The name errors give the text the page sends: they name no file, only a
// place in it ("editor:3:14: error: ...").
inline constexpr const char* kEditorSource = "editor";

// {"kind", "line", "column", "message", "hint", "text"} of a vern::Error.
nlohmann::json error_json(const Error& e);

// 400, {"ok": false, "error": {"kind": "usage", "message": ...}}.
ApiAnswer bad_request(const std::string& message);

// The JSON's text; bytes that are no UTF-8 (a file name) become U+FFFD.
std::string dumped(const nlohmann::json& value);

}  // namespace vern
