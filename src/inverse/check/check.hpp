// Checking: does this grammar derive this example exactly, and how?
//
// The test oracle of inference (every example must be derivable from the
// grammar inferred from it, docs/inference.md) and a tool in its own right: "does
// this building fit the style?".
//
// The grammar derives the example when some sequence of choices (options
// whose condition can hold and whose priority can be > 0) and random values
// (each draw within its distribution's support) makes derive() produce
// exactly the example's labelled boxes: the same multiset of (label, world
// axis-aligned box) within the tolerance, nothing extra, nothing missing.
// A terminal is compared by its scope's world bounds, which a quarter turn
// leaves unchanged.
//
// How: a matcher walks the operation graph top-down with the boxes that lie
// inside each scope. A split places its part boundaries on the positions
// where no box crosses (the cuts of the ordered-box algorithm, snapped
// within the tolerance) and accepts a placement when the part lengths can
// come from the part sizes: absolute lengths within their size's support,
// relative lengths with one common scale k (len_i = k * r_i), or the
// overflow rule of docs/grammar.md when the absolute parts alone exceed the
// scope. Consecutive parts that receive no box form one stretch of empty
// space whose inner boundaries may lie anywhere. A part may also end inside
// the empty space after its last box (a skyscraper plot above its towers):
// its child is asked which lengths it accepts, and the part's size must
// agree. Repeats try the tile counts their size allows; choices try their
// options in order; a random argument with few values (randint, choice) is
// tried value by value, a continuous one is solved for, numerically, from
// the first split whose sizes use it. Random constants with few values are
// enumerated once per derivation; continuous ones are solved like arguments.
// The search first keeps every boundary on a box face (enough for what
// inference writes) and only then lets parts end in empty space.
// Contents placed with T or S may leave their part's slice, where no cut
// lies (inference's placements of a pinwheel): where such a node fails to
// match but the grammar below it has one outcome (no draw, no alternatives,
// no parameters), it is derived on its scope and compared with the boxes
// there instead (deterministic_subtree.hpp), which is exact.
//
// Exact: sizes whose random draws each appear once (interval arithmetic),
// few-valued draws, one continuous value per split. Approximate (may accept
// what derive() cannot produce, or miss a solution): a continuous value
// used by several operations is pinned down by the first; inside a length
// query a continuous value counts as independent draws; runs of two or more
// empty parts treat non-nil children statically.
//
// What cannot be decided this way is reported in the mismatch as
// "cannot check: ..." (random T/S/R values or axes, several continuous
// random values in one split, splits of scopes turned by angles other than
// quarter turns), never guessed. Not found: a boundary in empty space at
// the start of a part, or one that moves repeat tiles starting at it, or a
// comp's faces.
//
// The pieces, each a file of src/inverse/ (check_detail, private):
//   check.cpp             this entry point: the random constants, a Matcher per choice of them
//   check_matcher.hpp     the Matcher, which walks the grammar; it matches terminals, transforms
//                         and comp faces in check_matcher.cpp, splits in check_split.cpp, repeats
//                         in check_repeat.cpp, choices and calls in check_choices.cpp, answers
//                         length queries in check_lengths.cpp and reports in check_report.cpp
//   split_search.hpp      the search for one split's placement (split_search.cpp), what the part
//                         sizes allow (split_sizes.cpp), solving for a random value (split_solve.cpp)
//   check_cuts.hpp        where boxes may be cut along a scope's axis
//   check_scale.hpp       the scales a placement leaves possible
//   check_bindings.hpp    parameters, constants, unknowns and the trail of their bindings
//   check_emptiness.hpp   where a node may leave empty space
//   check_free_scope.hpp  a scope whose length along one axis is left open
//   check_budget.hpp      the matching-step limit
//   check_witness.hpp     the witness lines; check_text.hpp, how messages spell things
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "base/hashing.hpp"
#include "graph/grammar.hpp"
#include "inverse/load/example.hpp"

