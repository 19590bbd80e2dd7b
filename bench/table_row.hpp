// One row of the table scripts/bench prints, the same for every benchmark
// (inverse and forward):
//
//   benchmark    the benchmark's name
//   size         units handled per iteration: parts, terminals, bytes, ...
//   median time  real time of one iteration, median over the repetitions
//   cpu time     the same in CPU time (the benchmark's process, or the
//                command's user + system time: counter "cpu_seconds"),
//                which a busy machine inflates less
//   throughput   size per second (units/s), or bytes/s when the benchmark
//                sets bytes processed
//   bytes/unit   peak memory / size
//   peak memory  the most heap held at once during one iteration, above
//                what was held before (heap_meter.hpp); for rows that run
//                a command, its peak resident set
//
// A benchmark either measures its peak in one extra run (peak_heap_of,
// keeping the meter's cost out of the timed iterations), or calls
// reset_peak_heap() after building its inputs and report_row(state, size,
// unit) at its end (metered while timed). Register it with ->UseRealTime()
// so that throughput is per wall-clock second, as the time column is.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>

#include "heap_meter.hpp"

namespace vern {

inline void report_row(benchmark::State& state, double size, const char* unit, double peak_bytes) {
  state.SetLabel(unit);
  state.SetItemsProcessed(static_cast<std::int64_t>(size * static_cast<double>(state.iterations())));
  state.counters["size"] = size;
  state.counters["peak_bytes"] = peak_bytes;
  state.counters["bytes_per_unit"] = size > 0 ? peak_bytes / size : 0.0;
}

// Peak heap since reset_peak_heap(); stops the meter.
inline void report_row(benchmark::State& state, double size, const char* unit) {
  const auto peak = static_cast<double>(peak_heap_since_reset());
  stop_heap_meter();
  report_row(state, size, unit, peak);
}

// The peak heap of one run of body(), metered the first time a benchmark
// asks for `key` (its argument, say) and remembered after: one run per
// benchmark, not per repetition. (The cache is per call site: each lambda
// is its own Body type.)
template <class Body>
double peak_heap_of(std::int64_t key, Body&& body) {
  static std::map<std::int64_t, double> measured;
  auto it = measured.find(key);
  if (it == measured.end()) {
    reset_peak_heap();
    body();
    const auto peak = static_cast<double>(peak_heap_since_reset());
    stop_heap_meter();
    it = measured.emplace(key, peak).first;
  }
  return it->second;
}

}  // namespace vern
