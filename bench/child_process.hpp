// Running one of the project's commands from a benchmark, for the rows that
// measure a whole command: wall time and peak memory as a user sees them.
//
// The command is started by a second, fresh vern_bench (`vern_bench
// --measure-child CMD ARGS...`) that forks it and reports its rusage. A
// direct child would not do: Linux counts the memory a process had before
// exec in its peak resident set, and a child spawned straight from this
// process starts out sharing all the inputs the benchmarks hold.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vern {

struct ChildRun {
  double seconds = 0;         // wall clock, start to exit
  double cpu_seconds = 0;     // user + system time of the command
  std::int64_t peak_rss = 0;  // bytes: the command's maximum resident set
  int exit_code = -1;         // or -1 when it did not exit normally
};

// Runs argv[0] with the arguments, its standard output discarded, and waits.
ChildRun run_child(const std::vector<std::string>& argv);

// A program next to the running one (vern_bench lives in build/bin/ with
// generate, infer and check).
std::filesystem::path sibling_program(const std::string& name);

// `--measure-child CMD ARGS...`: runs the command and prints
// "SECONDS CPU_SECONDS PEAK_RSS_BYTES EXIT_CODE" on standard output.
bool is_measure_child_command(const char* arg);
int measure_child_main(int argc, char** argv);

}  // namespace vern
