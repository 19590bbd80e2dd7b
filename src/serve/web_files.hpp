// The page `serve` hands out: a fixed list of files, nothing else.
//
// Requests name a file of the list by its URL; no part of a URL ever
// becomes part of a path, so no request reaches outside the page's folder
// (no "..", no link followed out of it).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace vern {

struct WebFile {
  std::filesystem::path path;  // inside the page's folder
  std::string content_type;
};

// The file for `url` ("/", "/app.js", "/vendor/three.module.js", ...)
// inside `web` (the folder holding index.html and, from npm at set-up
// time, node_modules/three), or none.
std::optional<WebFile> web_file(std::string_view url, const std::filesystem::path& web);

// Where the page is: `given` (serve --web), else beside the program
// (PREFIX/share/vernacular/web when installed), else the source tree's
// web/ this program was built from. Throws vern::Error (Io) when none holds
// index.html and three.js, saying how to set it up.
std::filesystem::path find_web_folder(const std::optional<std::filesystem::path>& given,
                                      const std::filesystem::path& program);

}  // namespace vern
