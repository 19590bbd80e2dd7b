#include "graph/label.hpp"

#include <algorithm>
#include <cstdio>

#include "base/utf8.hpp"

namespace vern {

namespace {

bool is_control(char32_t c) { return c < 0x20 || (c >= 0x7F && c <= 0x9F); }

// Marks that turn the direction of the text around them: a label holding one
// would show a grammar line other than the one that is parsed.
bool is_bidi_control(char32_t c) {
  return c == 0x061C || c == 0x200E || c == 0x200F || (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069);
}

// Unicode's White_Space, less the control characters (refused anyway).
bool is_white_space(char32_t c) {
  return c == 0x20 || c == 0xA0 || c == 0x1680 || (c >= 0x2000 && c <= 0x200A) || c == 0x2028 || c == 0x2029 ||
         c == 0x202F || c == 0x205F || c == 0x3000;
}

std::string code_point_name(char32_t c) {
  char text[16];
  std::snprintf(text, sizeof text, "U+%04X", static_cast<unsigned>(c));
  return text;
}

std::string control_name(char32_t c) {
  switch (c) {
    case 0x00: return "a NUL byte";
    case 0x09: return "a tab";
    case 0x0A: return "a line break";
    case 0x0D: return "a carriage return";
    default: return "a control character (" + code_point_name(c) + ")";
  }
}

void append_escape(std::string& out, unsigned char byte) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  out += '%';
  out += kHex[byte >> 4];
  out += kHex[byte & 15];
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Printable ASCII: most names are nothing else, and need no closer look.
bool is_printable_ascii(std::string_view text) {
  for (const char c : text)
    if (c < 0x20 || c > 0x7E) return false;
  return true;
}

// Where an example's copy number starts ("window.001": at the '.'), or
// name.size() when there is none.
std::size_t copy_number_start(std::string_view name) {
  const std::size_t dot = name.rfind('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == name.size()) return name.size();
  for (std::size_t i = dot + 1; i < name.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return name.size();
  return dot;
}

bool is_plain_ascii(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
         c == '-';
}

}  // namespace

std::optional<std::string> label_fault(std::string_view text) {
  if (text.empty()) return "is empty";
  if (text.size() > kMaxLabelBytes) return "is longer than " + std::to_string(kMaxLabelBytes) + " bytes";
  if (is_printable_ascii(text)) {
    if (text.front() == ' ') return "starts with white space";
    if (text.back() == ' ') return "ends with white space";
    return std::nullopt;
  }
  if (const std::size_t bad = invalid_utf8_offset(text); bad != std::string_view::npos) {
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(text[bad]));
    return std::string("is not UTF-8 text (byte ") + byte + ")";
  }
  char32_t first = 0, last = 0;
  for (std::size_t at = 0; at < text.size();) {
    const bool starts = at == 0;
    const char32_t c = next_code_point(text, at);
    if (is_control(c)) return "holds " + control_name(c);
    if (is_bidi_control(c)) return "holds a bidirectional control character (" + code_point_name(c) + ")";
    if (starts) first = c;
    last = c;
  }
  if (is_white_space(first)) return "starts with white space";
  if (is_white_space(last)) return "ends with white space";
  return std::nullopt;
}

void require_label(std::string_view label, const std::string& file, SourceLoc loc, const std::string& what) {
  if (const std::optional<std::string> fault = label_fault(label)) {
    fail(ErrorKind::Input, file, loc, what + " cannot be a label: it " + *fault,
         "a label is UTF-8 text of at most " + std::to_string(kMaxLabelBytes) +
             " bytes, without control characters (line breaks, tabs, NUL) or white space at either end: rename it");
  }
}

std::string shown_name(std::string_view text) {
  constexpr std::size_t kShown = 60, kStart = 40;
  if (text.size() <= kShown && is_printable_ascii(text)) return std::string(text);
  // A longer name shows its start, cut before a UTF-8 continuation byte,
  // never inside a character.
  std::size_t cut = text.size();
  if (text.size() > kShown) {
    cut = kStart;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  }
  std::string out;
  const std::string_view head = text.substr(0, cut);
  for (std::size_t at = 0; at < head.size();) {
    const std::size_t bad = invalid_utf8_offset(head.substr(at, 4));
    char escape[16];
    if (bad == 0) {  // not the start of a UTF-8 character (or cut short by the 100 bytes)
      std::snprintf(escape, sizeof escape, "\\x%02X", static_cast<unsigned char>(head[at++]));
      out += escape;
      continue;
    }
    const std::size_t start = at;
    const char32_t c = next_code_point(head, at);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x80 && is_control(c)) {
      std::snprintf(escape, sizeof escape, "\\x%02X", static_cast<unsigned>(c));
      out += escape;
    } else if (is_control(c) || is_bidi_control(c)) {
      std::snprintf(escape, sizeof escape, "\\u%04X", static_cast<unsigned>(c));
      out += escape;
    } else {
      out.append(head.substr(start, at - start));
    }
  }
  if (cut < text.size()) {
    const auto characters = std::count_if(text.begin(), text.end(),
                                          [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; });
    out += "... (" + std::to_string(characters) + " characters)";
  }
  return out;
}

std::string strip_numeric_suffix(std::string_view name) { return std::string(name.substr(0, copy_number_start(name))); }

std::string name_in_file(std::string_view label, bool one_word) {
  // The '.' that would make the label's own end read as a copy number.
  const std::size_t copy_dot = copy_number_start(label);
  std::string out;
  out.reserve(label.size());
  for (std::size_t i = 0; i < label.size(); ++i) {
    const char c = label[i];
    if (c == '%' || c == '#' || c == '\\' || (one_word && c == ' ') || (i == copy_dot && c == '.'))
      append_escape(out, static_cast<unsigned char>(c));
    else
      out += c;
  }
  return out;
}

std::string label_of_name(std::string_view name) {
  if (name.find('%') == std::string_view::npos) return std::string(name);
  std::string out;
  out.reserve(name.size());
  for (std::size_t i = 0; i < name.size(); ++i) {
    const int high = name[i] == '%' && i + 2 < name.size() ? hex_value(name[i + 1]) : -1;
    const int low = high >= 0 ? hex_value(name[i + 2]) : -1;
    if (low >= 0) {
      out += static_cast<char>(high * 16 + low);
      i += 2;
    } else {
      out += name[i];
    }
  }
  return out;
}

std::string_view without_three_js_copy_number(std::string_view name) {
  const std::size_t underscore = name.rfind('_');
  if (underscore == std::string_view::npos || underscore == 0 || underscore + 1 == name.size()) return name;
  for (std::size_t i = underscore + 1; i < name.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return name;
  return name.substr(0, underscore);
}

std::string label_of_part_name(std::string_view name) {
  return label_of_name(name.substr(0, copy_number_start(name)));
}

std::string read_label(std::string_view name, NameOf kind, const std::string& file, SourceLoc loc,
                       const std::string& who) {
  std::string label = kind == NameOf::Part ? label_of_part_name(name) : label_of_name(name);
  if (label_fault(label)) {
    std::string what = who + " '" + shown_name(name) + "'";
    if (label_of_name(name) != name) what += " (read as '" + shown_name(label_of_name(name)) + "')";
    require_label(label, file, loc, what);
  }
  return label;
}

std::string label_as_word(std::string_view label) {
  const bool utf8 = invalid_utf8_offset(label) == std::string_view::npos;
  std::string out;
  out.reserve(label.size());
  for (std::size_t at = 0; at < label.size();) {
    const char c = label[at];
    if (is_plain_ascii(c)) {
      out += c;
      ++at;
      continue;
    }
    const std::size_t start = at;
    if (static_cast<unsigned char>(c) < 0x80 || !utf8 || is_white_space(next_code_point(label, at))) {
      // One byte, or every byte of a white-space character.
      if (at == start) ++at;
      for (std::size_t i = start; i < at; ++i) append_escape(out, static_cast<unsigned char>(label[i]));
    } else {
      out.append(label.substr(start, at - start));  // a non-ASCII letter or sign: readable as it is
    }
  }
  return out;
}

}  // namespace vern
