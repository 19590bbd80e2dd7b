// The matcher of check.hpp: does a grammar, run on a scope, derive exactly
// these boxes? A private header shared by the files that implement it.
//
// A Matcher walks the operation graph top-down with the boxes that lie
// inside each scope, for one choice of the random constants (check.cpp
// tries them). Each kind of operation is matched in a file of its own:
//   check_matcher.cpp  the walk: terminals, nil, transforms, comp faces, expressions
//   check_split.cpp    splits (their placements are searched by split_search.hpp)
//   check_repeat.cpp   repeat and repeatN: which tile counts, which boxes per tile
//   check_choices.cpp  alternatives and rule calls with their arguments
//   check_lengths.cpp  length queries: which lengths along an open axis a node accepts
//   check_report.cpp   what a match leaves: the deepest failure, the witness
// A match that fails takes back what it added (witness lines, bindings of
// unknowns), so the walk is a plain backtracking search.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base/error.hpp"
#include "forward/scope.hpp"
#include "graph/grammar.hpp"
#include "inverse/check/check.hpp"
#include "inverse/check/check_bindings.hpp"
#include "inverse/check/check_budget.hpp"
#include "inverse/check/check_cuts.hpp"
#include "inverse/check/check_emptiness.hpp"
#include "inverse/check/check_free_scope.hpp"
#include "inverse/check/check_scale.hpp"
#include "inverse/check/check_text.hpp"
#include "inverse/check/check_witness.hpp"
#include "inverse/check/deterministic_subtree.hpp"
#include "inverse/check/split_search.hpp"
#include "inverse/sizes/support.hpp"

namespace vern::check_detail {

// derive()'s default nesting limit: deeper recursion is an error there, so
// no derivation goes deeper.
inline constexpr std::size_t kMaxDepth = 1000;
// Random values with at most this many possibilities (randint(2, 5),
// choice(...)) are tried one by one, which is exact.
inline constexpr std::size_t kMaxEnumerated = 64;
// Repeat tile counts tried for one random tile size.
inline constexpr double kMaxTileCounts = 100000;

// Why the attempt that got furthest failed: the one that had matched the
// most boxes in parts it had finished (a split's earlier parts, a
// repeat's earlier tiles), then the deepest. Depth alone named a wing's
// door bay tried at the wrong index, deep in a part that matched later,
// where the house failed in its storeys, one part on.
struct Mismatch {
  std::size_t progress = 0;
  int depth = -1;
  std::string message;

  bool further_than(const Mismatch& o) const {
    return progress != o.progress ? progress > o.progress : depth > o.depth;
  }
};

// The boxes of a repeat's tiles: the tile each box lies in, by tile (the
// boxes of one tile in the order they were added). A repeat may make
// millions of tiles, most of them empty: only the boxes are kept.
class Tiling {
 public:
  void clear() {
    boxes_.clear();
    next_ = 0;
  }
  void add(std::uint64_t tile, std::uint32_t box) { boxes_.emplace_back(tile, box); }
  // Orders the boxes by tile, once all are added.
  void sort();
  // The boxes of tile i: tiles 0, 1, 2, ... are taken in turn. The list
  // is this tiling's own, refilled by the next take (a list per tile was
  // one allocation in thirty of the city's checks).
  const BoxList& take(std::uint64_t i);

 private:
  std::vector<std::pair<std::uint64_t, std::uint32_t>> boxes_;  // (tile, box)
  std::size_t next_ = 0;
  BoxList taken_;
};

// A random argument with few values, tried value by value.
struct ArgChoice {
  std::size_t arg;
  std::vector<double> values;
};

struct TileCount {
  double n = 0;
  double size = 0;  // repeat: a tile size giving n tiles
};

class Matcher {
 public:
  // floating: whether a part may end inside empty space (a boundary no box
  // face marks); a first attempt without is far cheaper and settles every
  // example whose boundaries all lie on box faces. Sizes fit within
  // `tolerance`; faces within `cut_tolerance` are one cut
  // (CheckOptions::cut_tolerance).
  Matcher(const Grammar& g, const std::vector<LabelledBox>& boxes, double tolerance, double cut_tolerance,
          Budget& budget,
          DeterministicSubtrees& deterministic, std::vector<Slot> constants, std::vector<Unknown> unknowns,
          bool floating, bool learned_order = false, bool answer_only = false);

