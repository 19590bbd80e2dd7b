// evaluate: how well does inference learn each grammar's style? For each
// grammar: derive k examples, infer a grammar from them, check it
// reproduces them, derive n variants, and report a Markdown table
// (docs/evaluation.md holds the bundled grammars' table).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <limits>
#include <map>
#include <sstream>
#include <thread>

#include "base/atomic_file.hpp"
#include "base/error.hpp"
#include "eval/class_means.hpp"
#include "eval/evaluation.hpp"
#include "eval/precision_recall.hpp"
#include "eval/random_grammar.hpp"
#include "eval/random_style.hpp"
#include "forward/primitive_sources.hpp"
#include "graph/parser.hpp"
#include "report/html_report.hpp"
#include "report/round_trip_report.hpp"
#include "support/command_line.hpp"
#include "support/guarded_main.hpp"
#include "support/output_paths.hpp"

namespace fs = std::filesystem;
using namespace vern;

namespace {

CommandLine make_command_line() {
  CommandLine cl("evaluate", "evaluate GRAMMAR.grm... [-k EXAMPLES] [-n VARIANTS] [--keep FOLDER]",
                 "Round-trips each grammar through inference and prints one Markdown table row per grammar:\n"
                 "k examples (seeds 1..k) -> infer -> check each -> n variants (seeds 1001..) judged for\n"
                 "validity, novelty and closeness to the source grammar's own variants.");
  cl.add({"--examples", "-k", 1, "K", "examples per grammar (default 10)"});
  cl.add({"--variants", "-n", 1, "N", "variants judged per grammar (default 100)"});
  cl.add({"--threads", "-j", 1, "N", "derive with N threads (default: all cores; results are the same)"});
  cl.add({"--distributions", "", 1, "KIND", "fitted (default) or uniform: how inference writes varying sizes"});
  cl.add({"--keep", "", 1, "FOLDER", "also write each inferred grammar to FOLDER/NAME.grm (NAME.N.grm with --precision-recall)"});
  cl.add({"--report", "", 1, "FILE.html",
          "also write a page to open in any browser, offline: the table, and for each grammar pictures of\n"
          "its examples beside the learnt grammar's variants, and the learnt grammar (not with\n"
          "--precision-recall)"});
  cl.add({"--precision-recall", "", 0, "", "instead: precision and recall against the source, per example count"});
  cl.add({"--counts", "", 1, "N,N,...", "with --precision-recall: example counts (default 3,10,30)"});
  cl.add({"--samples", "", 1, "S", "with --precision-recall: variants and fresh samples judged (default 40)"});
  cl.add({"--random", "", 1, "N", "with --precision-recall: also N random grammars (seeds 1..N, plots within 30 %)"});
  cl.add({"--random-rules", "", 1, "R", "rules per random grammar (default 8)"});
  cl.add({"--random-styles", "", 1, "K",
          "with --precision-recall: also K random styles (random_style.hpp), with a table per class"});
  cl.add({"--seed", "", 1, "S", "the seed of --random-styles: required, chosen when measuring, never tuned on"});
  cl.add({"--random-styles-write", "", 1, "FOLDER",
          "write the K random styles to FOLDER/random_style_I.grm (alone: only write them)"});
  cl.add_standard_options();
  cl.set_epilog(
      "columns:\n"
      "  rules, DL      rules and description length (operations + numbers) of source -> inferred\n"
      "  lines          lines of the inferred grammar as infer writes it\n"
      "  reproduced     examples the inferred grammar derives exactly (check)\n"
      "  valid          variants with no overlapping parts and none outside the plot\n"
      "                 (the source grammar's own rate in brackets)\n"
      "  novel          variants equal to no example ('-' when the source never varies)\n"
      "  structure, sizes  distance of the variants' part counts and part sizes from the source\n"
      "                 grammar's (relative earth mover's distance; the source against itself in brackets)\n"
      "\n"
      "columns with --precision-recall (one row per grammar and example count N):\n"
      "  self           fresh source samples the source derives on their extents (1.00: a fair judge)\n"
      "  reproduced     examples the inferred grammar derives exactly\n"
      "  precision      inferred variants, on the examples' plots, that the source derives\n"
      "  wider          the same on plots 1.5 times as wide\n"
      "  recall         fresh source samples (seeds 5001..) that the inferred grammar derives\n"
      "  invalid        inferred variants with overlapping parts or parts outside the plot\n"
      "\n"
      "with --random-styles, then a table per class (docs/evaluation.md, \"Random styles\"): the styles\n"
      "containing it and their mean precision and recall per N (an inference that failed scores 0), a row\n"
      "for all random styles, and how many have precision <= 0.25 at the largest N\n"
      "\n"
      "examples:\n"
      "  evaluate data/grammars/*.grm -k 10 -n 100\n"
      "  evaluate data/styles/dev/*.grm --precision-recall --counts 3,10,30\n"
      "  evaluate --precision-recall --random 20 --counts 10,30\n"
      "  evaluate --precision-recall --random-styles 300 --seed $(date +%s)\n");
  return cl;
}

std::string percent(std::uint32_t part, std::uint32_t whole) {
  return whole == 0 ? "-" : std::to_string((part * 100 + whole / 2) / whole) + " %";
}

std::string fixed(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", v);
  return buffer;
}

std::string two_places(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}

std::vector<std::uint32_t> example_counts(const ParsedCommandLine& args) {
  if (!args.has("--counts")) return {3, 10, 30};
  std::vector<std::uint32_t> counts;
  std::istringstream in(args.value("--counts"));
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const long n = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || n < 1 || n > 1000)
      throw Error(ErrorKind::Usage, "evaluate: error: --counts takes example counts 1..1000 separated by commas, not '" +
                                        args.value("--counts") + "'\n  hint: --counts 3,10,30");
    counts.push_back(static_cast<std::uint32_t>(n));
  }
  return counts;
}

