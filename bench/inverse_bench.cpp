// Inference at scale: ordered-box splitting alone (1k to 1M synthetic
// parts, to show n log n), loading OBJ, merging, infer in memory and the
// infer command end to end, on the ten bundled skyscraper-city examples
// (about 20,000 parts) and on one synthetic 1,000,000-part example.
// Run: scripts/bench (Release build), or build/bin/vern_bench.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <map>

#include "base/atomic_file.hpp"
#include "child_process.hpp"
#include "inverse/infer.hpp"
#include "inverse/load/example.hpp"
#include "inverse/load/scene_buildings.hpp"
#include "inverse/merge/merge.hpp"
#include "inverse/split/box_split.hpp"
#include "inverse/split/split_graph.hpp"
#include "table_row.hpp"
#include "workload.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;

// ---- inputs, built once and kept (before any meter is reset) ----

std::vector<fs::path> city_files() { return example_files({VERN_SOURCE_DIR "/data/examples/skyscraper_city"}); }

const std::vector<Example>& city() {
  static const std::vector<Example> examples = [] {
    std::vector<Example> out;
    for (const auto& f : city_files()) out.push_back(load_example(f));
    return out;
  }();
  return examples;
}

std::size_t parts(const std::vector<Example>& examples) {
  std::size_t n = 0;
  for (const auto& e : examples) n += e.boxes.size();
  return n;
}

// The synthetic layout of n parts (default options, seed 1), in memory.
const std::vector<LabelledBox>& layout(std::size_t n) {
  static std::map<std::size_t, std::vector<LabelledBox>> made;
  auto it = made.find(n);
  if (it == made.end()) {
    LayoutOptions o;
    o.boxes = n;
    it = made.emplace(n, random_layout(o)).first;
  }
  return it->second;
}

// ... and as a labelled OBJ file, written once into $VERN_BENCH_CACHE (or
// the temporary folder): the same options always give the same file.
fs::path layout_file(std::size_t n) {
  const char* env = std::getenv("VERN_BENCH_CACHE");
  const fs::path folder = env != nullptr ? fs::path(env) : fs::temp_directory_path() / "vernacular-bench";
  fs::create_directories(folder);
  const fs::path file = folder / ("layout_" + std::to_string(n) + "_seed1.obj");
  if (!fs::exists(file)) write_file_atomically(file, layout_obj(layout(n)));
  return file;
}

Example layout_example(std::size_t n) {
  Example e;
  e.source = "layout_" + std::to_string(n);
  e.boxes = layout(n);
  update_bounds(e);
  return e;
}

// ---- ordered-box splitting ----

