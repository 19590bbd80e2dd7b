// Command-line parsing shared by the apps: options declared once, with their
// help text, so parsing, errors and --help can never disagree.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vern {

struct OptionSpec {
  std::string name;         // "--seed"
  std::string short_name;   // "-s" or ""
  int values = 0;           // how many values follow (0: a flag)
  std::string value_names;  // "N" or "X Y Z", for --help
  std::string help;
};

struct ParsedCommandLine {
  std::string program;  // for messages about the values
  std::vector<std::string> positional;
  std::map<std::string, std::vector<std::string>> options;  // by long name

  bool has(const std::string& name) const { return options.count(name) != 0; }
  const std::string& value(const std::string& name, std::size_t i = 0) const { return options.at(name).at(i); }
};

class CommandLine {
 public:
  CommandLine(std::string program, std::string usage, std::string description);
  void add(OptionSpec spec);
  // --help, --version, and --quiet where the command prints progress:
  // every command's.
  void add_standard_options(bool quiet = true);
  // Free text printed after the options in --help (examples, exit codes).
  void set_epilog(std::string text) { epilog_ = std::move(text); }

  // Throws vern::Error (Usage) for unknown options, missing or empty values
  // and empty positional arguments, with a suggestion when a known option
  // is close.
  ParsedCommandLine parse(int argc, const char* const* argv) const;
  std::string help() const;
  // "infer (Vernacular) 0.1.0": the version project() gives the build.
  std::string version() const;
  // What --help or --version asks to print instead of running (help
  // first when both), or nothing.
  std::optional<std::string> requested_text(const ParsedCommandLine& args) const;
  // parse(), but when --help or --version asks for text, prints it to
  // stdout and gives nothing: the program then ends with 0.
  std::optional<ParsedCommandLine> parse_or_answer(int argc, const char* const* argv) const;

  // Typed values, with Usage errors that name the option.
  static double number(const ParsedCommandLine& cl, const std::string& name, std::size_t i = 0);
  static long long integer(const ParsedCommandLine& cl, const std::string& name, long long min, long long max);
  // The option's value, which must be one of `allowed` (Usage error naming them).
  static const std::string& one_of(const ParsedCommandLine& cl, const std::string& name,
                                   const std::vector<std::string>& allowed);

 private:
  const OptionSpec* find(const std::string& arg) const;

  std::string program_;
  std::string usage_;
  std::string description_;
  std::string epilog_;
  std::vector<OptionSpec> specs_;
};

}  // namespace vern