// --random-styles K --seed S: the K styles, each with a seed mixed from S
// and its index. The seed has no default: it is chosen when measuring.
std::vector<RandomStyle> random_styles(const ParsedCommandLine& args) {
  if (!args.has("--random-styles")) {
    for (const char* option : {"--seed", "--random-styles-write"})
      if (args.has(option))
        throw Error(ErrorKind::Usage, std::string("evaluate: error: ") + option +
                                          " goes with --random-styles\n  hint: --random-styles 300 --seed $(date +%s)");
    return {};
  }
  if (!args.has("--seed"))
    throw Error(ErrorKind::Usage,
                "evaluate: error: --random-styles needs --seed S, a seed chosen now and never tuned on\n"
                "  hint: --random-styles " +
                    args.value("--random-styles") + " --seed $(date +%s)");
  const auto count = static_cast<std::uint32_t>(CommandLine::integer(args, "--random-styles", 1, 100000));
  const auto seed = static_cast<std::uint64_t>(CommandLine::integer(args, "--seed", 0, std::numeric_limits<long long>::max()));
  std::vector<RandomStyle> styles;
  for (std::uint32_t i = 0; i < count; ++i) styles.push_back(random_style(random_style_seed(seed, i)));
  return styles;
}

std::string style_name(std::size_t index) { return "random_style_" + std::to_string(index); }