  // Does the start rule, run on `start`, derive exactly the boxes `all`?
  bool run(const Scope& start, const BoxList& all);

  // After a successful run: its random split parts and its witness.
  std::vector<MatchedPart> matched_parts() const;
  std::vector<CheckStep> steps() const;
  std::vector<std::string> witness() const;
  // After a failed one: why, and what could not be checked.
  const Mismatch& mismatch() const { return best_; }
  const std::string& uncheckable() const { return uncheckable_; }
  bool open_ends_unsupported() const { return open_ends_unsupported_; }

 private:
  friend class SplitSearch;

  // Restores what a match or query added: on failure, its witness lines
  // and bindings; always, the unknowns drawn inside it (out of scope now).
  struct Marks {
    std::size_t witness, trail, unknowns;
  };
  Marks marks() const { return {witness_.size(), vars_.trail_size(), vars_.unknown_count()}; }
  void restore(const Marks& m, bool keep);

  // ---- messages and witness (check_report.cpp) ----

  std::string rule_label() const;
  RuleId current_rule() const { return vars_.rule(); }
  std::string expr_text(const Expr& e, RuleId rule) const { return check_detail::expr_text(g_, e, rule); }
  std::string expr_text(const Expr& e) const { return expr_text(e, current_rule()); }
  std::string node_ref(NodeId id, RuleId rule) const { return check_detail::node_ref(g_, id, rule); }
  std::string node_ref(NodeId id) const { return node_ref(id, current_rule()); }
  WitnessLine line(WitnessLine::Kind kind, NodeId node) const;
  void note_value(NodeId node, const std::string& name, double v, const Origin& origin);
  std::string where(NodeId id, const Scope& s) const;
  std::string list_boxes(const BoxList& list) const;
  // Would a failure here be recorded? Messages are built only then: most
  // attempts fail, and their text would cost more than the attempt.
  bool recording() const { return quiet_ == 0 && here().further_than(best_); }
  // Where the match stands now, as a mismatch here would rank.
  Mismatch here() const { return {progress_, depth_, {}}; }
  // Counts the boxes of the parts a match finishes towards progress_,
  // for as long as the guard lives (a split's or a repeat's children).
  class Finished {
   public:
    explicit Finished(Matcher& m) : m_(m), base_(m.progress_) {}
    ~Finished() { m_.progress_ = base_; }
    Finished(const Finished&) = delete;
    Finished& operator=(const Finished&) = delete;
    void add(std::size_t boxes) { m_.progress_ += boxes; }

   private:
    Matcher& m_;
    std::size_t base_;
  };
  // Records why a match failed, keeping the deepest; length queries
  // (quiet) record nothing: their failures are not the example's.
  bool fail(NodeId id, const Scope& s, const std::string& what);
  bool cannot_check(NodeId id, const Scope& s, const std::string& what);
  // What derive() refuses whatever it draws (a tile size never > 0), and
  // work beyond the limits, stop the whole check, with generate's message:
  // the grammar's file:line:col, the rule chain and a hint.
  [[noreturn]] void refuse(ErrorKind kind, SourceLoc loc, const std::string& message, const std::string& hint) const;
  // "plot > house(3) > floors(?)": the running rules, with their arguments
  // as far as they are known.
  std::string rule_chain() const;

  // ---- expressions (check_matcher.cpp) ----

  // What an expression can be here. `what` (and `number`, when not 0)
  // name it in messages. Expressions that use no parameter and no random
  // constant are the same everywhere: their values are kept.
  std::optional<Possible> evaluate(const Expr& e, NodeId id, const Scope& s, const char* what, std::size_t number = 0);
  std::optional<double> exact_number(const Expr& e, NodeId id, const Scope& s, const char* what);
  std::optional<Axis> exact_axis(const Expr& e, NodeId id, const Scope& s, const char* what);

  // ---- the walk (check_matcher.cpp) ----

