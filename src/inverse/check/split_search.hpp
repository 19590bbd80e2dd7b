// The search for one split's placement while checking (check.hpp): where
// each part begins and ends among the example's boxes.
//
// Parts that hold boxes begin on cuts and end on cuts (check_cuts.hpp), or
// (floating) inside the empty stretch after their last box, at a length
// their child accepts. Consecutive parts that hold no box form a run of
// empty space whose inner boundaries are free. A placement is accepted
// when its lengths fit the part sizes (check_scale.hpp: one scale k for
// the relative parts, or the overflow factor c), and then every part's
// child matches its boxes.
//
// In a length query (free != nullptr) every placement is visited and the
// lengths they allow are collected instead: for a split across the open
// axis, the lengths all children accept; for one along it, the lengths the
// last run of empty space can stretch to.
//
// The search itself is in split_search.cpp; what the part sizes allow of a
// placement in split_sizes.cpp; solving for a continuous random value the
// sizes use in split_solve.cpp; the length queries in check_lengths.cpp.
#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "base/inline_list.hpp"
#include "forward/scope.hpp"
#include "graph/grammar.hpp"
#include "inverse/check/check_bindings.hpp"
#include "inverse/check/check_cuts.hpp"
#include "inverse/check/check_free_scope.hpp"
#include "inverse/check/check_scale.hpp"
#include "inverse/check/check_witness.hpp"
#include "inverse/sizes/support.hpp"

namespace vern::check_detail {

class Matcher;

struct PartInfo {
  bool relative = false;
  Support share;  // the size's support, negative values removed (derive() fails on them)
  NodeId child = 0;
  bool nil = false;
  bool primitive = false;  // a leaf taking exactly one box
  bool vanishes = false;   // derives nothing on any scope
  bool random = false;     // the size draws or uses an unknown: reported in the witness
};

// The parts of a split and how their sizes are evaluated, shared by
// matching and length queries (Matcher::setup_split).
struct SplitSetup {
  Axis axis = Axis::X;
  AxisMap am;
  double length = 0;                    // the scope's length along the axis (free axis: the last box face)
  bool free_axis = false;               // the split runs along a FreeScope's open axis
  double l0_length = 0, l1_length = 0;  // free axis: the scope's length at lmin and at lmax
  std::shared_ptr<const Cuts> cuts;
  std::vector<PartInfo> parts;
  std::vector<int> finite;  // unknowns with few values, tried one by one
  std::vector<std::vector<double>> finite_values;
  int solve_for = -1;  // the one continuous unknown, solved per placement
};

// Where one part lies in a placement.
struct Placement {
  bool filled = false;    // holds boxes: spans cuts [from, to]
  bool floating = false;  // its end lies inside the empty stretch after cut `to`
  std::size_t from = 0, to = 0;
  Support lengths;       // floating: the lengths its child accepts (until queried: all up to the next box)
  double length = 0;     // floating: the length chosen for the witness and the match
  bool queried = false;  // floating: `lengths` comes from the child
};

class SplitSearch {
 public:
  SplitSearch(Matcher& m, NodeId id, const Split& op, const Scope& s, SplitSetup& st, const FreeScope* free);

  // Normal: true when a placement matched. Query: false; see collected().
  // With floating false, every part ends on a cut (the first pass: enough
  // for any example whose boundaries all lie on box faces, and far cheaper).
  bool run(Mode mode, bool floating = true);

  bool any_sized() const { return any_sized_; }
  const Support& collected() const { return collected_; }

 private:
  static constexpr double kTiny = std::numeric_limits<double>::min();

  ScaleState initial(bool track_set = true) const;
  std::size_t none() const { return parts_.size(); }
  double at(std::size_t cut) const { return cuts_.at[cut]; }

  // ---- the size constraints (split_sizes.cpp) ----

  // A part that holds boxes, of length len.
  void constrain_filled(const PartInfo& p, double len, ScaleState& sc) const;
  static Support hull_if_integer(const Support& s) { return s.integer ? Support::range(s.lower(), s.upper()) : s; }
  // k with k * r = len (within the tolerance) for some r of the share.
  Support ratio(double len, const Support& share) const;
  // c with a = c * len for some a of the share.
  Support inverse_ratio(const Support& share, double len) const;
  // May part p hold no box (a member of a run)? A part that derives
  // something must then have length 0: a zero share (Fill, NoFill) or a
  // relative part under overflow. A lone part between two cuts is checked
  // for real in complete(), so it may try.
  bool may_be_empty(const PartInfo& p, bool starts_run) const;
  bool may_hold_boxes(const PartInfo& p) const;
  // What the parts of a run can add up to: al..ah metres plus rl..rh
  // shares of the scale.
  struct RunSums {
    double al = 0, ah = 0, rl = 0, rh = 0;
    bool possible = true;
  };
  RunSums run_sums(std::size_t first, std::size_t last, bool final) const;
  // Parts [first, last) share an empty stretch of length gap.
  void constrain_run(std::size_t first, std::size_t last, double gap, bool final, ScaleState& sc) const;
  // The lines bounding a floating part's length as functions of the scale,
  // for one interval of its share and one of its child's lengths. The run
  // after it, parts [first, last), fills the rest up to end.
  void floating_lines(std::size_t f, const RunSums& r, double end, bool final, std::pair<double, double> share,
                      std::pair<double, double> len, std::vector<Line>& lowers, std::vector<Line>& uppers) const;
  // A floating part and the run after it: its length l and the scale must
  // satisfy every line at once.
  void constrain_floating(std::size_t f, std::size_t first, std::size_t last, double end, bool final,
                          ScaleState& sc) const;
  // A length for floating part f at scale k: the middle of what fits.
  std::optional<double> floating_length(std::size_t f, std::size_t first, std::size_t last, double end, bool final,
                                        double k) const;
  // Closes the run [first, last) that ends at `end`; it began at cut
  // `anchor`, or at the end of floating part `floating`.
  void close_run(std::size_t floating, std::size_t first, std::size_t last, std::size_t anchor, double end, bool final,
                 ScaleState& sc) const;

