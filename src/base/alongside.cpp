#include "base/alongside.hpp"

#include <exception>
#include <thread>

#include "base/huge_pages.hpp"

namespace vern {

void run_alongside(unsigned threads, const std::function<void()>& side, const std::function<void()>& main) {
  if (threads == 1) {
    side();
    main();
    return;
  }
  std::exception_ptr side_error, main_error;
  {
    std::jthread helper([&] {
      huge_pages_for_this_thread();
      try {
        side();
      } catch (...) {
        side_error = std::current_exception();
      }
    });
    try {
      main();
    } catch (...) {
      main_error = std::current_exception();
    }
  }  // joins the helper
  if (side_error) std::rethrow_exception(side_error);
  if (main_error) std::rethrow_exception(main_error);
}

}  // namespace vern
