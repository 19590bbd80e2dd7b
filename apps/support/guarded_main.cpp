#include "support/guarded_main.hpp"

#include <iostream>
#include <new>

#include "graph/error.hpp"
#include "graph/freed_memory.hpp"
#include "graph/huge_pages.hpp"
#include "graph/interrupt_cleanup.hpp"
#include "support/command_stack.hpp"

namespace vern {

int guarded_main(const char* program, int (*run)(int, char**), int argc, char** argv) {
  install_interrupt_cleanup();
  keep_freed_memory();
  use_huge_pages();
  try {
    return run_on_command_stack([&] {
      huge_pages_for_this_thread();
      return run(argc, argv);
    });
  } catch (const Error& e) {
    std::cerr << e.what() << "\n";
    return exit_code(e.kind());
  } catch (const std::bad_alloc&) {
    std::cerr << program << ": error: out of memory\n  hint: ask for less (fewer buildings, lower limits)\n";
    return exit_code(ErrorKind::Limit);
  } catch (const std::exception& e) {
    std::cerr << program << ": internal error: " << e.what() << "\n  hint: please report it with the input\n";
    return exit_code(ErrorKind::Internal);
  }
}

}  // namespace vern