  // Does node `id`, run on scope s, derive exactly the boxes `inside`?
  bool match(NodeId id, const Scope& s, const BoxList& inside);
  // A node the matcher could not follow, derived on s and compared
  // (deterministic_subtree.hpp): exact, so its verdict replaces what the
  // attempt recorded.
  bool derives_here(NodeId id, const Scope& s, const BoxList& inside, const Mismatch& before);
  bool dispatch(NodeId id, const Scope& s, const BoxList& inside);
  bool match_terminal(NodeId id, const std::string& label, const Scope& s, const BoxList& inside);
  // T, S and R as functions of the scope (their values must be exact).
  std::optional<std::function<Scope(const Scope&)>> transform(NodeId id, const Scope& s);
  bool match_comp(NodeId id, const Comp& op, const Scope& s, const BoxList& inside);

  // ---- splits (check_split.cpp) ----

  // "~2 : ~1", for messages.
  std::string sizes_text(const Split& op) const;
  // The axis, cuts and parts of a split on scope s; with fs, the scope's
  // length along fs's open axis is free (s is its longest form).
  std::optional<SplitSetup> setup_split(NodeId id, const Split& op, const Scope& s, const BoxList& inside,
                                        const FreeScope* fs);
  // Calls f() for every combination of the few-valued unknowns, bound, with
  // the part sizes evaluated; stops at the first f() that returns true.
  template <typename F>
  bool each_sizing(NodeId id, const Split& op, const Scope& s, SplitSetup& st, F f);
  bool match_split(NodeId id, const Split& op, const Scope& s, const BoxList& inside);

  // ---- repeats (check_repeat.cpp) ----

  // "size 1" or "count randint(3, 5)": what decides a repeat's tile count.
  std::string repeat_what(NodeId id) const;
  // The tile counts a repeat or repeatN may make on scope s, in order.
  std::optional<std::vector<TileCount>> tile_counts(NodeId id, const Scope& s, Axis a, bool& random);
  // n tiles of repeat `id`, refused when matching them would take more
  // steps than the check may: each tile is matched once. Refused before
  // any is laid out, as derive() refuses more tiles than its limit.
  std::uint64_t tiles_within_limit(NodeId id, double n) const;
  // Do n equal tiles put every boundary where no box crosses? Fills `tiles`.
  bool tiles_fit(const BoxList& inside, const AxisMap& am, double length, std::uint64_t n, Tiling& tiles) const;
  struct RepeatSetup {
    Axis axis = Axis::X;
    std::optional<AxisMap> am;
    NodeId child = 0;
    std::vector<TileCount> counts;
    bool random = false;
  };
  std::optional<RepeatSetup> setup_repeat(NodeId id, const Scope& s);
  bool match_repeat(NodeId id, const Scope& s, const BoxList& inside);

  // ---- choices and calls (check_choices.cpp) ----

  struct Options {
    std::vector<bool> applicable;
    bool nil_possible = true;  // every option may fail: the label derives nothing
    bool any = false;
  };
  std::optional<Options> options_of(NodeId id, const Choose& op, const Scope& s);
  bool match_choose(NodeId id, const Choose& op, const Scope& s, const BoxList& inside);
  // The callee's frame: known values, unknowns for continuous random
  // arguments, and the few-valued random arguments to try one by one.
  std::optional<std::pair<Frame, std::vector<ArgChoice>>> setup_call(NodeId id, const Call& op, const Scope& s);
  // Runs body() in the callee's frame for each combination of the
  // few-valued arguments; stops at the first body() that returns true.
  template <typename F>
  bool each_binding(NodeId id, const Call& op, Frame& frame, const std::vector<ArgChoice>& choices, std::size_t next,
                    F& body);
  bool match_call(NodeId id, const Call& op, const Scope& s, const BoxList& inside);

  // ---- length queries: which lengths along an open axis fit (check_lengths.cpp) ----

  // The lengths l in [fs.lmin, fs.lmax] for which node `id`, run on
  // fs.at(l), derives exactly `inside`. A query: it leaves no witness,
  // binding or mismatch behind. Exact where matching is, except that a
  // continuous unknown in the sizes of a split along the open axis counts
  // as independent values (verified when the length is then matched).
  Support lengths(NodeId id, const FreeScope& fs, const BoxList& inside);
  Support lengths_dispatch(NodeId id, const FreeScope& fs, const BoxList& inside);
  // A terminal fills its scope: the one length (if any) at which the
  // scope's world box is the box's. World bounds move linearly with l.
  Support lengths_terminal(const std::string& label, const FreeScope& fs, const BoxList& inside);
  Support lengths_split(NodeId id, const Split& op, const FreeScope& fs, const BoxList& inside);
  Support lengths_repeat(NodeId id, const FreeScope& fs, const BoxList& inside);
  // Tiles along the open axis: n tiles of L / n, where L moves with l.
  // With two tiles or more, the first boundary must fall where no box
  // crosses, so each face c of a box gives the candidate L = n * c, checked
  // by matching; one tile is the scope itself.
  Support lengths_repeat_along(NodeId id, const FreeScope& fs, const BoxList& inside, const RepeatSetup& st);

