// Numbers as text: the shortest decimal that reads back to the same double.
//
// Used by the grammar writer and by the mesh writers so that what we write
// parses back bit for bit, and the same number is always the same text.
#pragma once

#include <string>

namespace vern {

// Shortest round-trip form ("0.1", "2", "1e-07"); "-0" is written "0".
std::string format_number(double v);

// Appends the same text to out without a temporary string (hot path).
void append_number(std::string& out, double v);

}  // namespace vern