  // ---- the search (split_search.cpp) ----

  bool free_axis() const { return free_ && st_.free_axis; }
  // May part i, holding the boxes of cuts [j, e], end in the empty stretch after e?
  bool may_float(std::size_t i, std::size_t e) const;
  // The lengths part i's child accepts beyond its last box, up to the next box.
  const Support& floating_lengths(std::size_t i, std::size_t j, std::size_t e);
  bool close_checked(std::size_t floating, std::size_t first, std::size_t last, std::size_t anchor, double end,
                     bool final, ScaleState& sc) const;
  // A floating part asks its child for the lengths it accepts only once
  // the whole placement fits with any length up to the next box: the query
  // costs far more than the test. Then the placement is tested again.
  bool resolve_floating(ScaleState& sc);
  bool place(std::size_t i, std::size_t anchor, std::size_t run_first, std::size_t floating, ScaleState sc);

  // The runs of the current placement, as place() closed them.
  struct Run {
    std::size_t first, last, anchor;
    double end;
    bool final;
    std::size_t floating;  // the floating part before it, or none()
  };
  // Most splits place a few runs: held in place, not on the heap (a
  // list per call was the check's most frequent allocation).
  using Runs = InlineList<Run, 4>;
  Runs runs() const;
  double run_start(const Run& r) const;
  // The whole placement's scale state, replayed (for solving).
  ScaleState replay(bool track_set = true) const;
  // A scale inside the set that fits: the middle of its first interval.
  double pick_scale(const ScaleState& sc) const;
  // A placement fits the sizes: bind what it pins down, match every part.
  bool complete(const ScaleState& sized);
  // Matches the children of the parts that hold boxes (and of lone empty
  // parts, which must derive nothing there).
  bool children_match(bool lone_runs);
  // One line per part whose size is random: the value that reproduces it.
  void add_witness(double k);

  // ---- solving for a continuous random value (split_solve.cpp) ----

  // How far the placement is from fitting: 0 when it fits. Misses in
  // metres count in tolerances, so a length that cannot fit at all (a run
  // whose shares fall to 0) never looks better than a scale that almost
  // fits: the scan in solve() must not be drawn to it.
  double violation(const ScaleState& sc) const;
  // Re-evaluates the part sizes (after an unknown was bound or unbound).
  bool refresh_shares();
  // Where the unknown enters the sizes of parts holding boxes linearly (a
  // share ~s1 beside ~(10 - s1), a height 0.5 * s1 + 1), their lengths pin
  // it down: the values solving those equations, to try before scanning.
  // Only a shortcut: each is still tried in full. Leaves the part sizes
  // as the last guess made them (solve() evaluates them again).
  std::vector<double> linear_guesses(Unknown& u);
  // Finds a value of the unknown st_.solve_for that makes this placement
  // fit: a scan of its support, then a golden-section refinement around the
  // best point (the misfit is piecewise linear and V-shaped at a solution).
  // The unknown is left unbound, the part sizes evaluated at the value
  // found (the caller binds it: no second evaluation), or over the
  // unknown's support when none is found.
  std::optional<double> solve();
  // The middle of the stretch of values around v that fit, found by
  // bisection: a value at the edge of what fits would leave no slack for
  // the parts below (which see it through their own tolerance).
  template <typename Fits>
  double centre(double v, Fits& fits) const;

  // ---- length queries (check_lengths.cpp) ----

  // Query across the open axis: the lengths every child accepts.
  bool collect_across(const ScaleState&);
  // Query along the open axis: the last run, from cut `anchor` to the
  // scope's open end, can be any length its parts and the scale allow.
  void collect_open_end(std::size_t anchor, std::size_t run_first, const ScaleState& sc);

  Matcher& m_;
  NodeId id_;
  const Split& op_;
  const Scope& s_;
  SplitSetup& st_;
  const Cuts& cuts_;
  std::vector<PartInfo>& parts_;
  Axis axis_;
  double length_;
  double tol_;
  const FreeScope* free_;
  Mode mode_ = Mode::Fill;
  bool floating_ = true;
  std::vector<Placement> placement_;
  // Per part and span of cuts: whether its child matched, and the witness
  // lines it left; the lengths its child accepts (across the open axis);
  // the lengths it accepts floating.
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::pair<bool, std::vector<WitnessLine>>> memo_;
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, Support> lengths_memo_;
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, Support> floating_memo_;
  bool any_sized_ = false;
  Support collected_;
};

}  // namespace vern::check_detail
