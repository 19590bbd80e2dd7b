// Inference throughput on the ten bundled skyscraper-city examples (about
// 20,000 parts): loading, ordered-box splitting alone, and infer end to end.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "inverse/box_split.hpp"
#include "inverse/example.hpp"
#include "inverse/infer.hpp"

namespace vern {
namespace {

std::vector<std::filesystem::path> city_files() {
  return example_files({VERN_SOURCE_DIR "/data/examples/skyscraper_city"});
}

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

void BM_LoadCityExamples(benchmark::State& state) {
  const auto files = city_files();
  for (auto _ : state) {
    for (const auto& f : files) benchmark::DoNotOptimize(load_example(f).boxes.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * parts(city())));
}
BENCHMARK(BM_LoadCityExamples)->Unit(benchmark::kMillisecond);

void BM_SplitCityExamples(benchmark::State& state) {
  const auto& examples = city();
  for (auto _ : state) {
    for (const auto& e : examples) {
      SplitTree t = split_boxes(e.boxes, BoxSplitOptions{default_tolerance(e)});
      benchmark::DoNotOptimize(t.children.data());
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * parts(examples)));
}
BENCHMARK(BM_SplitCityExamples)->Unit(benchmark::kMillisecond);

// Split, merge, tidy and name: everything after loading.
void BM_InferCity(benchmark::State& state) {
  const auto& examples = city();
  std::size_t rules = 0;
  for (auto _ : state) {
    Inference result = infer(examples, {});
    rules = result.grammar.rules.size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * parts(examples)));
  state.counters["parts"] = static_cast<double>(parts(examples));
  state.counters["rules"] = static_cast<double>(rules);
}
BENCHMARK(BM_InferCity)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vern
