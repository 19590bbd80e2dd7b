#include "support/guarded_main.hpp"

#include <filesystem>
#include <iostream>
#include <new>

#include <vernacular/error.hpp>

#include "base/error.hpp"
#include "base/files_read.hpp"
#include "base/freed_memory.hpp"
#include "base/huge_pages.hpp"
#include "base/interrupt_cleanup.hpp"
#include "graph/label.hpp"
#include "support/command_stack.hpp"

namespace vern {

namespace {

ErrorKind kind_of(vernacular::ErrorKind kind) {
  switch (kind) {
    case vernacular::ErrorKind::Usage: return ErrorKind::Usage;
    case vernacular::ErrorKind::Input: return ErrorKind::Input;
    case vernacular::ErrorKind::Limit: return ErrorKind::Limit;
    case vernacular::ErrorKind::Io: return ErrorKind::Io;
    case vernacular::ErrorKind::Internal: return ErrorKind::Internal;
  }
  return ErrorKind::Internal;
}

}  // namespace

int guarded_main(const char* program, int (*run)(int, char**), int argc, char** argv) {
  install_interrupt_cleanup();
  keep_freed_memory();
  use_huge_pages();
  // Every file read is an input no output may replace (files_read.hpp).
  const FilesReadRecorded recording;
  try {
    return run_on_command_stack([&] {
      huge_pages_for_this_thread();
      return run(argc, argv);
    });
  } catch (const Error& e) {
    std::cerr << e.what() << "\n";
    return exit_code(e.kind());
  } catch (const vernacular::Failure& f) {
    std::cerr << f.what() << "\n";
    return exit_code(kind_of(f.error().kind));
  } catch (const std::filesystem::filesystem_error& e) {
    // Every file-system call on a user's path takes an error code and says
    // what went wrong; one that slipped through is still the path's fault,
    // not a bug of the run: named, as an I/O error.
    const std::string path = e.path1().empty() ? std::string(program) : shown_name(e.path1().string());
    std::cerr << path << ": error: cannot read or write: " << e.code().message()
              << "\n  hint: check the path (a link that leads to itself, a folder that cannot be listed)\n";
    return exit_code(ErrorKind::Io);
  } catch (const std::bad_alloc&) {
    std::cerr << program << ": error: out of memory\n  hint: ask for less (fewer buildings, lower limits)\n";
    return exit_code(ErrorKind::Limit);
  } catch (const std::exception& e) {
    std::cerr << program << ": internal error: " << e.what() << "\n  hint: please report it with the input\n";
    return exit_code(ErrorKind::Internal);
  }
}

}  // namespace vern
