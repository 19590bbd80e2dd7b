#include "support/command_line.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>

#include "base/error.hpp"
#include "base/suggest.hpp"

namespace vern {

namespace {
[[noreturn]] void usage_error(const std::string& program, const std::string& message, const std::string& hint) {
  throw Error(ErrorKind::Usage, program + ": error: " + message + (hint.empty() ? "" : "\n  hint: " + hint));
}
}  // namespace

CommandLine::CommandLine(std::string program, std::string usage, std::string description)
    : program_(std::move(program)), usage_(std::move(usage)), description_(std::move(description)) {}

void CommandLine::add(OptionSpec spec) { specs_.push_back(std::move(spec)); }

void CommandLine::add_standard_options(bool quiet) {
  if (quiet) add({"--quiet", "-q", 0, "", "print errors only"});
  add({"--help", "-h", 0, "", "show this help"});
  add({"--version", "", 0, "", "show the version and exit"});
}

const OptionSpec* CommandLine::find(const std::string& arg) const {
  for (const auto& s : specs_)
    if (arg == s.name || (!s.short_name.empty() && arg == s.short_name)) return &s;
  return nullptr;
}

ParsedCommandLine CommandLine::parse(int argc, const char* const* argv) const {
  ParsedCommandLine out;
  out.program = program_;
  bool only_positional = false;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (only_positional || arg.size() < 2 || arg[0] != '-' || (arg[1] >= '0' && arg[1] <= '9')) {
      // Every positional argument is a file or folder; "" names none (a
      // shell variable left unset), and would become the current folder.
      if (arg.empty())
        usage_error(program_, "an empty argument names no file", "run '" + program_ + " --help' for what to give");
      out.positional.push_back(arg);
      continue;
    }
    if (arg == "--") {
      only_positional = true;
      continue;
    }
    std::string inline_value;
    bool has_inline = false;
    if (auto eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      inline_value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      has_inline = true;
    }
    const OptionSpec* spec = find(arg);
    if (!spec) {
      std::vector<std::string> names;
      for (const auto& s : specs_) names.push_back(s.name);
      const std::string best = closest_name(arg, names);
      usage_error(program_, "unknown option '" + arg + "'",
                  best.empty() ? "run '" + program_ + " --help' for the options"
                               : "did you mean '" + best + "'? ('" + program_ + " --help' lists them all)");
    }
    auto& values = out.options[spec->name];
    values.clear();
    if (has_inline) {
      if (spec->values != 1)
        usage_error(program_, spec->name + " takes " + std::to_string(spec->values) + " values, not '=" + inline_value + "'",
                    "write " + spec->name + (spec->value_names.empty() ? "" : " " + spec->value_names) +
                        " with spaces, without '='");
      values.push_back(inline_value);
    } else {
      for (int k = 0; k < spec->values; ++k) {
        if (i + 1 >= argc)
          usage_error(program_, spec->name + " needs " + std::to_string(spec->values) + " value" +
                                    (spec->values > 1 ? "s" : "") + " (" + spec->value_names + ")",
                      "for example: " + spec->name + " " + spec->value_names);
        values.emplace_back(argv[++i]);
      }
    }
    // No option means anything by "": `-o ''` would write ".prims.obj".
    for (const std::string& v : values)
      if (v.empty())
        usage_error(program_, spec->name + " is given an empty value",
                    "give " + spec->name + " " + spec->value_names + " (an unset shell variable gives '')");
  }
  return out;
}

std::string CommandLine::version() const { return program_ + " (Vernacular) " VERN_VERSION "\n"; }

std::optional<ParsedCommandLine> CommandLine::parse_or_answer(int argc, const char* const* argv) const {
  ParsedCommandLine args = parse(argc, argv);
  if (const std::optional<std::string> text = requested_text(args)) {
    std::cout << *text;
    return std::nullopt;
  }
  return args;
}

std::optional<std::string> CommandLine::requested_text(const ParsedCommandLine& args) const {
  if (args.has("--help")) return help();
  if (args.has("--version")) return version();
  return std::nullopt;
}

std::string CommandLine::help() const {
  std::string text = "usage: " + usage_ + "\n\n" + description_ + "\n\noptions:\n";
  for (const auto& s : specs_) {
    std::string left = "  " + (s.short_name.empty() ? "" : s.short_name + ", ") + s.name;
    if (!s.value_names.empty()) left += " " + s.value_names;
    if (left.size() < 28) left.resize(28, ' ');
    else left += "\n" + std::string(28, ' ');
    // A help of several lines keeps to its column.
    std::string help = s.help;
    for (std::size_t at = help.find('\n'); at != std::string::npos; at = help.find('\n', at + 1))
      help.insert(at + 1, std::string(28, ' '));
    text += left + help + "\n";
  }
  if (!epilog_.empty()) text += "\n" + epilog_;
  return text;
}

double CommandLine::number(const ParsedCommandLine& cl, const std::string& name, std::size_t i) {
  const std::string& text = cl.value(name, i);
  double v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    usage_error(cl.program, name + " expects a number, got '" + text + "'", "for example: " + name + " 10");
  return v;
}

long long CommandLine::integer(const ParsedCommandLine& cl, const std::string& name, long long min, long long max) {
  const std::string& text = cl.value(name);
  long long v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size())
    usage_error(cl.program, name + " expects a whole number, got '" + text + "'",
                "give a whole number from " + std::to_string(min) + " to " + std::to_string(max));
  if (v < min || v > max)
    usage_error(cl.program, name + " must be between " + std::to_string(min) + " and " + std::to_string(max) + ", got " + text,
                "give a whole number from " + std::to_string(min) + " to " + std::to_string(max));
  return v;
}

const std::string& CommandLine::one_of(const ParsedCommandLine& cl, const std::string& name,
                                       const std::vector<std::string>& allowed) {
  const std::string& text = cl.value(name);
  if (std::find(allowed.begin(), allowed.end(), text) != allowed.end()) return text;
  std::string list;
  for (std::size_t i = 0; i < allowed.size(); ++i) list += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + allowed[i];
  usage_error(cl.program, "unknown " + name + " '" + text + "'", "give " + list);
}

}  // namespace vern
