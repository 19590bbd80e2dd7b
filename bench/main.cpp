// One benchmark program for every bench/*.cpp: run scripts/bench.
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
