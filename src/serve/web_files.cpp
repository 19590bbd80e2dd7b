#include "serve/web_files.hpp"

#include <array>
#include <system_error>

#include "base/error.hpp"

#ifndef VERN_SOURCE_WEB
#define VERN_SOURCE_WEB ""
#endif

namespace vern {

namespace fs = std::filesystem;

namespace {

struct Entry {
  std::string_view url;
  std::string_view file;
  std::string_view type;
};

constexpr std::array kFiles = {
    Entry{"/", "index.html", "text/html; charset=utf-8"},
    Entry{"/index.html", "index.html", "text/html; charset=utf-8"},
    Entry{"/app.js", "app.js", "text/javascript; charset=utf-8"},
    Entry{"/editor.js", "editor.js", "text/javascript; charset=utf-8"},
    Entry{"/viewer.js", "viewer.js", "text/javascript; charset=utf-8"},
    Entry{"/style.css", "style.css", "text/css; charset=utf-8"},
    Entry{"/vendor/three.module.js", "node_modules/three/build/three.module.js", "text/javascript; charset=utf-8"},
    Entry{"/vendor/three.core.js", "node_modules/three/build/three.core.js", "text/javascript; charset=utf-8"},
    Entry{"/vendor/OrbitControls.js", "node_modules/three/examples/jsm/controls/OrbitControls.js",
          "text/javascript; charset=utf-8"},
};

bool complete(const fs::path& web) {
  std::error_code ec;
  return fs::is_regular_file(web / "index.html", ec) &&
         fs::is_regular_file(web / "node_modules/three/build/three.module.js", ec);
}

}  // namespace

std::optional<WebFile> web_file(std::string_view url, const fs::path& web) {
  for (const Entry& e : kFiles)
    if (e.url == url) return WebFile{web / e.file, std::string(e.type)};
  return std::nullopt;
}

fs::path find_web_folder(const std::optional<fs::path>& given, const fs::path& program) {
  if (given) {
    if (!complete(*given))
      throw Error(ErrorKind::Io, given->string() + ": error: no page here (index.html and node_modules/three)\n"
                                                   "  hint: give the web/ folder of Vernacular's sources after "
                                                   "scripts/setup, which installs three.js into it");
    return *given;
  }
  std::error_code ec;
  const fs::path exe = fs::canonical(program, ec);
  for (const fs::path& candidate : {exe.parent_path().parent_path() / "share/vernacular/web", fs::path(VERN_SOURCE_WEB)})
    if (!candidate.empty() && complete(candidate)) return candidate;
  throw Error(ErrorKind::Io,
              "serve: error: the page is not installed (no index.html with node_modules/three beside the program or in " +
                  std::string(VERN_SOURCE_WEB) + ")\n  hint: run scripts/setup, which installs three.js from npm, or give --web DIR");
}

}  // namespace vern
