// Alternatives that are the same operation are one alternative, seen as
// often as all of them. Merging makes such options whenever two examples
// come out alike; later steps make more (houses that differ only in how
// many storeys they were seen with, once their storeys stretch alike;
// twins written as calls of one rule), and a grammar listing one
// alternative twice reads as if it had two.
#pragma once

#include "graph/grammar.hpp"

namespace vern {

// Joins c's options whose child is the same node: one option, where the
// first of them stood, its priority the sum of theirs (no priority counts
// as 1). Only options without a condition and with a literal priority
// join; the rest stay as they are. Returns whether any joined.
bool join_equal_options(Choose& c);

// An option without a condition whose priority is a number: the options
// the steps that rewrite alternatives by their weights read.
bool plain_option(const ChooseOption& o);

// A choice of two options or more, all plain.
bool plain_choice(const Choose& c);

}  // namespace vern
