// A choice made once per building and kept below (issue 23, item 2): the
// bays of one house all windows with a railing or all without, each bay
// a panel now and then. Merging sees each bay's choice on its own and
// writes one free choice of panel, railing bay and window bay, so that
// almost every variant mixes the two kinds no building of the style mixes.
//
// The examples' witnesses show it: per example, the alternatives a choice
// takes. Alternatives that never share an example, though each is taken
// in several and, drawn freely, would have shared some (three examples or
// more expected), are kinds kept per building (the largest such set); the
// others go with any kind. An alternative that holds one call of a rule
// that is a choice of its own (a frame of render | opening | render, maybe
// a rule of its own, whose opening is glass or an infill, beside a bay of
// paired windows) is read through it as well, its draws those right after
// the choice took the alternative: kinds may lie on both levels (houses of
// pairs and glass, houses of infills and glass). The choice then takes a
// parameter, `kind(b) : b == 0 --> ...`,
// passed down from the start rule through every rule that leads to it,
// drawn once per building there (`randint(0, k - 1)`). Kept only if every
// example still derives.
//
// A building may take one kind at some place always (its ground floor's
// bays of the first kind, under storeys of the kind kept, one row rule for
// both): then every building of the second kind shows both, but no row
// does. Such kinds are read row by row (each repeat's tiles apart), and
// where keeping them does not derive every example, the calls that pass
// the kind on are made, place by place, to pass one kind always
// (`row(0)` in the ground floor's split), kept where more examples derive,
// until all do.
#pragma once

#include <cstddef>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/check/derives_examples.hpp"
#include "inverse/load/example.hpp"

namespace vern {

// Whether some choice of g shows kinds kept per building (what
// keep_choices would try), by g's witnesses: read where known, else
// checked. Joining sizes leaves choices and their alternatives as they
// are, so asked before it, this says whether keep_choices is worth its
// check after it.
bool shows_kept_choices(const Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                        Witnesses& witnesses);

// Rewrites g in place (one choice, the first found in rule order);
// returns how many choices became kept (0: g as it was). witnesses: g's,
// read where known, else checked; not known when it returns having
// changed g.
std::size_t keep_choices(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                         Witnesses& witnesses);

}  // namespace vern
