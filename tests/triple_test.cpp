// Triple: three values on the heap that behave like std::array.
#include "base/triple.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>

namespace vern {
namespace {

TEST(Triple, CopiesAreValuesAndEmptyReadsAsDefaults) {
  Triple<std::string> a{"x", "y", "z"};
  Triple<std::string> b = a;
  b[1] = "changed";
  EXPECT_EQ(a[1], "y");
  EXPECT_FALSE(a == b);
  const Triple<std::string> empty;
  EXPECT_EQ(empty, (Triple<std::string>{"", "", ""}));
  Triple<std::string> moved = std::move(a);
  EXPECT_EQ(moved[2], "z");
  a = moved;  // a moved-from triple can be assigned again
  EXPECT_EQ(a, moved);
  std::string joined;
  for (const std::string& s : std::as_const(a)) joined += s;
  EXPECT_EQ(joined, "xyz");
}

}  // namespace
}  // namespace vern
