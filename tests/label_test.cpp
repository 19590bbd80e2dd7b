// What a label is (graph/label.hpp): which text is one, how a file's name
// holds one and gives it back, and how a message shows a hostile name.
#include "graph/label.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace vern {
namespace {

using namespace std::string_literals;

// Labels a format cannot hold as they are, and plain ones.
const std::vector<std::string> kLabels = {
    "window", "right_angle_triangle", "fen\xC3\xAAtre", "fen__tre", "a-b.c", "#x", "a#b", "a b", "a_b", "a  b",
    "50%", "%41", "a%2", "back\\", "\\front", "v1.2", "wall.001", "a.", ".5", "x\"y", "colour_ff0000",
    "a colour_ff0000", "\xE6\x97\xA5\xE6\x9C\xAC"};

TEST(Label, PlainAndUnusualTextIsALabel) {
  for (const std::string& label : kLabels) EXPECT_EQ(label_fault(label), std::nullopt) << label;
  EXPECT_EQ(label_fault(std::string(kMaxLabelBytes, 'a')), std::nullopt);
}

TEST(Label, WhatCannotBeALabelSaysWhy) {
  EXPECT_EQ(label_fault(""), "is empty");
  EXPECT_EQ(label_fault(" "), "starts with white space");
  EXPECT_EQ(label_fault("wall "), "ends with white space");
  EXPECT_EQ(label_fault(" wall"), "starts with white space");
  EXPECT_EQ(label_fault("wall\xC2\xA0"), "ends with white space");  // a no-break space
  EXPECT_EQ(label_fault("wall\nf 1 2 3"), "holds a line break");
  EXPECT_EQ(label_fault("a\tb"), "holds a tab");
  EXPECT_EQ(label_fault("a\0b"s), "holds a NUL byte");
  EXPECT_EQ(label_fault("a\rb"), "holds a carriage return");
  EXPECT_EQ(label_fault("a\x1B[2Jb"), "holds a control character (U+001B)");
  EXPECT_EQ(label_fault("a\x7F"), "holds a control character (U+007F)");
  EXPECT_EQ(label_fault("a\xC2\x85"), "holds a control character (U+0085)");
  EXPECT_EQ(label_fault("a\xE2\x80\xAE" "b"), "holds a bidirectional control character (U+202E)");
  EXPECT_EQ(label_fault("fen\xEAtre"), "is not UTF-8 text (byte 0xEA)");
  EXPECT_EQ(label_fault(std::string(kMaxLabelBytes + 1, 'a')), "is longer than 1024 bytes");
}

TEST(Label, PlainLabelsAreTheirOwnNamesAndWords) {
  for (const std::string label : {"window", "right_angle_triangle", "fen\xC3\xAAtre", "a-b.c", "a b", "wall.x"}) {
    EXPECT_EQ(name_in_file(label), label);
    if (label != "a b") {
      EXPECT_EQ(label_as_word(label), label);
    }
  }
}

TEST(Label, NamesEscapeWhatOBJAndExamplesGiveAMeaningTo) {
  EXPECT_EQ(name_in_file("#x"), "%23x");        // an OBJ comment
  EXPECT_EQ(name_in_file("back\\"), "back%5C");  // an OBJ line continuation
  EXPECT_EQ(name_in_file("50%"), "50%25");      // the escape itself
  EXPECT_EQ(name_in_file("v1.2"), "v1%2E2");    // a copy number, in an example
  EXPECT_EQ(name_in_file("wall.001"), "wall%2E001");
  EXPECT_EQ(name_in_file("a b"), "a b");
  EXPECT_EQ(name_in_file("a b", true), "a%20b");
}

TEST(Label, NamesReadBackAsTheLabelTheyHold) {
  for (const std::string& label : kLabels) {
    for (const bool one_word : {false, true}) {
      const std::string name = name_in_file(label, one_word);
      EXPECT_EQ(label_of_name(name), label) << name;
      EXPECT_EQ(label_of_part_name(name), label) << name;
      // A copy, as Blender names it, is a part of the same label.
      EXPECT_EQ(label_of_part_name(name + ".001"), label) << name;
      if (one_word) {
        EXPECT_EQ(name.find(' '), std::string::npos) << name;
      }
    }
  }
}

TEST(Label, NamesFromElsewhereKeepAPercentThatIsNoEscape) {
  EXPECT_EQ(label_of_name("50%"), "50%");
  EXPECT_EQ(label_of_name("a%zzb"), "a%zzb");
  EXPECT_EQ(label_of_name("a%4"), "a%4");
  EXPECT_EQ(label_of_name("%41%62"), "Ab");
  EXPECT_EQ(label_of_name("wall%0A"), "wall\n");  // and then not a label
  EXPECT_EQ(label_of_part_name("window.001"), "window");
  EXPECT_EQ(label_of_part_name("window%2E001"), "window.001");
}

TEST(Label, BlenderSuffixesAreStrippedFromPartNames) {
  EXPECT_EQ(strip_numeric_suffix("window.001"), "window");
  EXPECT_EQ(strip_numeric_suffix("wall.12"), "wall");
  EXPECT_EQ(strip_numeric_suffix("v1.5"), "v1");
  EXPECT_EQ(strip_numeric_suffix("wall.001.002"), "wall.001");  // one suffix only
  EXPECT_EQ(strip_numeric_suffix("roof"), "roof");
  EXPECT_EQ(strip_numeric_suffix("door.left"), "door.left");
  EXPECT_EQ(strip_numeric_suffix("door.1a"), "door.1a");
  EXPECT_EQ(strip_numeric_suffix("door."), "door.");
  EXPECT_EQ(strip_numeric_suffix(".001"), ".001");  // nothing would be left
  EXPECT_EQ(strip_numeric_suffix("window_3"), "window_3");
}

TEST(Label, DifferentLabelsAreDifferentWords) {
  EXPECT_EQ(label_as_word("a b"), "a%20b");
  EXPECT_EQ(label_as_word("a#b"), "a%23b");
  EXPECT_EQ(label_as_word("a_b"), "a_b");
  EXPECT_EQ(label_as_word("50%"), "50%25");
  EXPECT_EQ(label_as_word("a\xC2\xA0" "b"), "a%C2%A0b");  // white space, though not ASCII
  std::set<std::string> words;
  for (const std::string& label : kLabels) {
    const std::string word = label_as_word(label);
    EXPECT_TRUE(words.insert(word).second) << label << " -> " << word << " is another label's word";
    EXPECT_EQ(word.find_first_of(" \t#\"\\"), std::string::npos) << word;
  }
}

TEST(Label, MessagesShowHostileNamesAsEscapes) {
  EXPECT_EQ(shown_name("window.001"), "window.001");
  EXPECT_EQ(shown_name("fen\xC3\xAAtre"), "fen\xC3\xAAtre");
  EXPECT_EQ(shown_name("wall\nf 1 2 3"), "wall\\nf 1 2 3");
  EXPECT_EQ(shown_name("a\tb\r"), "a\\tb\\r");
  EXPECT_EQ(shown_name("\x1B[2J"), "\\x1B[2J");
  EXPECT_EQ(shown_name("a\0b"s), "a\\x00b");
  EXPECT_EQ(shown_name("fen\xEAtre"), "fen\\xEAtre");
  EXPECT_EQ(shown_name("a\xE2\x80\xAE" "b"), "a\\u202Eb");
  EXPECT_EQ(shown_name(std::string(300, 'a')), std::string(40, 'a') + "... (300 characters)");
}

TEST(Label, ReadingANameThatIsNoLabelNamesThePlaceAndWhatItDecodesTo) {
  EXPECT_EQ(read_label("window.001", NameOf::Part, "x.obj", {3, 1}, "the object name"), "window");
  EXPECT_EQ(read_label("window.001", NameOf::Primitive, "x.obj", {3, 1}, "the object name"), "window.001");
  try {
    read_label("wall%0A", NameOf::Part, "x.obj", {3, 1}, "the object name");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input);
    const std::string text = e.what();
    EXPECT_NE(text.find("x.obj:3:1: error: the object name 'wall%0A' (read as 'wall\\n') cannot be a label: it holds "
                        "a line break\n  hint: "),
              std::string::npos)
        << text;
  }
}

TEST(Label, ThreeJsCopyNumbersAreAnUnderscoreAndDigitsAtTheEnd) {
  EXPECT_EQ(without_three_js_copy_number("rect_1"), "rect");
  EXPECT_EQ(without_three_js_copy_number("big_window_12"), "big_window");
  EXPECT_EQ(without_three_js_copy_number("rect"), "rect");
  EXPECT_EQ(without_three_js_copy_number("rect_"), "rect_");
  EXPECT_EQ(without_three_js_copy_number("_1"), "_1");
  EXPECT_EQ(without_three_js_copy_number("rect_1b"), "rect_1b");
}

}  // namespace
}  // namespace vern
