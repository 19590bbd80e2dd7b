// Plain numbers read straight from text: the fast path of the OBJ reader.
//
// Almost every number in an exported OBJ is a short decimal ("1.802",
// "-0.5", "17"). These scanners read only that plain form, to exactly the
// value std::from_chars gives, and refuse anything else (exponents, a '+',
// ".5", long mantissas) by returning nullptr: the caller then takes its
// general path, which also owns every error message.
#pragma once

#include <cstdint>

namespace vern {

// -?[0-9]+(\.[0-9]+)? with at most 2^53 as its digits read as a whole
// number and at most 22 digits after the point. Such a value is that whole
// number divided by a power of ten, both exact doubles, so the one
// correctly rounded division is the correctly rounded value (Clinger's
// fast path): bit for bit what from_chars returns. Returns the end of the
// number, or nullptr when the text at p is not of this form.
const char* scan_plain_decimal(const char* p, const char* end, double& value);

// [0-9]+ of at most 9 digits (no sign): an OBJ index counted from 1.
// Returns the end of the digits, or nullptr.
const char* scan_plain_index(const char* p, const char* end, std::uint32_t& value);

}  // namespace vern
