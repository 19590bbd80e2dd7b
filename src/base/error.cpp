#include "base/error.hpp"

namespace vern {

int exit_code(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Usage: return 2;
    case ErrorKind::Input: return 3;
    case ErrorKind::Limit: return 4;
    case ErrorKind::Io: return 5;
    case ErrorKind::Internal: return 70;
  }
  return 70;
}

namespace {
std::string where(const std::string& file, SourceLoc loc) {
  std::string text = file;
  if (loc.known()) text += (text.empty() ? "" : ":") + std::to_string(loc.line) + ":" + std::to_string(loc.column);
  if (!text.empty()) text += ": ";
  return text;
}
}  // namespace

std::string format_warning(const std::string& file, SourceLoc loc, const std::string& message) {
  return where(file, loc) + "warning: " + message;
}

std::string format_message(const std::string& file, SourceLoc loc, const std::string& message,
                           const std::string& hint) {
  std::string text = where(file, loc) + "error: " + message;
  if (!hint.empty()) text += "\n  hint: " + hint;
  return text;
}

void fail(ErrorKind kind, const std::string& file, SourceLoc loc, const std::string& message,
          const std::string& hint) {
  throw Error(kind, format_message(file, loc, message, hint));
}

std::string naming_input(const std::string& message, const std::string& input, const std::string& role) {
  if (message.rfind("error: ", 0) == 0) return input + ": " + message;
  const std::size_t hint = message.find("\n  hint: ");
  const std::string line = "\n  " + role + ": " + input;
  if (hint == std::string::npos) return message + line;
  return message.substr(0, hint) + line + message.substr(hint);
}

}  // namespace vern
