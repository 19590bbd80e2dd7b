// Sizes that vary together are drawn once (issue 4, "sibling sizes that
// vary together stay together").
//
// Merging keeps, per part, the range of the values the examples showed,
// and a derivation draws each part's size on its own: a house 4 to 10 m
// high and its garage half as high become two draws, so variants put tall
// garages on short houses. And a split of two parts whose sizes both vary
// (`~rand : rect | ~rand : nil`) draws twice where the examples vary in
// one way only.
//
// What the examples did is known exactly once the grammar is written:
// `check` finds, per example, the derivation that reproduces it and the
// length of every random part in it (MatchedPart, lined up across
// examples by derivation_path). This step reads those lengths region by
// region (a region: what one derivation runs below the start or below an
// alternative of a choice, through splits, transforms, choices and calls
// of rules that do not recurse, but not into repeats, whose tiles draw
// anew; a size inside an alternative is compared over the examples that
// took it), and per region:
//   - in a split whose relative parts all vary, only their shares are
//     free: the last one is the rest, `~(10 - s1)`;
//   - a share written as one weight whose length still varies (the scale
//     merging read the split's other weights in) is a varying size too
//     where it follows a draw in metres (storeys 2u + 4.5 m over an
//     arcade u high);
//   - each other varying size, in derivation order, is compared with the
//     ones before it: one that is a straight-line function of an earlier
//     one (within the tolerance; four examples or more, or, in a region
//     that fewer show, two or more for equal sizes) is written as that function, `~(0.5 * s1)`; one that follows an earlier one closely (|correlation| >= 0.9,
//     five examples or more) is that function plus a drawn deviation
//     `s2 = rand(-e, e)` as wide as the examples' largest; one the region's
//     examples all show the same is that constant (a piece merged from
//     places that each show their own, `choice(1.2, 1.5)`, keeps each
//     place's, and that alone is reason to rewrite the region where four
//     examples show it); any other is drawn,
//     `s2`, from the distribution its values fit best (fit_distribution);
//   - a size inside a repeat that every tile of a building shows the same
//     (the window width kept on every storey, a door bay's place), while
//     buildings differ, is drawn once per building by the region, not
//     anew in each tile, whether or not another size follows it;
//   - a repeat's drawn tile size is a size too (check reports its tiles'
//     length and count): repeats that show one length in every building
//     (both fronts' storeys) take one draw, and a drawn tile size is
//     drawn from the range most likely to have given each building's
//     tile count (s in [t, t n / (n - 1)) gives n tiles of t), not from
//     the tiles' lengths, which are shorter than the sizes drawn; a tile
//     count that is a straight line of a size drawn before it (runs of
//     bays beside an entrance at any place) makes the repeat a repeatN
//     of that line.
// A region with something to join becomes a rule with those draws as
// parameters, `buildingSizes(s1, e1) --> split(x){ ... }`, called where
// the region stood with the draws as arguments; the rules it called are
// written out inside it, but for a choice whose sizes change: that is a
// rule of its own taking the same parameters. The whole change is kept
// only when every example still checks.
#pragma once

#include <cstddef>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/load/example.hpp"

namespace vern {

struct JointSizesOptions {
  double tolerance = 1e-6;             // metres
  bool uniform_distributions = false;  // drawn sizes as rand(min, max) (--distributions uniform)
  std::size_t min_examples = 4;        // fewer examples show no line and no constant
  // Two sizes equal in every example that shows both, while they vary,
  // are one size from this many examples on, in a region seen in fewer
  // than min_examples: equality needs no fitted line, and varying sizes
  // equal to the last millimetre by chance are not seen (the wall and the
  // roof of one wing, three houses).
  std::size_t min_equal = 2;
  unsigned threads = 0;                // for checking the examples (0: one per core)
};

struct JointSizes {
  std::size_t regions = 0;  // regions rewritten (0: the grammar is unchanged)
  std::size_t joined = 0;   // sizes no longer drawn on their own
  // Whether the grammar left behind (rewritten or not) derives every
  // example within options.tolerance: joining checks it anyway, so infer
  // need not check again.
  bool derives_examples = false;
};

// Rewrites g in place (see above). examples: as given to infer; each is
// checked at its own origin on its own extent.
JointSizes join_sizes(Grammar& g, const std::vector<Example>& examples, const JointSizesOptions& options);

}  // namespace vern
