#include "serve/server.hpp"

#include <httplib.h>
#include <sys/socket.h>

#include <vector>

#include "base/error.hpp"
#include "base/input_file.hpp"
#include "serve/check_request.hpp"
#include "serve/derive_request.hpp"
#include "serve/web_files.hpp"

namespace vern {

namespace {

constexpr std::size_t kLargestRequest = 4u << 20;

void not_found(httplib::Response& res, const std::string& path) {
  res.status = 404;
  res.set_content("not found: " + path + " (the page is at /)\n", "text/plain; charset=utf-8");
}

}  // namespace

void serve(const ServeSession& session, const ServeOptions& options,
           const std::function<void(int port, std::function<void()> stop)>& on_listening) {
  httplib::Server server;
  server.set_payload_max_length(kLargestRequest);
  // SO_REUSEADDR (a restart binds at once) but not httplib's default
  // SO_REUSEPORT, with which a second server, anyone's, would share the
  // port and take half the page's requests.
  server.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  const std::string start = session_json(session);

  server.Get(R"(/api/session)", [&](const httplib::Request&, httplib::Response& res) {
    res.set_content(start, "application/json");
  });
  server.Post(R"(/api/derive)", [&](const httplib::Request& req, httplib::Response& res) {
    const ApiAnswer answer = derive_request(req.body, session);
    res.status = answer.status;
    res.set_content(answer.body, "application/json");
  });
  server.Post(R"(/api/check)", [&](const httplib::Request& req, httplib::Response& res) {
    const ApiAnswer answer = check_request(req.body, session);
    res.status = answer.status;
    res.set_content(answer.body, "application/json");
  });
  server.Get(R"(/.*)", [&](const httplib::Request& req, httplib::Response& res) {
    const std::optional<WebFile> file = web_file(req.path, options.web);
    std::vector<unsigned char> bytes;
    if (!file || read_regular_file(file->path, 64u << 20, bytes)) return not_found(res, req.path);
    res.set_content(std::string(bytes.begin(), bytes.end()), file->content_type.c_str());
    // Same-origin only, nothing cached across versions of the page.
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Content-Type-Options", "nosniff");
  });
  server.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    // httplib reads a body sent as a form (any request without a JSON
    // Content-Type) up to 8 KiB only, and says 413 past it.
    if (res.status == 413)
      res.set_content("request too large: at most 4 MiB sent as Content-Type: application/json (8 KiB as a form)\n",
                      "text/plain; charset=utf-8");
    else if (res.body.empty())
      res.set_content(std::to_string(res.status) + ": " + req.path + "\n", "text/plain; charset=utf-8");
  });
  server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    res.status = 500;
    std::string what = "internal error";
    try {
      std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    res.set_content(what + "\n", "text/plain; charset=utf-8");
  });

  const char* host = "127.0.0.1";  // loopback only: the page runs grammars for whoever asks
  int port = options.port;
  if (port == 0) {
    port = server.bind_to_any_port(host);
    if (port < 0) throw Error(ErrorKind::Io, "serve: error: could not bind any port on 127.0.0.1");
  } else if (!server.bind_to_port(host, port)) {
    throw Error(ErrorKind::Io, "serve: error: could not listen on 127.0.0.1:" + std::to_string(port) +
                                   "\n  hint: another program uses it; give another with --port, or --port 0 for any");
  }
  on_listening(port, [&server] { server.stop(); });
  server.listen_after_bind();
}

}  // namespace vern
