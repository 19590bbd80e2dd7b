// run_alongside: both pieces run, and the side's error wins whatever the
// thread count.
#include "base/alongside.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace vern {
namespace {

TEST(Alongside, RunsBoth) {
  for (const unsigned threads : {0u, 1u, 2u}) {
    int side = 0, main = 0;
    run_alongside(threads, [&] { ++side; }, [&] { ++main; });
    EXPECT_EQ(side, 1);
    EXPECT_EQ(main, 1);
  }
}

TEST(Alongside, TheSidesErrorComesFirst) {
  for (const unsigned threads : {0u, 1u, 2u}) {
    auto fails = [](const char* what) { return [what] { throw std::runtime_error(what); }; };
    try {
      run_alongside(threads, fails("side"), fails("main"));
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "side");
    }
    try {
      run_alongside(threads, [] {}, fails("main"));
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "main");
    }
  }
}

}  // namespace
}  // namespace vern
