// One benchmark program for every bench/*.cpp: run scripts/bench.
// `vern_bench --make-layout N ...` and `--make-grammar R ...` write the
// synthetic workloads instead (bench/workload.hpp); `--measure-child CMD`
// is how the command rows measure a command (bench/child_process.hpp).
#include <benchmark/benchmark.h>

#include "child_process.hpp"
#include "workload.hpp"

int main(int argc, char** argv) {
  if (argc > 1 && vern::is_workload_command(argv[1])) return vern::workload_main(argc, argv);
  if (argc > 1 && vern::is_measure_child_command(argv[1])) return vern::measure_child_main(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
