// Errors as values: what went wrong, where, and what to do about it.
//
// Every function of the public API reports failure by throwing
// vernacular::Failure, which carries an Error: a value a caller can
// inspect (its kind decides what to do: a broken input is the user's to
// fix, a limit can be raised, an internal error is ours) and format as it
// likes. Nothing in an Error names a command-line flag or command.
#pragma once

#include <cstdint>
#include <exception>
#include <string>

namespace vernacular {

enum class ErrorKind {
  Usage,     // a call's arguments are wrong (an unknown file type, an empty list of examples)
  Input,     // a grammar or example file is wrong (syntax, unknown name, overlapping parts)
  Limit,     // a limit was reached (derivation depth, terminals, matching steps, memory)
  Io,        // a file could not be read or written
  Internal,  // a bug in Vernacular: a broken invariant; please report it
};

// "usage", "input", "limit", "io", "internal".
const char* to_string(ErrorKind kind);

// Where an error lies: a file and, within it, a line and column (a
// grammar's text, an OBJ's line), or the object or node named (a glTF
// node, an OBJ object). Empty and 0 where not known.
struct Location {
  std::string file;
  std::uint32_t line = 0;    // 1-based; 0: no line
  std::uint32_t column = 0;  // 1-based; 0: no column
  friend bool operator==(const Location&, const Location&) = default;
};

struct Error {
  ErrorKind kind = ErrorKind::Internal;
  Location location;
  std::string message;  // what went wrong; may span lines (the rule chain, the example concerned)
  std::string hint;     // what to do about it; empty where there is nothing to say

  // "file:line:column: error: message" and, with a hint, "\n  hint: hint":
  // the form the commands print.
  std::string text() const;
  friend bool operator==(const Error&, const Error&) = default;
};

// What the API throws. what() is error().text(), or the text given: an
// error found inside Vernacular keeps the words its finder wrote (lines
// naming the example concerned, the rule chain), which error() holds
// taken apart.
class Failure : public std::exception {
 public:
  explicit Failure(Error error);
  Failure(Error error, std::string text);
  const Error& error() const noexcept { return error_; }
  const char* what() const noexcept override { return text_.c_str(); }

 private:
  Error error_;
  std::string text_;
};

}  // namespace vernacular