  const Grammar& g_;
  const std::vector<LabelledBox>& boxes_;
  const double tol_;
  Budget& budget_;
  DeterministicSubtrees& deterministic_;
  Bindings vars_;
  // Where the node being matched lies (derivation_path), and the part or
  // option the next match() enters through.
  std::vector<std::uint64_t> path_{0};
  std::uint32_t slot_ = 0;
  std::vector<WitnessLine> witness_;
  std::unordered_map<const Expr*, Possible> fixed_values_;
  CutsCache cuts_;
  BindingLookup lookup_;
  // The scope the expression being evaluated stands in (size(axis)).
  const Scope* scope_ = nullptr;
  Emptiness empty_;
  Mismatch best_;
  std::string uncheckable_;
  bool open_ends_unsupported_ = false;
  bool floating_ = true;
  // CheckOptions::learned_order: per choose, how often each alternative
  // has matched so far.
  bool learned_order_ = false;
  std::unordered_map<NodeId, std::vector<std::uint32_t>> wins_;
  // CheckOptions::answer_only: no values, parts or memoised lines recorded.
  bool answer_only_ = false;
  int depth_ = 0;
  int quiet_ = 0;
  std::size_t progress_ = 0;  // boxes in finished parts on the current path (Finished)
};

// ---- the member templates that two files use ----

template <typename F>
bool Matcher::each_sizing(NodeId id, const Split& op, const Scope& s, SplitSetup& st, F f) {
  std::vector<std::size_t> pick(st.finite.size(), 0);
  while (true) {
    const std::size_t trail_mark = vars_.trail_size(), witness_mark = witness_.size();
    for (std::size_t k = 0; k < st.finite.size(); ++k) {
      const Unknown& u = vars_.unknown(st.finite[k]);
      const double v = st.finite_values[k][pick[k]];
      vars_.bind(st.finite[k], v);
      note_value(id, u.name, v, u.origin);
    }
    for (std::size_t i = 0; i < op.parts.size(); ++i) {
      auto p = evaluate(op.parts[i].size.value, id, s, "the size of part", i + 1);
      if (!p) return false;
      st.parts[i].share = p->support.clamp(0, kInf);
      st.parts[i].random = !p->exact;
      if (st.parts[i].share.empty()) {
        if (recording())
          fail(id, s,
               "the size of part " + std::to_string(i + 1) + " (" + expr_text(op.parts[i].size.value) +
                   ") is negative, so derive() fails here");
        return false;
      }
    }
    if (f()) return true;
    vars_.undo(trail_mark);
    witness_.resize(witness_mark);
    std::size_t k = 0;
    while (k < pick.size() && ++pick[k] == st.finite_values[k].size()) pick[k++] = 0;
    if (k == pick.size()) return false;
  }
}

template <typename F>
bool Matcher::each_binding(NodeId id, const Call& op, Frame& frame, const std::vector<ArgChoice>& choices,
                           std::size_t next, F& body) {
  if (next == choices.size()) {
    vars_.enter(frame);
    const bool ok = body();
    vars_.leave();
    return ok;
  }
  const Rule& callee = g_.rules[op.rule];
  const ArgChoice& c = choices[next];
  for (double v : c.values) {
    budget_.step();
    frame.params[c.arg] = Slot{Value(v), -1};
    const std::size_t mark = witness_.size();
    note_value(id, c.arg < callee.params.size() ? callee.params[c.arg] : "?", v,
               Origin{&op.args[c.arg], current_rule(), kNone});
    if (each_binding(id, op, frame, choices, next + 1, body)) return true;
    witness_.resize(mark);
  }
  return false;
}

}  // namespace vern::check_detail
