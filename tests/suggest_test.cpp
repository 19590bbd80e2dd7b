// "Did you mean": edit distances within a bound, the closest candidate, and
// names as messages show them.
#include "base/suggest.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace vern {
namespace {

TEST(Suggest, EditDistanceWithinItsLimit) {
  EXPECT_EQ(edit_distance_within("hose", "house", 2), 1u);
  EXPECT_EQ(edit_distance_within("house", "hose", 2), 1u);
  EXPECT_EQ(edit_distance_within("kitten", "sitting", 3), 3u);
  EXPECT_EQ(edit_distance_within("", "abc", 3), 3u);
  EXPECT_EQ(edit_distance_within("same", "same", 0), 0u);
  // Beyond the limit, no distance: by length alone, or by the table.
  EXPECT_EQ(edit_distance_within("kitten", "sitting", 2), std::nullopt);
  EXPECT_EQ(edit_distance_within("ab", "abcdef", 3), std::nullopt);
  EXPECT_EQ(edit_distance_within("abcd", "wxyz", 3), std::nullopt);
}

// Every path stays within `limit` of the diagonal: one that leaves it and
// comes back is longer than the limit, so the band loses nothing.
TEST(Suggest, EditDistanceAgreesWithTheWholeTable) {
  const auto whole = [](const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      std::size_t diagonal = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({up + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
        diagonal = up;
      }
    }
    return row[b.size()];
  };
  const std::vector<std::string> words = {"", "a", "ab", "ba", "abc", "acb", "wall", "walls", "window", "widow",
                                          "roof", "floor", "flor", "garage", "garden", "aaaa", "abab", "baba"};
  for (const std::string& a : words)
    for (const std::string& b : words)
      for (std::size_t limit = 0; limit < 7; ++limit) {
        const std::size_t d = whole(a, b);
        EXPECT_EQ(edit_distance_within(a, b, limit), d <= limit ? std::optional(d) : std::nullopt)
            << a << " / " << b << " within " << limit;
      }
}

TEST(Suggest, ClosestNameIsTheFirstOfTheClosest) {
  EXPECT_EQ(closest_name("hose", {"garage", "house", "horse"}), "house");
  EXPECT_EQ(closest_name("walls", {"wall", "walls"}), "walls");
  EXPECT_EQ(closest_name("xyz", {"garage", "house"}), "");
}

// Long names: a typo is a few edits, whatever the length.
TEST(Suggest, LongNamesAreComparedWithinEightEdits) {
  const std::string name(400000, 'a');
  std::string one_off = name;
  one_off.back() = 'b';
  EXPECT_EQ(closest_name(name, {"short", one_off}), one_off);
  std::string nine_off = name;
  for (std::size_t i = 0; i < 9; ++i) nine_off[i * 1000] = 'b';
  EXPECT_EQ(closest_name(name, {nine_off}), "");
}

TEST(Suggest, LongNamesAreShownShortened) {
  EXPECT_EQ(shown_name("garage"), "garage");
  EXPECT_EQ(shown_name(std::string(60, 'a')), std::string(60, 'a'));
  EXPECT_EQ(shown_name(std::string(61, 'a')), std::string(40, 'a') + "... (61 characters)");
  // Never cut inside a character: "é" is two bytes.
  std::string accented = std::string(39, 'a');
  for (int i = 0; i < 30; ++i) accented += "\xC3\xA9";
  EXPECT_EQ(shown_name(accented), std::string(39, 'a') + "... (69 characters)");
  EXPECT_EQ(suggest("zzz", {std::string(100, 'b')}, "the rules"),
            "the rules are: " + std::string(40, 'b') + "... (100 characters)");
}

}  // namespace
}  // namespace vern
