// The forward direction at scale, on the thesis's skyscraper city
// (data/grammars/skyscraper_city.grm, about 2,200 terminals a city):
//   DeriveCity            one city derived in memory per iteration (terminals/s)
//   WriteObj, WriteGlb,   OBJ text and GLB bytes of 10 cities in memory
//   WriteGlbInstanced     (MB/s of output; GLB plain and EXT_mesh_gpu_instancing)
//   GenerateCity/threads  `generate -n 1000 --instancing -o city.glb` in
//                         process: derive_variants, lay_out, glb_bytes
//   GenerateCommand/threads  the same as a command, file written (peak RSS)
//   GenerateStream/buildings  `generate -n N -o city.glb` (plain nodes) and
//   GenerateStreamObj/buildings  `-o city.obj`, N = 500 and 5000: buildings
//                         are written as they are derived, so the peak
//                         resident set should not grow with N (issue 16)
// Rows follow bench/table_row.hpp. Run: scripts/bench, or build/bin/vern_bench.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "child_process.hpp"
#include "forward/variants.hpp"
#include "graph/parser.hpp"
#include "io/gltf_writer.hpp"
#include "io/obj_writer.hpp"
#include "table_row.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;

constexpr const char* kCity = VERN_SOURCE_DIR "/data/grammars/skyscraper_city.grm";

const Grammar& city() {
  static const Grammar g = read_grammar_file(kCity);
  return g;
}

const PrimitiveLibrary& library() {
  static const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  return lib;
}

std::size_t terminals(const Scene& scene) {
  std::size_t n = 0;
  for (const Variant& v : scene.variants) n += v.terminals.size();
  return n;
}

// generate's layout of `count` cities from seed 1, spaced as by default.
Scene city_scene(std::uint32_t count, unsigned threads = 1) {
  VariantOptions o;
  o.count = count;
  o.derive.seed = 1;
  o.threads = threads;
  return lay_out(derive_variants(city(), o), 5.0);
}

// ---- derivation in memory ----

// One city per iteration, a different seed each time so no branch
// predictor learns one city. Size: terminals per city (the mean).
void BM_DeriveCity(benchmark::State& state) {
  const Grammar& g = city();
  std::uint64_t seed = 0;
  std::size_t derived = 0;
  reset_peak_heap();
  for (auto _ : state) {
    DeriveOptions o;
    o.seed = ++seed;
    Derivation d = derive(g, o);
    derived += d.terminals.size();
    benchmark::DoNotOptimize(d.terminals.data());
  }
  report_row(state, static_cast<double>(derived) / static_cast<double>(state.iterations()), "terminals");
}
BENCHMARK(BM_DeriveCity)->Unit(benchmark::kMillisecond)->UseRealTime();

// ---- writing: size in terminals, throughput in bytes written ----

const Scene& written_scene() {
  static const Scene scene = city_scene(10);
  return scene;
}

template <class Write>
void write_row(benchmark::State& state, Write write) {
  const Scene& scene = written_scene();
  const PrimitiveLibrary& lib = library();
  std::size_t bytes = 0;
  reset_peak_heap();
  for (auto _ : state) {
    const std::string out = write(scene, lib);
    bytes += out.size();
    benchmark::DoNotOptimize(out.data());
  }
  report_row(state, static_cast<double>(terminals(scene)), "terminals");
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
  state.counters["file_bytes"] = static_cast<double>(bytes) / static_cast<double>(state.iterations());
}

void BM_WriteObj(benchmark::State& state) {
  write_row(state, [](const Scene& s, const PrimitiveLibrary& lib) { return obj_text(s, lib, "city.mtl"); });
}
BENCHMARK(BM_WriteObj)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_WriteGlb(benchmark::State& state) {
  write_row(state, [](const Scene& s, const PrimitiveLibrary& lib) { return glb_bytes(s, lib); });
}
BENCHMARK(BM_WriteGlb)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_WriteGlbInstanced(benchmark::State& state) {
  write_row(state, [](const Scene& s, const PrimitiveLibrary& lib) {
    return glb_bytes(s, lib, GltfOptions{.instancing = true});
  });
}
BENCHMARK(BM_WriteGlbInstanced)->Unit(benchmark::kMillisecond)->UseRealTime();