// Every file this run writes, checked before any work: none may be a
// grammar evaluated, and no two may be one file (only the last written
// would be left). --keep writes FOLDER/NAME.grm per grammar, NAME.N.grm
// per example count N with --precision-recall (random grammars are
// random_SEED, random styles random_style_I); --random-styles-write writes
// FOLDER/random_style_I.grm.
void check_written_files(const ParsedCommandLine& args, std::size_t styles) {
  const std::vector<fs::path> grammars(args.positional.begin(), args.positional.end());
  std::map<std::string, std::string> written;  // the file, its folder resolved -> what is written there
  auto add = [&](const fs::path& folder, const fs::path& real, const std::string& file, const std::string& what) {
    const auto [it, fresh] = written.try_emplace((real / file).string(), what);
    if (!fresh)
      throw Error(ErrorKind::Usage, "evaluate: error: " + it->second + " and " + what + " would both be written to " +
                                        (folder / file).string() +
                                        "\n  hint: rename one of the grammars, or write them to separate folders");
    check_output_file("evaluate", folder / file, grammars, "the grammar file");
  };
  std::error_code ec;
  if (args.has("--random-styles-write")) {
    const fs::path folder = args.value("--random-styles-write");
    const fs::path real = fs::canonical(folder, ec);
    for (std::size_t i = 0; i < styles; ++i)
      add(folder, real, style_name(i) + ".grm", "random style " + std::to_string(i));
  }
  if (!args.has("--keep")) return;
  const fs::path folder = args.value("--keep");
  const fs::path real = fs::canonical(folder, ec);
  std::vector<std::string> suffixes = {".grm"};
  if (args.has("--precision-recall")) {
    suffixes.clear();
    for (const std::uint32_t count : example_counts(args)) suffixes.push_back("." + std::to_string(count) + ".grm");
  }
  auto keep = [&](const std::string& name, const std::string& source) {
    for (const std::string& suffix : suffixes) add(folder, real, name + suffix, "the grammar inferred from " + source);
  };
  for (const std::string& file : args.positional) keep(fs::path(file).stem().string(), file);
  if (!args.has("--precision-recall")) return;
  if (args.has("--random"))
    for (long long seed = 1, n = CommandLine::integer(args, "--random", 1, 100000); seed <= n; ++seed)
      keep("random_" + std::to_string(seed), "random grammar " + std::to_string(seed));
  for (std::size_t i = 0; i < styles; ++i) keep(style_name(i), "random style " + std::to_string(i));
}

// For each class, the styles that contain it and their mean precision and
// recall per N; then all styles, and how many are at 0.25 or below.
void print_class_table(const std::vector<StyleScores>& scores, const std::vector<std::uint32_t>& counts) {
  const ClassTable t = class_means(scores, counts);
  std::cout << "\n| class | styles |";
  for (std::uint32_t n : counts) std::cout << " precision N = " << n << " | recall N = " << n << " |";
  std::cout << "\n|---|---|";
  for (std::size_t c = 0; c < counts.size(); ++c) std::cout << "---|---|";
  std::cout << "\n";
  auto row = [&](std::string_view name, const ClassMeans& m) {
    std::cout << "| " << name << " | " << m.styles << " |";
    for (std::size_t c = 0; c < counts.size(); ++c)
      std::cout << " " << (m.styles ? two_places(m.precision[c]) : "-") << " | "
                << (m.styles ? two_places(m.recall[c]) : "-") << " |";
    std::cout << "\n";
  };
  for (std::size_t i = 0; i < kStyleClasses.size(); ++i) row(kStyleClasses[i].name, t.classes[i]);
  row("all random styles", t.all);
  std::cout << "\nRandom styles with precision <= 0.25 at N = " << *std::max_element(counts.begin(), counts.end())
            << ": " << t.low_precision << " of " << scores.size() << "\n";
}

// Per N, the mean of each score over the grammars, and the lowest.
struct Means {
  double precision = 0, wider = 0, recall = 0, lowest = 1;
  int grammars = 0;
};

