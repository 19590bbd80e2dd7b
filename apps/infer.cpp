// infer: labelled example buildings in, a grammar of their style out.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "base/alongside.hpp"
#include "base/files_read.hpp"
#include "base/folder_confinement.hpp"
#include "base/out_of_memory.hpp"
#include "base/parallel_for.hpp"
#include "graph/description_length.hpp"
#include "graph/reserved_words.hpp"
#include "graph/writer.hpp"
#include "inverse/infer.hpp"
#include "inverse/write/inferred_files.hpp"
#include "inverse/write/test_buildings.hpp"
#include "io/obj_writer.hpp"
#include "report/html_report.hpp"
#include "report/style_report.hpp"
#include "support/command_line.hpp"
#include "support/example_options.hpp"
#include "support/guarded_main.hpp"
#include "support/output_paths.hpp"

namespace fs = std::filesystem;
using namespace vern;

namespace {

CommandLine make_command_line() {
  CommandLine cl("infer", "infer EXAMPLES... -o STYLE.grm [options]",
                 "Reads example buildings whose parts are labelled (OBJ objects `o window`, or\n"
                 "named glTF nodes), finds how each is cut into its parts, merges the examples\n"
                 "and writes a grammar that derives each of them and new ones in their style,\n"
                 "plus the parts' meshes (STYLE.prims.obj) so the grammar alone regenerates them.\n"
                 "EXAMPLES are .obj, .gltf or .glb files, or folders of them.");
  cl.add({"--output", "-o", 1, "STYLE.grm", "the grammar to write (required)"});
  cl.add({"--primitives", "", 1, "PATH",
          "the parts' own meshes (a folder of NAME.obj, or one OBJ of named objects): a part whose\n"
          "mesh is its label's turned by quarter turns is written R(axis, angle){ I(label) }\n"
          "(default: the built-in meshes, else each label's first part)"});
  cl.add({"--primitives-out", "", 1, "FILE.obj", "where to write the parts' meshes (default: STYLE.prims.obj)"});
  cl.add({"--tolerance", "", 1, "METRES", "coordinates closer than this are equal (default: 1e-6 of the largest example's size or distance from the origin)"});
  cl.add({"--threads", "-j", 1, "N", "read and split examples with N threads (default: all cores; same result)"});
  cl.add({"--start", "", 1, "LABEL", "name of the start rule (default: building)"});
  cl.add({"--distributions", "", 1, "KIND",
          "fitted (default): each varying size as the best of constant, choice(...), rand, tnormal;\n"
          "uniform: rand(min, max) over the values seen, as the thesis"});
  cl.add({"--sizes", "", 1, "KIND",
          "joint (default): sizes the examples vary together are drawn once and shared, a split's\n"
          "parts that vary in one way only draw once (checks every example: slower);\n"
          "independent: each size drawn on its own"});
  cl.add({"--twins", "", 1, "KIND",
          "joined (default): parts built alike but for some numbers or an axis become one rule\n"
          "called with each part's values; apart: each written out in full"});
  cl.add({"--seed", "-s", 1, "S", "seed of the test derivations run on the result (default 1)"});
  cl.add({"--report", "", 1, "FILE.html",
          "also write a page to open in any browser, offline: pictures of the examples beside eight\n"
          "new buildings of the grammar (seeds S to S + 7), the grammar and its figures"});
  add_example_options(cl);
  cl.add_standard_options();
  cl.set_epilog(
      "examples:\n"
      "  infer data/examples/garage/*.obj -o garage.grm     # then: generate garage.grm -n 10 -o g.glb\n"
      "  infer my_buildings/ -o style.grm --tolerance 0.001\n"
      "\n"
      "exit codes: 0 success, 2 usage error, 3 bad input (an example file), 4 a limit was reached,\n"
      "            5 a file could not be read or written, 70 internal error\n");
  return cl;
}

[[noreturn]] void usage(const std::string& message, const std::string& hint = {}) {
  throw Error(ErrorKind::Usage, "infer: error: " + message + (hint.empty() ? "" : "\n  hint: " + hint));
}

int run(int argc, char** argv) {
  const CommandLine cl = make_command_line();
  const std::optional<ParsedCommandLine> parsed = cl.parse_or_answer(argc, argv);
  if (!parsed) return 0;
  const ParsedCommandLine& args = *parsed;
  if (!args.has("--output")) usage("no output grammar given", "add -o STYLE.grm");
  if (args.positional.empty()) usage("no examples given", "list .obj/.glb files or folders: infer examples/*.obj -o style.grm");
  const bool quiet = args.has("--quiet");
  const fs::path output = args.value("--output");
  const fs::path prims = args.has("--primitives-out") ? fs::path(args.value("--primitives-out"))
                                                      : meshes_path_for(output);
  if (prims.extension() != ".obj")
    usage("--primitives-out must name an .obj file, got " + prims.string(), "for example --primitives-out style.prims.obj");
  InferOptions options;
  if (args.has("--tolerance")) {
    options.tolerance = CommandLine::number(args, "--tolerance");
    if (!(options.tolerance > 0)) usage("--tolerance must be > 0, got " + args.value("--tolerance"), "for example --tolerance 0.001");
  }
  if (args.has("--threads")) options.threads = static_cast<unsigned>(CommandLine::integer(args, "--threads", 1, 1024));
  options.stack = stack_order(args);
  if (args.has("--distributions"))
    options.uniform_distributions = CommandLine::one_of(args, "--distributions", {"fitted", "uniform"}) == "uniform";
  if (args.has("--sizes"))
    options.joint_sizes = CommandLine::one_of(args, "--sizes", {"joint", "independent"}) == "joint";
  if (args.has("--twins"))
    options.twin_rules = CommandLine::one_of(args, "--twins", {"joined", "apart"}) == "joined";
  if (args.has("--start")) {
    options.start = args.value("--start");
    if (!is_rule_label(options.start))
      usage("--start '" + options.start + "' cannot be a rule label",
            "a label is a letter or '_' followed by letters, digits and '_', and not an operation word such as split");
  }
  ExampleLimits limits = example_limits(args);
  limits.tolerance = options.tolerance;
  const BuildingsMode buildings = buildings_mode(args);
  const std::uint64_t seed =
      args.has("--seed") ? static_cast<std::uint64_t>(CommandLine::integer(args, "--seed", 0, 1LL << 53)) : 1;

  const auto started = std::chrono::steady_clock::now();
  const std::vector<fs::path> files = example_files(args.positional);
  // Three files are written: the grammar, the meshes and their materials.
  const fs::path prims_mtl = mtl_path_for(prims);
  std::vector<fs::path> outputs = {output, prims, prims_mtl};
  const std::optional<fs::path> report = args.has("--report") ? std::optional<fs::path>(args.value("--report")) : std::nullopt;
  if (report) {
    if (report->extension() != ".html" && report->extension() != ".htm")
      usage("--report must name an .html file, got " + report->string(), "for example --report style.html");
    outputs.push_back(*report);
  }
  for (const fs::path& out : outputs) {
    check_output_file("infer", out, files, "an example");
    if (args.has("--primitives")) {
      check_output_file("infer", out, {fs::path(args.value("--primitives"))}, "the --primitives meshes");
    }
  }
  check_distinct_outputs("infer", outputs);

  const bool show_progress = !quiet && files.size() >= 20 && isatty(STDERR_FILENO);
  // Read in parallel; the first unreadable file (in the order given) is
  // the one reported, whatever the thread count.
  std::vector<Example> examples(files.size());
  // One file alone gets a second thread of its own, to read its text ahead
  // (a million-part OBJ is a quarter of the time); several share them.
  const unsigned per_file = files.size() == 1 ? options.threads : 1;
  parallel_for(
      files.size(), options.threads, [&](std::size_t i) { examples[i] = load_example(files[i], limits, per_file); },
      [&](std::size_t done) {
        if (show_progress && (done % 10 == 0 || done == files.size()))
          std::fprintf(stderr, "\rreading examples %zu/%zu", done, files.size());
      });
  if (show_progress) std::fprintf(stderr, "\n");
  // A file of several buildings is as many examples (scene_buildings.hpp).
  std::vector<std::string> notes;
  examples = examples_of_files(std::move(examples), buildings, options.tolerance, notes);
  if (!quiet) print_notes("infer", notes);
  PrimitiveLibrary library = PrimitiveLibrary::builtin();
  if (args.has("--primitives")) library.load(args.value("--primitives"));
  options.primitives = &library;
  // Every file read is an input, not only those named: a buffer a glTF
  // names, a mesh of the --primitives folder. Said before inferring.
  for (const fs::path& out : outputs) refuse_file_read(out);
  // Out of memory, the examples are named: the one, or the first and last.
  const std::string named = files.size() == 1 ? "this example"
                                              : std::to_string(files.size()) + " examples (" + files.front().string() +
                                                    " ... " + files.back().string() + ")";
  Inference result = naming_out_of_memory(files.size() == 1 ? files.front().string() : "infer",
                                          "inferring a grammar from " + named,
                                          "infer from fewer or smaller examples at once", [&] { return infer(examples, options); });
  if (!quiet)
    for (const std::string& w : result.warnings) std::fprintf(stderr, "%s\n", w.c_str());
  if (result.unturned_parts > 0 && !quiet)
    std::fprintf(stderr,
                 "infer: warning: %zu part%s whose mesh is not its label's turned by quarter turns: written "
                 "unturned\n  hint: give such parts their own label, or pass their meshes with --primitives\n",
                 result.unturned_parts, result.unturned_parts == 1 ? "" : "s");

  // Derive a few buildings from the result while its text is made: a
  // grammar that cannot derive is a bug, better found here than by the user
  // (its error comes first, as if derived before writing); one that reaches
  // a limit is written with a warning (inverse/write/test_buildings.hpp). One
  // building alone when the examples are large (a million parts: a third
  // of a second).
  std::size_t parts = 0, largest = 0;
  for (const Example& e : examples) {
    parts += e.boxes.size();
    largest = std::max(largest, e.boxes.size());
  }
  const std::size_t example_count = examples.size();
  // Done with the examples (their boxes, positions and meshes: 115 MB at
  // a million parts), freed before the derivation and the text take theirs,
  // unless the report shows them.
  if (!report) examples = {};
  const TestBuildingsOptions tests = test_buildings_for(parts, largest, seed);
  result.grammar.primitives = path_from(output, prims);
  // generate follows @primitives only into the grammar's own folder.
  if (!quiet && !path_in_folder(output.parent_path(), result.grammar.primitives))
    std::fprintf(stderr,
                 "infer: warning: the grammar names its meshes as '%s', outside its folder: generate reads them "
                 "only with --allow-outside-files\n  hint: write the meshes beside the grammar (--primitives-out)\n",
                 result.grammar.primitives.c_str());
  std::string grammar_text;
  std::vector<std::string> test_warnings;
  run_alongside(
      options.threads, [&] { test_warnings = derive_test_buildings(result.grammar, tests); },
      [&] { grammar_text = write_grammar(result.grammar); });
  if (!quiet)
    for (const std::string& w : test_warnings) std::fprintf(stderr, "%s\n", w.c_str());

  const std::string header = inferred_header(example_count, result.tolerance, output);
  const std::size_t lines = static_cast<std::size_t>(std::count(header.begin(), header.end(), '\n') +
                                                     std::count(grammar_text.begin(), grammar_text.end(), '\n'));
  // How much the grammar says (graph/description_length.hpp): what
  // `evaluate` reports too, so styles can be compared by it.
  const DescriptionLength dl = description_length(result.grammar);
  std::string page;
  if (report) {
    StyleReportInput in;
    in.title = output.filename().string();
    in.grammar_text = header + grammar_text;
    in.grammar = &result.grammar;
    in.primitives = &result.primitives;
    in.examples = &examples;
    in.layering = {options.stack, options.tolerance};
    in.figures = {{"examples", std::to_string(example_count)},
                  {"parts in the examples", std::to_string(parts)},
                  {"rules", std::to_string(result.grammar.rules.size())},
                  {"lines", std::to_string(lines)},
                  {"description length", std::to_string(dl.total()) + " (" + std::to_string(dl.operations) +
                                             " operations, " + std::to_string(dl.numbers) + " numbers)"}};
    in.notes = result.warnings;
    in.notes.insert(in.notes.end(), test_warnings.begin(), test_warnings.end());
    in.first_seed = seed;
    in.threads = options.threads;
    page = report_html(style_report(in));
  }
  std::vector<AlsoWritten> also;
  if (report) also.push_back({*report, page});
  write_inferred(result.primitives, header, grammar_text, output, prims, also);

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!quiet) {
    std::fprintf(stderr,
                 "infer: %zu example%s -> %s: %zu rules, %zu lines, description length %zu (%zu operations, %zu "
                 "numbers); meshes -> %s (%.2f s)\n",
                 example_count, example_count == 1 ? "" : "s", output.string().c_str(), result.grammar.rules.size(),
                 lines, dl.total(), dl.operations, dl.numbers, prims.string().c_str(), seconds);
    if (report) std::fprintf(stderr, "infer: report -> %s (open it in any browser)\n", report->string().c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return guarded_main("infer", run, argc, argv); }
