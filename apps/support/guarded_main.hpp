// The shared outer shell of every command: interrupt clean-up, freed memory
// kept for reuse (freed_memory.hpp), a stack that holds the limits
// (command_stack.hpp), the files read kept from being written over
// (files_read.hpp), and every failure printed once with its exit code
// (README, "Errors and exit codes").
#pragma once

namespace vern {

// Runs run(argc, argv) and returns its exit code; a vern::Error prints its
// message and returns its kind's code, running out of memory is a limit,
// a file-system error an I/O error naming its path, anything else an
// internal error.
int guarded_main(const char* program, int (*run)(int, char**), int argc, char** argv);

}  // namespace vern
