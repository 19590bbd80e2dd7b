// The editor's latency on the server side: one /api/derive answer (parse,
// derive with traces, JSON) for a house-sized grammar, the work each
// keystroke asks for (issue 27: redrawn within 50 ms of a keystroke).
//   DeriveRequest/buildings  data/grammars/modern_houses.grm, 1 and 3 buildings
//   DeriveRequestCity        data/grammars/skyscraper_city.grm, one city
// The browser's own part (parsing the JSON, drawing) is not in it: the page
// shows the whole round trip in its header.
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "serve/derive_request.hpp"

namespace vern {
namespace {

std::string request_for(const char* grammar, int count) {
  std::ifstream in(grammar);
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json{{"text", text.str()}, {"seed", 1}, {"count", count}}.dump();
}

// Answers `request` once per iteration; the answer's size as a counter.
void answer_repeatedly(benchmark::State& state, const std::string& request) {
  const ServeSession session;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const ApiAnswer a = derive_request(request, session);
    bytes = a.body.size();
    benchmark::DoNotOptimize(a);
  }
  state.counters["answer_kb"] = static_cast<double>(bytes) / 1024.0;
}

void BM_DeriveRequest(benchmark::State& state) {
  answer_repeatedly(state, request_for(VERN_SOURCE_DIR "/data/grammars/modern_houses.grm", static_cast<int>(state.range(0))));
}
BENCHMARK(BM_DeriveRequest)->ArgName("buildings")->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DeriveRequestCity(benchmark::State& state) {
  answer_repeatedly(state, request_for(VERN_SOURCE_DIR "/data/grammars/skyscraper_city.grm", 1));
}
BENCHMARK(BM_DeriveRequestCity)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace vern
