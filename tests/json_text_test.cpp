// JsonText: commas in the right places, strings escaped, numbers exact and
// short, nesting checked.
#include "io/json_text.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "base/error.hpp"

namespace vern {
namespace {

TEST(JsonText, SeparatesValuesAndKeysWithCommas) {
  JsonText j;
  j.open_object().field("a", 1).key("b").open_array().integer(1).integer(2).open_object().close_object().close_array();
  j.field("c", "x").key("d").boolean(false).close_object();
  EXPECT_EQ(j.text(), R"({"a":1,"b":[1,2,{}],"c":"x","d":false})");
}

TEST(JsonText, EscapesQuotesBackslashesAndControlCharacters) {
  JsonText j;
  j.string("say \"hi\"\\\n\t\x01 caf\xc3\xa9");
  EXPECT_EQ(j.text(), R"("say \"hi\"\\\u000a\u0009\u0001 café")");
}

TEST(JsonText, NumbersAreShortestExactAndZeroHasNoSign) {
  JsonText j;
  j.numbers(std::array<double, 6>{0.1, -0.0, 1e-7, 3.0, 2.5e300, 1.0 / 3.0});
  EXPECT_EQ(j.text(), "[0.1,0,1e-07,3,2.5e+300,0.3333333333333333]");
  EXPECT_EQ(std::stod("0.3333333333333333"), 1.0 / 3.0);
}

TEST(JsonText, RefusesNonFiniteNumbers) {
  JsonText j;
  EXPECT_THROW(j.number(std::numeric_limits<double>::quiet_NaN()), Error);
  EXPECT_THROW(j.number(INFINITY), Error);
}

TEST(JsonText, RefusesUnbalancedAndTooDeepNesting) {
  JsonText j;
  EXPECT_THROW(j.close_array(), Error);
  for (int i = 0; i < 64; ++i) j.open_array();
  EXPECT_THROW(j.open_array(), Error);
}

}  // namespace
}  // namespace vern
