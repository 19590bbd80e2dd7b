// `serve`'s HTTP server: the page and its one API, on the loopback
// interface only (Debian's cpp-httplib).
//
//   GET  /, /app.js, ...    the page (web_files.hpp)
//   GET  /api/session       what the page starts with (session_json)
//   POST /api/derive        derive the editor's text (derive_request.hpp)
//   POST /api/check         does it derive each example, how (check_request.hpp)
// Anything else is 404; a request body past 4 MiB is 413. Requests are
// answered on a pool of threads, so several tabs work at once and a slow
// derivation holds up no other request.
#pragma once

#include <filesystem>
#include <functional>

#include "serve/session.hpp"

namespace vern {

struct ServeOptions {
  int port = 8765;  // 0: any free port (said through on_listening)
  std::filesystem::path web;
};

// Serves until stop() is called from on_listening's handle or the process
// ends. on_listening(port, stop) is called once the socket listens. Throws
// vern::Error (Io) when the port cannot be bound, saying which.
void serve(const ServeSession& session, const ServeOptions& options,
           const std::function<void(int port, std::function<void()> stop)>& on_listening);

}  // namespace vern
