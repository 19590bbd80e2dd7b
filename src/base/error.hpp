// Errors that reach a user: where, what was expected, what to do.
//
// Every failure the toolkit reports is a vern::Error. Its kind decides the
// process exit code (see exit_code()), its text is already formatted as
//   file:line:col: error: what went wrong
//     hint: what to do
// so front ends print what() and nothing else.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace vern {

// A position in a source text. line == 0 means "no position" (a node built
// by code rather than read from a file).
struct SourceLoc {
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  bool known() const { return line != 0; }
  friend bool operator==(const SourceLoc&, const SourceLoc&) = default;
};

enum class ErrorKind {
  Usage,     // the command line is wrong
  Input,     // a grammar or data file is wrong (syntax, unknown name, type)
  Limit,     // a configured limit was reached (depth, terminals, operations)
  Io,        // a file could not be read or written
  Internal,  // a bug: a broken invariant
};

// Exit codes, documented in the README.
int exit_code(ErrorKind kind);

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, std::string message) : std::runtime_error(std::move(message)), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

 private:
  ErrorKind kind_;
};

// "file:line:col: error: message" (+ "\n  hint: hint" when a hint is given).
std::string format_message(const std::string& file, SourceLoc loc, const std::string& message,
                           const std::string& hint = {});

// "file:line:col: warning: message": warnings print in the same shape.
std::string format_warning(const std::string& file, SourceLoc loc, const std::string& message);

// A message about an input checked against another, naming it: an error
// that names no file ("error: ...") takes its name in front
// ("house.obj: error: ..."); one that names its own (a grammar's
// "style.grm:3:7: error: ...") gets a line "  example: house.obj" before
// its hint. `role` is that line's word.
std::string naming_input(const std::string& message, const std::string& input, const std::string& role = "example");

[[noreturn]] void fail(ErrorKind kind, const std::string& file, SourceLoc loc, const std::string& message,
                       const std::string& hint = {});

}  // namespace vern
