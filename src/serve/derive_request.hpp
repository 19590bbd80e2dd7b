// The editor's one question: derive this text with these seeds.
//
// Request (JSON): {"text": "...", "seed": 1, "count": 3, "size": [x, y, z]}
// (size: the plot, instead of the grammar's @scope; optional). Answer (JSON):
//   {"ok": true, "labels": [...], "colours": {label: [r, g, b]},
//    "meshes": {label: {"positions": [x, y, z, ...], "indices": [...]}},
//    "rules": [{"label": "floor", "line": 4}, ...],
//    "buildings": [{"seed": 1, "size": [x, y, z],
//                   "parts": [{"label": i, "matrix": [16, column-major],
//                              "at": [line, column], "rules": [rule, ...],
//                              "chain": "building > floor(2)",
//                              "path": [[op, index, axis], ...]}]}],
//    "note": ""}  (or which buildings were left out past the session's most_parts)
// z up, as grammars are; a part's matrix maps its primitive's unit box
// into place; its path, the split parts and repeat tiles it lies in
// (TerminalTrace::Step: operation, index, axis 0/1/2), says which storey
// and column it is in. Or, when the text does not read or derive:
//   {"ok": false, "error": {"kind": "input", "line": 3, "column": 14,
//                           "message": "...", "hint": "...", "text": "..."}}
// at the line and column of the text sent. A grammar that runs away stops
// at the session's limits, an error like any other.
#pragma once

#include <string>
#include <string_view>

#include "serve/session.hpp"

namespace vern {

struct ApiAnswer {
  int status = 200;  // 400 for a request that is not the JSON above
  std::string body;  // JSON
};

// At most this many buildings a request.
inline constexpr int kMostBuildings = 64;

ApiAnswer derive_request(std::string_view request, const ServeSession& session);

// {"name": ..., "text": ..., "examples": [{"name": ..., "parts": [{"label": ..., "min": [...], "max": [...]}]}]}:
// what the page starts with.
std::string session_json(const ServeSession& session);

}  // namespace vern
