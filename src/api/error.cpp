// vernacular::Error and the reading of internal error texts into it.
#include "vernacular/error.hpp"

#include <cctype>

#include "api/api_data.hpp"

namespace vernacular {

const char* to_string(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Usage: return "usage";
    case ErrorKind::Input: return "input";
    case ErrorKind::Limit: return "limit";
    case ErrorKind::Io: return "io";
    case ErrorKind::Internal: return "internal";
  }
  return "internal";
}

// The commands' form, written by the one formatter they use.
std::string Error::text() const {
  return vern::format_message(location.file, vern::SourceLoc{location.line, location.column}, message, hint);
}

Failure::Failure(Error error) : error_(std::move(error)), text_(error_.text()) {}

Failure::Failure(Error error, std::string text) : error_(std::move(error)), text_(std::move(text)) {}

namespace detail {
namespace {


ErrorKind kind_of(vern::ErrorKind kind) {
  switch (kind) {
    case vern::ErrorKind::Usage: return ErrorKind::Usage;
    case vern::ErrorKind::Input: return ErrorKind::Input;
    case vern::ErrorKind::Limit: return ErrorKind::Limit;
    case vern::ErrorKind::Io: return ErrorKind::Io;
    case vern::ErrorKind::Internal: return ErrorKind::Internal;
  }
  return ErrorKind::Internal;
}

// A trailing ":digits" of `text`, removed, or nullopt.
std::optional<std::uint32_t> take_number(std::string& text) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string::npos || colon + 1 == text.size()) return std::nullopt;
  std::uint32_t n = 0;
  for (std::size_t i = colon + 1; i < text.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(text[i])) || n > 100'000'000) return std::nullopt;
    n = n * 10 + static_cast<std::uint32_t>(text[i] - '0');
  }
  text.resize(colon);
  return n;
}

}  // namespace

Error error_of(const vern::Error& e) {
  Error out;
  out.kind = kind_of(e.kind());
  std::string text = e.what();
  // Where "error: " starts the text, or follows the location's ": ".
  std::size_t at = text.rfind("error: ", 0) == 0 ? 0 : text.find(": error: ");
  if (at == std::string::npos) {
    out.message = text;
    return out;
  }
  if (at != 0) {
    std::string where = text.substr(0, at);
    at += 2;
    std::string file = where;
    const auto second = take_number(file);
    const auto first = second ? take_number(file) : std::nullopt;
    if (first) {
      out.location = {file, *first, *second};
    } else if (second) {
      out.location = {file, *second, 0};
    } else {
      out.location.file = where;
    }
  }
  std::string rest = text.substr(at + 7);
  const std::size_t hint = rest.rfind("\n  hint: ");
  if (hint != std::string::npos) {
    out.hint = rest.substr(hint + 9);
    rest.resize(hint);
  }
  out.message = std::move(rest);
  return out;
}

}  // namespace detail
}  // namespace vernacular
