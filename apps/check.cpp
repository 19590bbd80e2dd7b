// check: does a grammar derive these buildings exactly, and how?
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <vernacular/vernacular.hpp>

#include "support/command_line.hpp"
#include "support/example_options.hpp"
#include "support/guarded_main.hpp"

namespace fs = std::filesystem;
using namespace vern;

namespace {

constexpr int kNotDerivable = 1;

CommandLine make_command_line() {
  CommandLine cl("check", "check STYLE.grm EXAMPLES... [options]",
                 "For each example building, says whether the grammar derives it exactly (the\n"
                 "same labelled parts, within the tolerance) on a plot of the example's own size\n"
                 "(or --scope, with the example's lowest corner at the plot's),\n"
                 "and prints the choices and values that reproduce it, or where the first\n"
                 "mismatch is. EXAMPLES are .obj, .gltf or .glb files, or folders of them.");
  cl.add({"--tolerance", "", 1, "METRES", "coordinates closer than this are equal (default: 1e-6 of the example's size or distance from the origin)"});
  cl.add({"--scope", "", 3, "X Y Z", "plot size to derive on (default: each example's own extent)"});
  cl.add({"--brief", "-b", 0, "", "one line per example, without the choices"});
  cl.add({"--max-steps", "", 1, "N", "give up after N matching steps per example (default 10000000); a repeat of more tiles is refused"});
  add_example_options(cl);
  cl.add_standard_options(/*quiet=*/false);
  cl.set_epilog(
      "examples:\n"
      "  check garage.grm data/examples/garage/         # do all the examples fit the inferred style?\n"
      "  check style.grm my_house.obj                    # does my house fit the style, and how?\n"
      "\n"
      "exit codes: 0 every example is derivable, 1 some example is not, 2 usage error,\n"
      "            3 bad input (grammar or example file), 4 a limit was reached,\n"
      "            5 a file could not be read, 70 internal error\n");
  return cl;
}

int run(int argc, char** argv) {
  const CommandLine cl = make_command_line();
  const std::optional<ParsedCommandLine> parsed = cl.parse_or_answer(argc, argv);
  if (!parsed) return 0;
  const ParsedCommandLine& args = *parsed;
  if (args.positional.size() < 2)
    throw Error(ErrorKind::Usage, "check: error: give a grammar and at least one example\n"
                                  "  hint: check style.grm examples/*.obj");
  vernacular::CheckOptions options;
  if (args.has("--tolerance")) {
    options.tolerance = CommandLine::number(args, "--tolerance");
    if (!(options.tolerance > 0))
      throw Error(ErrorKind::Usage, "check: error: --tolerance must be > 0, got " + args.value("--tolerance") +
                                        "\n  hint: for example --tolerance 0.001");
  }
  if (args.has("--max-steps"))
    options.max_steps = static_cast<std::uint64_t>(CommandLine::integer(args, "--max-steps", 1, 1LL << 50));
  const bool brief = args.has("--brief");
  vernacular::ReadOptions reading = read_options(args);
  reading.tolerance = options.tolerance;
  options.stack = stack_order(args);
  // A hand-written grammar's plot can be larger than what it built (the
  // city's towers stop below its 80 m plot): --scope names the plot.
  if (args.has("--scope")) {
    vernacular::Vec3 size{};
    for (std::size_t i = 0; i < 3; ++i) {
      size[i] = CommandLine::number(args, "--scope", i);
      if (size[i] < 0)
        throw Error(ErrorKind::Usage, "check: error: --scope sizes must be >= 0, got " + args.value("--scope", i) +
                                          "\n  hint: for example --scope 12 8 9 (metres along x, y, z)");
    }
    options.plot = size;
  }

  const vernacular::Grammar grammar = vernacular::Grammar::read(args.positional[0]);
  const std::vector<fs::path> files =
      vernacular::example_files(std::vector<fs::path>(args.positional.begin() + 1, args.positional.end()));
  std::size_t fits = 0, examples = 0;
  // File by file, each said as it is checked; a file of several buildings
  // is as many examples.
  std::vector<std::string> notes;
  for (const fs::path& file : files) {
    const std::vector<vernacular::Example> buildings = vernacular::read_examples({file}, reading);
    if (!buildings.empty()) notes.insert(notes.end(), buildings.front().notes().begin(), buildings.front().notes().end());
    for (const vernacular::Example& example : buildings) {
      ++examples;
      const vernacular::Verdict v = vernacular::check(grammar, example, options);
      if (v.derivable) {
        ++fits;
        std::cout << example.source() << ": derivable\n";
        if (!brief)
          for (const auto& line : v.witness) std::cout << "  " << line << "\n";
      } else {
        std::cout << example.source() << ": NOT derivable: " << v.reason << "\n";
      }
    }
  }
  print_notes("check", notes);
  std::cout << fits << " of " << examples << " example" << (examples == 1 ? "" : "s") << " derivable from "
            << args.positional[0] << "\n";
  return fits == examples ? 0 : kNotDerivable;
}

}  // namespace

int main(int argc, char** argv) { return guarded_main("check", run, argc, argv); }
