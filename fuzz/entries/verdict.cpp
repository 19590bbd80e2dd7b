#include "verdict.hpp"

#include <algorithm>
#include <exception>
#include <typeinfo>

namespace vern::fuzz {

std::string_view kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Usage: return "Usage";
    case ErrorKind::Input: return "Input";
    case ErrorKind::Limit: return "Limit";
    case ErrorKind::Io: return "Io";
    case ErrorKind::Internal: return "Internal";
  }
  return "unknown";
}

std::string judged(const std::function<std::string()>& body, std::initializer_list<ErrorKind> expected,
                   std::string_view where) {
  try {
    return body();
  } catch (const Error& e) {
    const std::string_view message = e.what();
    if (std::find(expected.begin(), expected.end(), e.kind()) == expected.end())
      return "unexpected " + std::string(kind_name(e.kind())) + " error: " + std::string(message);
    if (!message.starts_with(where))
      return "an error that does not say where (expected it to start with '" + std::string(where) +
             "'): " + std::string(message);
    return "";
  } catch (const std::exception& e) {
    // bad_alloc, out_of_range, ...: the toolkit promises a vern::Error.
    return "unexpected exception " + std::string(typeid(e).name()) + ": " + e.what();
  } catch (...) {
    return "unexpected exception of unknown type";
  }
}

std::string excerpt(std::string_view text, std::size_t limit) {
  if (text.size() <= limit) return std::string(text);
  return std::string(text.substr(0, limit)) + "\n[... " + std::to_string(text.size() - limit) + " more bytes]";
}

}  // namespace vern::fuzz
