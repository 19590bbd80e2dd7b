// Forward-direction throughput: derivation in memory (terminals/s) on the
// thesis's skyscraper city, and OBJ / GLB serialisation (bytes/s).
// Run: scripts/bench (Release build), or build/bin/vern_bench.
#include <benchmark/benchmark.h>

#include "forward/gltf_writer.hpp"
#include "forward/obj_writer.hpp"
#include "forward/variants.hpp"
#include "graph/parser.hpp"

namespace vern {
namespace {

const Grammar& city() {
  static const Grammar g = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/skyscraper_city.grm");
  return g;
}

// One city per iteration, a different seed each time so no branch
// predictor learns one city; items = terminals derived.
void BM_DeriveCity(benchmark::State& state) {
  const Grammar& g = city();
  std::uint64_t seed = 0;
  std::size_t terminals = 0;
  for (auto _ : state) {
    DeriveOptions o;
    o.seed = ++seed;
    Derivation d = derive(g, o);
    terminals += d.terminals.size();
    benchmark::DoNotOptimize(d.terminals.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(terminals));
  state.counters["terminals/city"] = double(terminals) / double(state.iterations());
}
BENCHMARK(BM_DeriveCity)->Unit(benchmark::kMillisecond);

Scene city_scene(std::uint32_t count) {
  VariantOptions o;
  o.count = count;
  o.derive.seed = 1;
  return lay_out(derive_variants(city(), o), 20.0);
}

void BM_WriteObj(benchmark::State& state) {
  const Scene scene = city_scene(4);
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string text = obj_text(scene, lib, "city.mtl");
    bytes += text.size();
    benchmark::DoNotOptimize(text.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_WriteObj)->Unit(benchmark::kMillisecond);

void BM_WriteGlb(benchmark::State& state) {
  const Scene scene = city_scene(4);
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string glb = glb_bytes(scene, lib);
    bytes += glb.size();
    benchmark::DoNotOptimize(glb.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_WriteGlb)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vern

