// The words of the grammar language that names cannot take. One list, read
// by the parser (which refuses them) and the writer (which must never
// produce them).
#pragma once

#include <string_view>

namespace vern {

// Words that start an operation; a rule labelled so could not be called.
bool is_operation_word(std::string_view s);

// Whether a rule may take `s` as its label: a letter or '_', then letters,
// digits and '_', and no operation word.
bool is_rule_label(std::string_view s);

// Words a parameter or constant may not take: a bare x, y, z, pi or rand
// already reads as an axis, a number or a draw; operation words likewise.
// Function names are free: `max` is the value, `max(a, b)` the function.
bool is_reserved_value_name(std::string_view s);

}  // namespace vern
