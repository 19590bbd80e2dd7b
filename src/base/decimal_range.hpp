// Decimal numbers a double cannot hold: too large, or too small.
//
// std::from_chars says result_out_of_range both for a number beyond the
// largest double (1e999) and for one nearer to zero than the least
// (1e-400: below 4.9e-324 it would read as 0), and leaves the value as it
// was. The readers refuse both, and say which: a number too small to hold
// is not "too large".
#pragma once

#include <string_view>

namespace vern {

// For a decimal ([-+]digits[.digits][(e|E)[-+]digits]) that from_chars
// found out of range: whether that is because it is too near zero (else
// it is too large).
bool decimal_underflows(std::string_view text);

}  // namespace vern
