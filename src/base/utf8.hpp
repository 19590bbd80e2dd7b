// Checking that text is UTF-8, for names that reach written files.
//
// Labels travel from an OBJ object name into a grammar, a glTF node and an
// OBJ object again; a name in some other encoding would come out as bytes
// that no viewer or editor shows correctly, so readers refuse it where it
// is read, naming the place.
#pragma once

#include <cstddef>
#include <string_view>

namespace vern {

// The offset of the first byte that does not belong to a well-formed UTF-8
// sequence (overlong forms, surrogates and code points past U+10FFFF are
// not well-formed), or npos when the whole text is UTF-8.
std::size_t invalid_utf8_offset(std::string_view text);

// The code point that starts at text[at], in text that is UTF-8 (checked
// above); `at` moves past it.
char32_t next_code_point(std::string_view text, std::size_t& at);

}  // namespace vern
