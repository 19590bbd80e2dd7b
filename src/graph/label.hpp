// What a label is, and how each file holds one.
//
// A label names a part's primitive: I(window) in a grammar, the object
// `o window` in an OBJ file, the node "window" in a glTF file. Labels go
// round: examples -> infer -> grammar -> generate -> buildings, which are
// examples again, and a primitives file names its meshes by label too. So
// one rule, here, says which text is a label, and every reader and writer
// keeps to it (docs/grammar.md, "Labels"):
//
//   - A label is UTF-8 text of 1 to kMaxLabelBytes bytes with no control
//     character (a line break, a tab, NUL, DEL, U+0080..U+009F), no
//     bidirectional control (which would make a grammar's text read other
//     than it parses), and no white space at its start or end. Anything
//     else is kept as it is: spaces inside, '#', '%', quotes, "fenêtre".
//     Readers refuse any other name (exit 3), naming the file and the line,
//     object or node: a name that cannot be written again is not guessed at.
//   - A grammar holds a label as it is: I(window), or I("a b") quoted (the
//     lexer's escapes \" and \\).
//   - An OBJ object or glTF node holds a label as a name (name_in_file):
//     the label, but with '%', '#', '\' and the '.' of a final copy number
//     written %XX (the byte in hex). OBJ reads '#' as a comment and a final
//     '\' as a line continuation; and in an example "window.001" is a copy of
//     "window" (Blender numbers copies so), so a label such as "v1.2" must
//     not look like one. Readers decode %XX (label_of_name), and an example's
//     reader drops the copy number first (label_of_part_name).
//   - A material (MTL newmtl and usemtl, glTF material names) is one word
//     per label (label_as_word): a plain label is its own word (window), any
//     other character outside letters, digits, '_', '.', '-' and non-ASCII
//     letters is written %XX, so different labels never share a material.
//
// Labels of letters, digits, '_', '.', '-' and non-ASCII letters without a
// final copy number are written everywhere exactly as they are.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "base/error.hpp"

namespace vern {

// The longest label, in bytes: far beyond any name a person gives a part,
// and far below the longest line an OBJ reader takes.
inline constexpr std::size_t kMaxLabelBytes = 1024;

// Why `text` is not a label, said after "it " ("holds a line break",
// "is empty", "ends with white space"), or nothing when it is one.
std::optional<std::string> label_fault(std::string_view text);

// Throws vern::Error (Input) at file:loc when `label` is not a label:
// "<what> cannot be a label: it holds a line break", with a hint. `what`
// names the place ("the object name 'wall%0A'"), shown with shown_name.
void require_label(std::string_view label, const std::string& file, SourceLoc loc, const std::string& what);

// Text from a file as a message may show it: control characters, bidirectional
// controls and bytes that are not UTF-8 as escapes (\n, \t, \x1B, \u202E),
// whole up to 60 bytes, else its first 40 and how long it is
// ("aaaa... (400000 characters)"), so that a hostile name can neither break
// a message's lines, drive the terminal nor make a message of megabytes.
std::string shown_name(std::string_view text);

// "window.001" -> "window", "wall.12" -> "wall", "v1.5" -> "v1": a final
// '.' followed only by digits is an example's copy number, dropped. Names
// that would become empty (".001") and names without such a suffix are kept
// whole.
std::string strip_numeric_suffix(std::string_view name);

// How an OBJ object or a glTF node names a label (see above). one_word:
// spaces are written %20 too, for names whose first word is the label
// (an instanced glTF node's "label colour_ff0000").
std::string name_in_file(std::string_view label, bool one_word = false);

// The label a name in a file carries: %XX decoded (a '%' without two hex
// digits after it stays). What a primitives file's objects are named by.
std::string label_of_name(std::string_view name);

// The label an example's part carries: its name without a copy number,
// then decoded.
std::string label_of_part_name(std::string_view name);

// A node name as three.js's glTF exporter wrote it, without the copy
// number three.js adds to a name already taken ("rect", "rect_1",
// "rect_2": the second and third parts labelled rect). Only for files
// whose asset.generator says three.js made them: elsewhere "rect_1" is a
// label of its own.
std::string_view without_three_js_copy_number(std::string_view name);

// What a name read from a file stands for: a primitive's (a primitives
// file's object: label_of_name) or an example's part (label_of_part_name).
enum class NameOf { Primitive, Part };

// The label `name` carries, or (Input) an error at file:loc: "<who> '<name>'
// cannot be a label: ...", with what it decodes to when that differs.
std::string read_label(std::string_view name, NameOf kind, const std::string& file, SourceLoc loc,
                       const std::string& who);

// The label as one word for a material name (see above).
std::string label_as_word(std::string_view label);

}  // namespace vern
