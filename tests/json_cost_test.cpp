#include "io/json_cost.hpp"

#include <gtest/gtest.h>

#include <string>

namespace vern {
namespace {

constexpr std::size_t kDeep = 64;

TEST(JsonCost, CountsMembersAndElementsAndWeighsObjects) {
  EXPECT_EQ(json_cost("", kDeep).values, 0u);
  EXPECT_EQ(json_cost("[]", kDeep).values, 0u);
  EXPECT_EQ(json_cost("[1]", kDeep).values, 1u);
  EXPECT_EQ(json_cost(" [ 1 , 2,3 ] ", kDeep).values, 3u);
  EXPECT_EQ(json_cost(R"({"a": 1, "b": [true, null], "c": {}})", kDeep).values, 5u);
  // An empty object costs more than a number, and one of glTF's own (an
  // element of an array of the top object) more again.
  const JsonCost number = json_cost("[1]", kDeep), object = json_cost("[{}]", kDeep);
  EXPECT_GT(object.bytes, number.bytes);
  const JsonCost nested = json_cost(R"({"extras": {"a": [{}]}})", kDeep);
  const JsonCost entry = json_cost(R"({"nodes": [{}], "b": 0})", kDeep);
  EXPECT_EQ(nested.values, entry.values);
  EXPECT_GT(entry.bytes, nested.bytes);
  // Memory grows with the values, whatever their text takes.
  EXPECT_EQ(json_cost("[1,1,1,1]", kDeep).bytes, 4 * json_cost("[1]", kDeep).bytes - 3 * json_cost("[]", kDeep).bytes);
}

TEST(JsonCost, StringsCountAsOneValueWhateverTheyHold) {
  EXPECT_EQ(json_cost(R"(["a,b:[{c}]", "d"])", kDeep).values, 2u);
  EXPECT_EQ(json_cost(R"(["quote \" , [ still inside", 1])", kDeep).values, 2u);
  EXPECT_EQ(json_cost(R"(["backslash \\", 1, 2])", kDeep).values, 3u);
  EXPECT_EQ(json_cost(R"(["[[[[[[[[[[[[[[[[[[[["])", 2).too_deep_at, JsonCost::npos);
}

TEST(JsonCost, NestingPastTheBoundIsFoundWhereItStarts) {
  EXPECT_EQ(json_cost("[[[]]]", 3).too_deep_at, JsonCost::npos);
  EXPECT_EQ(json_cost("[[[[]]]]", 3).too_deep_at, 3u);
  EXPECT_EQ(json_cost(R"({"a": {"b": [1]}})", 2).too_deep_at, 12u);
  // Text that is not JSON is counted all the same, and ends.
  EXPECT_EQ(json_cost("]]]}}[", kDeep).too_deep_at, JsonCost::npos);
  EXPECT_EQ(json_cost("[\"unclosed", kDeep).values, 1u);
  EXPECT_EQ(json_cost(std::string(200000, '['), kDeep).too_deep_at, kDeep);
}

TEST(JsonCost, TextLocationsCountLinesAndColumnsFromOne) {
  EXPECT_EQ(text_location("abc", 0), (SourceLoc{1, 1}));
  EXPECT_EQ(text_location("abc", 2), (SourceLoc{1, 3}));
  EXPECT_EQ(text_location("a\nbc\n[", 5), (SourceLoc{3, 1}));
  EXPECT_EQ(text_location("a\nbc", 3), (SourceLoc{2, 2}));
}

}  // namespace
}  // namespace vern