int run_precision_recall(const ParsedCommandLine& args, unsigned threads, bool quiet,
                         const std::vector<RandomStyle>& styles) {
  PrecisionRecallOptions options;
  options.threads = threads;
  if (args.has("--samples"))
    options.samples = static_cast<std::uint32_t>(CommandLine::integer(args, "--samples", 1, 100000));
  const std::vector<std::uint32_t> counts = example_counts(args);
  std::vector<Means> means(counts.size());

  std::cout << "| grammar | N | rules | lines | self | reproduced | precision | wider | recall | invalid |\n"
               "|---|---|---|---|---|---|---|---|---|---|\n";
  // The grammars named, then the random ones (random_grammar.hpp).
  std::vector<std::pair<std::string, Grammar>> sources;
  for (const std::string& file : args.positional) sources.emplace_back(fs::path(file).stem().string(), read_grammar_file(file));
  if (args.has("--random")) {
    GrammarOptions random;
    random.varied_plots = true;
    if (args.has("--random-rules"))
      random.rules = static_cast<std::size_t>(CommandLine::integer(args, "--random-rules", 1, 1000));
    else
      random.rules = 8;
    const auto count = CommandLine::integer(args, "--random", 1, 100000);
    for (long long seed = 1; seed <= count; ++seed) {
      random.seed = static_cast<std::uint64_t>(seed);
      const std::string name = "random_" + std::to_string(seed);
      sources.emplace_back(name, parse_grammar(random_grammar(random), name));
    }
  }
  // The random styles last: source first_style + i is style i.
  const std::size_t first_style = sources.size();
  for (std::size_t i = 0; i < styles.size(); ++i)
    sources.emplace_back(style_name(i), parse_grammar(styles[i].text, style_name(i)));
  std::vector<StyleScores> scores(styles.size());
  for (std::size_t i = 0; i < styles.size(); ++i)
    scores[i] = {styles[i].classes, std::vector<double>(counts.size(), 0.0), std::vector<double>(counts.size(), 0.0)};
  std::ostringstream notes;
  int failures = 0;
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const auto& [name, source] = sources[s];
    StyleScores* style = s >= first_style ? &scores[s - first_style] : nullptr;
    const auto started = std::chrono::steady_clock::now();
    const Share self = self_recall(source, options);
    if (self.hits != self.total) notes << "- " << name << ": the source does not derive its own " << self.first_miss << "\n";
    for (std::size_t c = 0; c < counts.size(); ++c) {
      options.examples = counts[c];
      PrecisionRecall r;
      try {
        r = precision_recall(source, options);
      } catch (const Error& error) {
        std::cout << "| " << name << " | " << counts[c] << " | - | - | - | inference failed | - | - | - | - |\n";
        notes << "- " << name << ", N = " << counts[c] << ": " << error.what() << "\n";
        ++failures;
        continue;
      }
      std::cout << "| " << name << " | " << counts[c] << " | " << r.inferred.rules << " | " << r.inferred_lines << " | "
                << two_places(self.value()) << " | " << r.reproduced << "/" << r.examples << " | "
                << two_places(r.precision.value()) << " | " << two_places(r.precision_wider.value()) << " | "
                << two_places(r.recall.value()) << " | " << r.invalid << " |" << std::endl;
      if (args.has("--keep"))
        write_file_atomically(fs::path(args.value("--keep")) / (name + "." + std::to_string(counts[c]) + ".grm"),
                              r.inferred_text);
      const std::string at = "- " + name + ", N = " + std::to_string(counts[c]) + ": ";
      if (!r.first_unreproduced.empty()) notes << at << "not reproduced: " << r.first_unreproduced << "\n";
      if (!r.precision.first_miss.empty()) notes << at << "imprecise: " << r.precision.first_miss << "\n";
      if (!r.recall.first_miss.empty()) notes << at << "not recalled: " << r.recall.first_miss << "\n";
      if (!r.first_invalid.empty()) notes << at << "invalid: " << r.first_invalid << "\n";
      if (r.reproduced != r.examples || r.invalid != 0) ++failures;
      Means& m = means[c];
      m.precision += r.precision.value();
      m.wider += r.precision_wider.value();
      m.recall += r.recall.value();
      m.lowest = std::min({m.lowest, r.precision.value(), r.recall.value()});
      ++m.grammars;
      if (style) {
        style->precision[c] = r.precision.value();
        style->recall[c] = r.recall.value();
      }
    }
    if (!quiet) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      std::fprintf(stderr, "evaluate: %s (%.1f s)\n", name.c_str(), seconds);
    }
  }
  std::cout << "\n| N | grammars | mean precision | mean wider | mean recall | lowest |\n|---|---|---|---|---|---|\n";
  for (std::size_t c = 0; c < counts.size(); ++c) {
    const Means& m = means[c];
    if (m.grammars == 0) continue;
    std::cout << "| " << counts[c] << " | " << m.grammars << " | " << two_places(m.precision / m.grammars) << " | "
              << two_places(m.wider / m.grammars) << " | " << two_places(m.recall / m.grammars) << " | "
              << two_places(m.lowest) << " |\n";
  }
  if (!styles.empty()) print_class_table(scores, counts);
  if (!notes.str().empty()) std::cout << "\n" << notes.str();
  return failures == 0 ? 0 : 1;
}

