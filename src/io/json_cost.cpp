#include "io/json_cost.hpp"

#include <array>
#include <vector>

namespace vern {

namespace {

// Bytes each kind of value takes once read, at most: peak memory of infer
// on 18 MB files of one kind each, over their count (tinygltf 2.7 with
// nlohmann::json 3.11), rounded up with room to spare.
constexpr std::uint64_t kMemberBytes = 384;   // a key and its value: 367 (numbers in `extras`)
constexpr std::uint64_t kElementBytes = 256;  // an array element: 200 (numbers in `extras`)
constexpr std::uint64_t kObjectBytes = 512;   // each object besides: 110 in `extras`, 420 as a primitive
// An object directly in an array of the top object is one of glTF's own
// (a node, an accessor, a material), read into tinygltf's struct for it:
// 715 for an empty node, 3.5 KB for an empty material.
constexpr std::uint64_t kEntryBytes = 4096;

bool space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

// Bytes that are neither structure, a quote nor space: numbers, literals.
// The scan passes over runs of them in a tight loop (most of a glTF's
// text is matrices of numbers).
const std::array<bool, 256> kPlain = [] {
  std::array<bool, 256> plain{};
  plain.fill(true);
  for (const char c : std::string_view("{}[]:,\" \n\r\t")) plain[static_cast<unsigned char>(c)] = false;
  return plain;
}();

bool plain(char c) { return kPlain[static_cast<unsigned char>(c)]; }

}  // namespace

JsonCost json_cost(std::string_view text, std::size_t max_depth) {
  JsonCost cost;
  std::uint64_t members = 0, elements = 0, objects = 0, entries = 0;
  std::vector<char> open;  // the containers the scan is in: '{' or '['
  bool array_start = false;  // right after a '[': the next value, if any, is its first element
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (space(c)) continue;
    if (array_start && c != ']') ++elements;
    array_start = false;
    if (plain(c)) {
      while (i + 1 < text.size() && plain(text[i + 1])) ++i;
      continue;
    }
    switch (c) {
      case '"':
        // A string: its bytes cost what the text does; escapes are skipped whole.
        for (++i; i < text.size() && text[i] != '"'; ++i)
          if (text[i] == '\\') ++i;
        break;
      case '{':
      case '[':
        if (open.size() >= max_depth) {
          cost.too_deep_at = i;
          i = text.size();
          break;
        }
        if (c == '{') {
          ++objects;
          if (open.size() == 2 && open[0] == '{' && open[1] == '[') ++entries;
        }
        open.push_back(c);
        array_start = c == '[';
        break;
      case '}':
      case ']':
        if (!open.empty()) open.pop_back();
        break;
      case ':': ++members; break;
      case ',':
        if (!open.empty() && open.back() == '[') ++elements;
        break;
      default: break;
    }
  }
  cost.values = members + elements;
  cost.bytes = members * kMemberBytes + elements * kElementBytes + objects * kObjectBytes + entries * kEntryBytes;
  return cost;
}

SourceLoc text_location(std::string_view text, std::size_t offset) {
  SourceLoc loc{1, 1};
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++loc.line;
      loc.column = 1;
    } else {
      ++loc.column;
    }
  }
  return loc;
}

}  // namespace vern