namespace vern {

struct CheckOptions {
  // Absolute, in metres: two coordinates this close are the same. 0 means
  // 1e-6 times the example's largest extent or coordinate (default_tolerance).
  double tolerance = 0;
  // Where the example's coordinates are snapped to a noise level (the
  // tolerance; snapped_coordinates.hpp), places still apart are cuts apart
  // however close: faces closer than this are one cut (0: the tolerance),
  // while sizes fit within the tolerance.
  double cut_tolerance = 0;
  // Matching steps (operations tried, placements considered) before giving
  // up with a vern::Error (Limit).
  std::uint64_t max_steps = 10'000'000;
  // Spell the witness out (CheckResult::witness); parts are kept either way.
  bool witness = true;
  // Where any derivation that reproduces the example will do (a rewrite
  // checked, lengths read): each choose tries first the alternatives that
  // have matched most often so far in this example, ties in the written
  // order. A city's cells are mostly plain towers, and its nested
  // courtyards, written first, were tried and failed at each. Where two
  // alternatives match, another derivation than the written order's may
  // be found (its witness and parts), and where an early choice fails
  // later, the answer may be "no": derives_examples() then asks again in
  // the written order.
  bool learned_order = false;
  // Only whether the example derives (a rewrite verified): the result
  // keeps no witness, parts or steps, and matching keeps no record of them
  // (a city's check copied 850,000 witness lines into the memos of splits
  // it never tried twice).
  bool answer_only = false;
};

// Where in a derivation a node runs: a hash of the chain of nodes from
// the start rule's body down to it, and of the part (1, 2, ... of a split)
// or option (of a choose) each step entered through (0: any other step,
// such as a call's body or a transform's child). The same place in every
// example has the same path, which is how values seen at one place are
// lined up across examples (joint_sizes.hpp).
inline std::uint64_t derivation_path(std::uint64_t parent, NodeId node, std::uint32_t slot) {
  return path_hash(parent, (std::uint64_t{node} << 20) + slot + 1);
}

// One part of a split with a random size, as the derivation that
// reproduces an example places it; also a repeat whose tile size draws,
// as a split of one part: `split` the repeat, part 0, `length` the tiles'
// length and `value` their count.
struct MatchedPart {
  std::uint64_t path = 0;  // the split's derivation_path
  NodeId split = 0;
  std::size_t part = 0;
  double length = 0;  // metres, along the split's axis
  double value = 0;   // the size's value (a relative size: the share, for the scale chosen)
  bool random = true;  // false: a size written as a number, beside one that draws
};

// One step of the derivation that reproduces an example, as data, in
// derivation order: an alternative taken, a value pinned down, a repeat's
// tiles (then each tile's steps, tile after tile).
struct CheckStep {
  enum class Kind : std::uint8_t { Alternative, Value, Part, Tiles };
  Kind kind = Kind::Alternative;
  NodeId node = 0;        // the choose; the split that pinned the value down; the split; the repeat
  std::size_t index = 0;  // Alternative: the option taken; Part: the part
  double value = 0;       // Value: the value; Part: its size's value; Tiles: how many tiles
  double length = 0;      // Tiles: each tile's length; Part: its length
};

struct CheckResult {
  bool derivable = false;
  // When derivable: what was matched, then the choices and random values
  // that reproduce the example, one line each, in derivation order, e.g.
  //   "start: plot on x 0..10, y 0..10, z 0..10, 3 boxes"
  //   "plot: alternative 2 of 2 (split(x) at 24:10)"
  //   "garage, split(z) at 26:12, part 1: 1.04 (~rand(0.75, 1.25))"
  //   "plot, floors at 53:10: numFloors = 3 (randint(minFloors, maxFloors))"
  std::vector<std::string> witness;
  // When derivable: every part of a split with a random part in that
  // derivation, in order.
  std::vector<MatchedPart> parts;
  // When derivable: its choices, values and repeats, in order.
  std::vector<CheckStep> steps;
  // When not: where the attempt that got furthest (the most boxes in parts
  // it had finished, then the deepest) failed and why, e.g.
  //   "at house (25:1), split(z) at 25:10 on x 0..6.66667, y 0..10, z 0..10: no placement of the
  //    parts on the cuts of the example's boxes fits sizes ~2 : ~1 (cuts at z = 0, 6.5, 10)"
  // prefixed by "with N = 9, M = 8: " when random constants were tried
  // value by value, and followed by notes on what could not be checked.
  std::string mismatch;
};

// Checks whether `grammar`, started with its start rule on the axis-aligned
// scope [0, scope_size], derives exactly `boxes` (already translated so the
// scope starts at the origin). Throws vern::Error (Limit) when more than
// options.max_steps steps are needed, or a repeat would make more tiles
// than that (each tile is matched once); and (Input) where derive() fails
// whatever it draws and generate says so: a repeat's tile size never > 0.
// A repeat's error names grammar.source_name:line:column and the rule
// chain, as generate's does.
CheckResult check_example(const Grammar& grammar, const std::vector<LabelledBox>& boxes, glm::dvec3 scope_size,
                          const CheckOptions& options = {});

}  // namespace vern