int run(int argc, char** argv) {
  const CommandLine cl = make_command_line();
  const std::optional<ParsedCommandLine> parsed = cl.parse_or_answer(argc, argv);
  if (!parsed) return 0;
  const ParsedCommandLine& args = *parsed;
  const std::vector<RandomStyle> styles = random_styles(args);
  if (!styles.empty() && !args.has("--precision-recall") && !args.has("--random-styles-write"))
    throw Error(ErrorKind::Usage,
                "evaluate: error: --random-styles goes with --precision-recall or --random-styles-write\n"
                "  hint: evaluate --precision-recall --random-styles " +
                    args.value("--random-styles") + " --seed " + args.value("--seed"));
  const bool random = args.has("--random") || !styles.empty();
  if (args.positional.empty() && !(args.has("--precision-recall") && random) && styles.empty())
    throw Error(ErrorKind::Usage, "evaluate: error: no grammar given\n  hint: evaluate data/grammars/*.grm");
  EvaluationOptions options;
  if (args.has("--examples"))
    options.examples = static_cast<std::uint32_t>(CommandLine::integer(args, "--examples", 1, 10000));
  if (args.has("--variants"))
    options.variants = static_cast<std::uint32_t>(CommandLine::integer(args, "--variants", 1, 100000));
  if (args.has("--threads")) options.threads = static_cast<unsigned>(CommandLine::integer(args, "--threads", 1, 1024));
  if (args.has("--distributions"))
    options.uniform_distributions = CommandLine::one_of(args, "--distributions", {"fitted", "uniform"}) == "uniform";
  const bool quiet = args.has("--quiet");
  std::error_code ec;
  if (args.has("--keep") && !fs::is_directory(args.value("--keep"), ec))
    throw Error(ErrorKind::Io, args.value("--keep") + ": error: not an existing folder\n  hint: create it first");
  if (args.has("--random-styles-write") && !fs::is_directory(args.value("--random-styles-write"), ec))
    throw Error(ErrorKind::Io,
                args.value("--random-styles-write") + ": error: not an existing folder\n  hint: create it first");
  check_written_files(args, styles.size());
  std::optional<fs::path> report;
  if (args.has("--report")) {
    report = args.value("--report");
    if (args.has("--precision-recall"))
      throw Error(ErrorKind::Usage, "evaluate: error: --report goes with the round trips' table, not --precision-recall\n"
                                    "  hint: keep the grammars inferred with --keep FOLDER");
    if (report->extension() != ".html" && report->extension() != ".htm")
      throw Error(ErrorKind::Usage, "evaluate: error: --report must name an .html file, got " + report->string() +
                                        "\n  hint: for example --report evaluation.html");
    check_output_file("evaluate", *report, std::vector<fs::path>(args.positional.begin(), args.positional.end()),
                      "the grammar file");
  }
  if (args.has("--random-styles-write")) {
    const fs::path folder = args.value("--random-styles-write");
    for (std::size_t i = 0; i < styles.size(); ++i)
      write_file_atomically(folder / (style_name(i) + ".grm"), styles[i].text);
    if (!args.has("--precision-recall") && args.positional.empty()) return 0;
  }
  if (args.has("--precision-recall")) return run_precision_recall(args, options.threads, quiet, styles);

  std::cout << "| grammar | rules | DL | lines | reproduced | valid | novel | structure | sizes |\n"
               "|---|---|---|---|---|---|---|---|---|\n";
  Report page;
  page.title = "Round trips";
  page.intro = "Each grammar derives " + std::to_string(options.examples) +
               " examples (seeds 1 to " + std::to_string(options.examples) +
               "), a grammar is inferred from them, and " + std::to_string(options.variants) +
               " variants of each grammar (seeds 1001 on) are compared (docs/evaluation.md says how to read the "
               "columns). In brackets: the source grammar's own figure.";
  page.table_head = {"grammar", "rules", "DL", "lines", "reproduced", "valid", "novel", "structure", "sizes"};
  std::ostringstream notes;
  int failures = 0;
  for (const std::string& file : args.positional) {
    const auto started = std::chrono::steady_clock::now();
    const std::string name = fs::path(file).stem().string();
    const Grammar source = read_grammar_file(file);
    Evaluation e;
    try {
      e = evaluate_inference(source, options);
    } catch (const Error& error) {
      std::cout << "| " << name << " | " << source.rules.size() << " | - | - | inference failed | - | - | - | - |\n";
      notes << "- " << name << ": " << error.what() << "\n";
      page.table_rows.push_back({name, std::to_string(source.rules.size()), "-", "-", "inference failed", "-", "-", "-", "-"});
      if (report) page.sections.push_back({name, {}, {error.what()}, {}, {}, {}});
      ++failures;
      continue;
    }
    if (args.has("--keep")) write_file_atomically(fs::path(args.value("--keep")) / (name + ".grm"), e.inferred_text);
    std::cout << "| " << name << " | " << e.source.rules << " → " << e.inferred.rules << " | " << e.source.total()
              << " → " << e.inferred.total() << " | " << e.inferred_lines << " | " << e.reproduced << "/"
              << e.examples << " | " << percent(e.valid, e.variants) << " (" << percent(e.source_valid, e.variants)
              << ") | " << (e.source_varies ? percent(e.novel, e.variants) : "-") << " | " << fixed(e.distance.structure)
              << " (" << fixed(e.noise.structure) << ") | " << fixed(e.distance.sizes) << " (" << fixed(e.noise.sizes)
              << ") |" << std::endl;
    if (!e.first_unreproduced.empty()) notes << "- " << name << ": not reproduced: " << e.first_unreproduced << "\n";
    if (!e.first_fault.empty()) notes << "- " << name << ": first invalid variant: " << e.first_fault << "\n";
    const std::vector<std::string> row = {
        name,
        std::to_string(e.source.rules) + " → " + std::to_string(e.inferred.rules),
        std::to_string(e.source.total()) + " → " + std::to_string(e.inferred.total()),
        std::to_string(e.inferred_lines),
        std::to_string(e.reproduced) + "/" + std::to_string(e.examples),
        percent(e.valid, e.variants) + " (" + percent(e.source_valid, e.variants) + ")",
        e.source_varies ? percent(e.novel, e.variants) : "-",
        fixed(e.distance.structure) + " (" + fixed(e.noise.structure) + ")",
        fixed(e.distance.sizes) + " (" + fixed(e.noise.sizes) + ")"};
    page.table_rows.push_back(row);
    if (report) {
      const Grammar learnt = parse_grammar(e.inferred_text, name + " (learnt)");
      const PrimitiveLibrary meshes = primitives_for(source, file, std::nullopt, false);
      RoundTripInput in;
      in.name = name;
      in.source = &source;
      in.learnt = &learnt;
      in.primitives = &meshes;
      in.learnt_text = e.inferred_text;
      for (std::size_t c = 1; c < row.size(); ++c) in.figures.emplace_back(page.table_head[c], row[c]);
      if (!e.first_unreproduced.empty()) in.notes.push_back("not reproduced: " + e.first_unreproduced);
      if (!e.first_fault.empty()) in.notes.push_back("first invalid variant: " + e.first_fault);
      in.shown = std::min<std::uint32_t>(6, options.examples);
      in.threads = options.threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : options.threads;
      page.sections.push_back(round_trip_section(in));
    }
    if (e.reproduced != e.examples) ++failures;
    if (!quiet) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      std::fprintf(stderr, "evaluate: %s (%.1f s)\n", name.c_str(), seconds);
    }
  }
  if (!notes.str().empty()) std::cout << "\n" << notes.str();
  if (report) {
    write_file_atomically(*report, report_html(page));
    if (!quiet) std::fprintf(stderr, "evaluate: report -> %s (open it in any browser)\n", report->string().c_str());
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) { return guarded_main("evaluate", run, argc, argv); }