// ---- generate -n 1000 to one instanced GLB ----

constexpr std::uint32_t kBuildings = 1000;

// In process, file writing aside: everything generate computes. Size:
// buildings; the terminals and GLB size are counters.
void BM_GenerateCity(benchmark::State& state) {
  const auto threads = static_cast<unsigned>(state.range(0));
  const PrimitiveLibrary& lib = library();
  city();
  std::size_t derived = 0, bytes = 0;
  reset_peak_heap();
  for (auto _ : state) {
    const Scene scene = city_scene(kBuildings, threads);
    const std::string glb = glb_bytes(scene, lib, GltfOptions{.instancing = true});
    derived = terminals(scene);
    bytes = glb.size();
    benchmark::DoNotOptimize(glb.data());
  }
  report_row(state, kBuildings, "buildings");
  state.counters["terminals"] = static_cast<double>(derived);
  state.counters["glb_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_GenerateCity)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// `generate` run `count` buildings from seed 1 with these options into
// `file`, as a user runs it: parse, derive, lay out, write. Peak memory is
// the command's peak resident set.
void run_generate(benchmark::State& state, std::uint32_t count, std::vector<std::string> options, const char* file) {
  const fs::path out = fs::temp_directory_path() / "vernacular-bench-out";
  fs::create_directories(out);
  std::vector<std::string> argv{sibling_program("generate").string(), kCity, "-n", std::to_string(count), "--seed", "1"};
  argv.insert(argv.end(), options.begin(), options.end());
  argv.insert(argv.end(), {"-o", (out / file).string(), "-q"});
  std::int64_t peak = 0;
  for (auto _ : state) {
    const ChildRun run = run_child(argv);
    if (run.exit_code != 0) {
      state.SkipWithError("generate failed");
      return;
    }
    state.SetIterationTime(run.seconds);
    peak = std::max(peak, run.peak_rss);
  }
  report_row(state, count, "buildings", static_cast<double>(peak));
  std::error_code ec;
  state.counters["file_bytes"] = static_cast<double>(fs::file_size(out / file, ec));
}

// The command, as a user runs it (instanced GLB).
void BM_GenerateCommand(benchmark::State& state) {
  run_generate(state, kBuildings, {"-j", std::to_string(state.range(0)), "--instancing"}, "city.glb");
}
BENCHMARK(BM_GenerateCommand)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseManualTime();

// The one-file outputs as a user writes them, for two counts ten times
// apart: the peak resident set is the row's point (it was 445 MB and
// 4.4 GB for the GLB before the writers streamed, now some 20 MB for both).
void generate_stream(benchmark::State& state, const char* file) {
  run_generate(state, static_cast<std::uint32_t>(state.range(0)), {"-j", "2"}, file);
  const fs::path out = fs::temp_directory_path() / "vernacular-bench-out";
  std::error_code ec;
  fs::remove(out / file, ec);  // a gigabyte or more
  fs::remove(out / "city.mtl", ec);
}

void BM_GenerateStream(benchmark::State& state) { generate_stream(state, "city.glb"); }
BENCHMARK(BM_GenerateStream)->ArgName("buildings")->Arg(500)->Arg(5000)->Iterations(1)->Unit(benchmark::kMillisecond)->UseManualTime();

void BM_GenerateStreamObj(benchmark::State& state) { generate_stream(state, "city.obj"); }
BENCHMARK(BM_GenerateStreamObj)->ArgName("buildings")->Arg(500)->Iterations(1)->Unit(benchmark::kMillisecond)->UseManualTime();

}  // namespace
}  // namespace vern
