#include "io/json_cursor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace vern {
namespace {

using Declined = JsonCursor::Declined;

TEST(JsonCursor, ReadsObjectsArraysAndValuesInOrder) {
  JsonCursor json(R"( {"a": [1, -2.5, 3e2], "b" : {"c":true,"d":false}, "e":"text", "f":[]} )");
  std::vector<std::string> seen;
  json.open_object();
  std::string_view key;
  while (json.next_key(key)) {
    seen.emplace_back(key);
    if (key == "a") {
      std::vector<double> v;
      json.open_array();
      while (json.next_item()) v.push_back(json.number());
      EXPECT_EQ(v, (std::vector<double>{1, -2.5, 300}));
    } else if (key == "b") {
      json.open_object();
      std::string_view inner;
      ASSERT_TRUE(json.next_key(inner));
      EXPECT_EQ(inner, "c");
      EXPECT_TRUE(json.boolean());
      ASSERT_TRUE(json.next_key(inner));
      EXPECT_FALSE(json.boolean());
      EXPECT_FALSE(json.next_key(inner));
    } else if (key == "e") {
      EXPECT_EQ(json.string(), "text");
    } else {
      json.open_array();
      EXPECT_FALSE(json.next_item());
    }
  }
  json.finish();
  EXPECT_EQ(seen, (std::vector<std::string>{"a", "b", "e", "f"}));
}

// Numbers as nlohmann::json reads them and tinygltf converts them.
TEST(JsonCursor, NumbersAreReadAsJsonLibrariesReadThem) {
  auto number = [](const char* text) {
    JsonCursor json(text);
    const double v = json.number();
    json.finish();
    return v;
  };
  EXPECT_EQ(number("0.1"), 0.1);
  EXPECT_EQ(number("6.666666666666667"), 6.666666666666667);
  EXPECT_EQ(number("-1.5E-3"), -1.5e-3);
  // An integer literal is an integer first: "-0" is +0.0; "-0.0" is -0.0.
  EXPECT_FALSE(std::signbit(number("-0")));
  EXPECT_TRUE(std::signbit(number("-0.0")));
  // Past 64 bits, a double, rounded as strtod rounds.
  EXPECT_EQ(number("18446744073709551616"), 18446744073709551616.0);
  EXPECT_EQ(number("9007199254740993"), 9007199254740992.0);
  EXPECT_EQ(number("-9223372036854775809"), -9223372036854775808.0);
}

TEST(JsonCursor, DeclinesWhatLiesOutsideItsSubset) {
  auto declines = [](const std::string& text, const std::function<void(JsonCursor&)>& read) {
    JsonCursor json(text);
    try {
      read(json);
      json.finish();
    } catch (const Declined&) {
      return true;
    }
    return false;
  };
  auto number = [](JsonCursor& j) { j.number(); };
  auto string = [](JsonCursor& j) { j.string(); };
  auto index = [](JsonCursor& j) { j.index(); };
  for (const char* text : {"01", "1.", ".5", "1e", "+1", "-", "1e400", "NaN", "0x10", "1 2"})
    EXPECT_TRUE(declines(text, number)) << text;
  for (const char* text : {R"("a\"b")", "\"caf\xC3\xA9\"", "\"tab\there\"", "\"open", "'single'"})
    EXPECT_TRUE(declines(text, string)) << text;
  for (const char* text : {"-1", "1.0", "1e0", "2147483648"}) EXPECT_TRUE(declines(text, index)) << text;
  EXPECT_FALSE(declines("2147483647", index));
  // Commas and closings where JSON has them only.
  auto items = [](JsonCursor& j) {
    j.open_array();
    while (j.next_item()) j.number();
  };
  for (const char* text : {"[1,]", "[,1]", "[1 2]", "[1", "[1]]", "[1] x"}) EXPECT_TRUE(declines(text, items)) << text;
  EXPECT_FALSE(declines(" [ 1 , 2 ]\n", items));
  auto keys = [](JsonCursor& j) {
    j.open_object();
    for (std::string_view k; j.next_key(k);) j.number();
  };
  for (const char* text : {R"({"a":1,})", R"({"a" 1})", R"({a:1})", R"({"a":1 "b":2})"})
    EXPECT_TRUE(declines(text, keys)) << text;
  EXPECT_FALSE(declines(R"({"a":1,"b":2})", keys));
}

}  // namespace
}  // namespace vern