void BM_SplitBoxes(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<LabelledBox>& boxes = layout(n);
  Example e;
  e.boxes = boxes;
  update_bounds(e);
  const BoxSplitOptions options{default_tolerance(e)};
  e = {};
  auto run = [&] {
    SplitTree t = split_boxes(boxes, options);
    benchmark::DoNotOptimize(t.children.data());
  };
  for (auto _ : state) run();
  report_row(state, static_cast<double>(n), "parts", peak_heap_of(state.range(0), run));
}
BENCHMARK(BM_SplitBoxes)->RangeMultiplier(10)->Range(1000, 1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SplitCity(benchmark::State& state) {
  const auto& examples = city();
  auto run = [&] {
    for (const auto& e : examples) {
      SplitTree t = split_boxes(e.boxes, BoxSplitOptions{default_tolerance(e)});
      benchmark::DoNotOptimize(t.children.data());
    }
  };
  for (auto _ : state) run();
  report_row(state, static_cast<double>(parts(examples)), "parts", peak_heap_of(0, run));
}
BENCHMARK(BM_SplitCity)->Unit(benchmark::kMillisecond)->UseRealTime();

// ---- loading ----

void BM_LoadObj(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const fs::path file = layout_file(n);
  ExampleLimits limits;
  limits.max_parts = n;
  auto run = [&] { benchmark::DoNotOptimize(load_example(file, limits).boxes.data()); };
  for (auto _ : state) run();
  report_row(state, static_cast<double>(n), "parts", peak_heap_of(state.range(0), run));
}
BENCHMARK(BM_LoadObj)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime();

// Looking for buildings standing apart among a file's parts (what infer
// and check do to every file read), each part a group of its own as in a
// Blender export: the layout is one building, so this is the whole cost.
void BM_SceneBuildings(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Example e = layout_example(n);
  const double tolerance = default_tolerance(e);
  for (auto _ : state) {
    state.PauseTiming();
    Example file = e;  // the file as read, which the command hands over
    state.ResumeTiming();
    const SceneBuildings s = scene_buildings(std::move(file), BuildingsMode::Parts, tolerance);
    benchmark::DoNotOptimize(s.buildings.data());
  }
  Example file = e;
  reset_peak_heap();
  { const SceneBuildings s = scene_buildings(std::move(file), BuildingsMode::Parts, tolerance); }
  report_row(state, static_cast<double>(n), "parts", static_cast<double>(peak_heap_since_reset()));
}
BENCHMARK(BM_SceneBuildings)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_LoadCity(benchmark::State& state) {
  const auto files = city_files();
  const double n = static_cast<double>(parts(city()));
  auto run = [&] {
    std::vector<Example> examples;
    for (const auto& f : files) examples.push_back(load_example(f));
    benchmark::DoNotOptimize(examples.data());
  };
  for (auto _ : state) run();
  report_row(state, n, "parts", peak_heap_of(0, run));
}
BENCHMARK(BM_LoadCity)->Unit(benchmark::kMillisecond)->UseRealTime();

// ---- merging and simplifying (the examples' graphs built untimed) ----

void BM_MergeCity(benchmark::State& state) {
  const auto& examples = city();
  double tolerance = 0;
  for (const auto& e : examples) tolerance = std::max(tolerance, default_tolerance(e));
  MergeOptions options;
  options.tolerance = tolerance;
  auto graphs = [&](Grammar& g) {
    std::vector<NodeId> roots;
    for (const auto& e : examples) roots.push_back(example_graph(g, e, BoxSplitOptions{tolerance}));
    return roots;
  };
  for (auto _ : state) {
    state.PauseTiming();
    Grammar g;
    const std::vector<NodeId> roots = graphs(g);
    state.ResumeTiming();
    benchmark::DoNotOptimize(merge_examples(g, roots, options));
  }
  // The peak includes the graphs merging works on (as in infer).
  report_row(state, static_cast<double>(parts(examples)), "parts", peak_heap_of(0, [&] {
               Grammar g;
               const std::vector<NodeId> roots = graphs(g);
               benchmark::DoNotOptimize(merge_examples(g, roots, options));
             }));
}
BENCHMARK(BM_MergeCity)->Unit(benchmark::kMillisecond)->UseRealTime();

// ---- infer in memory: split, merge, tidy, name ----

void BM_InferCity(benchmark::State& state) {
  const auto& examples = city();
  std::size_t rules = 0;
  auto run = [&] { rules = infer(examples, {}).grammar.rules.size(); };
  for (auto _ : state) run();
  report_row(state, static_cast<double>(parts(examples)), "parts", peak_heap_of(0, run));
  state.counters["rules"] = static_cast<double>(rules);
}
BENCHMARK(BM_InferCity)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_InferLayout(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<Example> examples{layout_example(n)};
  auto run = [&] { benchmark::DoNotOptimize(infer(examples, {}).grammar.rules.size()); };
  for (auto _ : state) run();
  report_row(state, static_cast<double>(n), "parts", peak_heap_of(state.range(0), run));
}
BENCHMARK(BM_InferLayout)->Arg(100'000)->Arg(1'000'000)->Repetitions(3)->Unit(benchmark::kMillisecond)->UseRealTime();

// n examples of 30 parts, each of another structure (layouts of seeds
// 1..n): merging keeps them as n alternatives, and what grows faster than
// n shows here (issue 25, item 18). Compare the rows: time per example
// at 1,000 against 250.
void BM_InferDistinctExamples(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<Example> examples;
  for (std::size_t i = 1; i <= n; ++i) {
    LayoutOptions o;
    o.boxes = 30;
    o.seed = i;
    Example e;
    e.source = "distinct_" + std::to_string(i);
    e.boxes = random_layout(o);
    update_bounds(e);
    examples.push_back(std::move(e));
  }
  auto run = [&] { benchmark::DoNotOptimize(infer(examples, {}).grammar.rules.size()); };
  for (auto _ : state) run();
  report_row(state, static_cast<double>(n), "examples", peak_heap_of(0, run));
}
BENCHMARK(BM_InferDistinctExamples)->Arg(250)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime();

// ---- the infer command end to end: read, infer, test-derive, write ----

void run_infer(benchmark::State& state, const std::vector<std::string>& args, double size) {
  const fs::path out = fs::temp_directory_path() / "vernacular-bench-out";
  fs::create_directories(out);
  std::vector<std::string> argv{sibling_program("infer").string()};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), {"-o", (out / "style.grm").string(), "-q"});
  std::int64_t peak = 0;
  double cpu = 0;
  for (auto _ : state) {
    const ChildRun run = run_child(argv);
    if (run.exit_code != 0) {
      state.SkipWithError("infer failed");
      return;
    }
    state.SetIterationTime(run.seconds);
    peak = std::max(peak, run.peak_rss);
    cpu += run.cpu_seconds;
  }
  report_row(state, size, "parts", static_cast<double>(peak));
  state.counters["cpu_seconds"] = cpu / static_cast<double>(state.iterations());
}

void BM_InferCommandCity(benchmark::State& state) {
  run_infer(state, {VERN_SOURCE_DIR "/data/examples/skyscraper_city"}, static_cast<double>(parts(city())));
}
BENCHMARK(BM_InferCommandCity)->Unit(benchmark::kMillisecond)->UseManualTime();

void BM_InferCommandLayout(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  run_infer(state, {layout_file(n).string(), "--max-parts", std::to_string(n)}, static_cast<double>(n));
}
BENCHMARK(BM_InferCommandLayout)->Arg(1'000'000)->Repetitions(3)->Unit(benchmark::kMillisecond)->UseManualTime();

}  // namespace
}  // namespace vern
