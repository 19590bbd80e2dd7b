#include "inverse/infer.hpp"

#include <algorithm>
#include <optional>

#include "base/alongside.hpp"
#include "base/number_format.hpp"
#include "base/parallel_for.hpp"
#include "inverse/check/derives_examples.hpp"
#include "inverse/load/layered_parts.hpp"
#include "inverse/load/orientation.hpp"
#include "inverse/load/snapped_coordinates.hpp"
#include "inverse/load/turned_examples.hpp"
#include "inverse/merge/merge.hpp"
#include "inverse/merge/kept_choices.hpp"
#include "inverse/merge/shared_frames.hpp"
#include "inverse/merge/subsumed_options.hpp"
#include "inverse/sizes/fit_distribution.hpp"
#include "inverse/sizes/joint_sizes.hpp"
#include "inverse/sizes/overflow_splits.hpp"
#include "inverse/sizes/progressions.hpp"
#include "inverse/sizes/repeat_alternatives.hpp"
#include "inverse/sizes/scope_by_count.hpp"
#include "inverse/sizes/tidy_numbers.hpp"
#include "inverse/split/box_split.hpp"
#include "inverse/split/comp_faces.hpp"
#include "inverse/split/split_graph.hpp"
#include "inverse/write/rule_naming.hpp"

namespace vern {

namespace {
// Joining sizes checks every example twice, and joining twins reads the
// whole grammar once per rule it makes; beyond this many parts in all
// neither is tried (a million-part example is one example anyway).
constexpr std::size_t kJoinedPartsLimit = 200'000;

// infer(), once overlapping parts are known to be resolved (`layered`:
// each example's overlaps are still to be found while splitting it).
// `snapped`: the examples' coordinates are snapped to the noise level
// options.tolerance (snapped_coordinates.hpp), so that coordinates apart
// are places apart: they are cut within float noise (two places 0.04 m
// apart at a level of 0.05 m are two cuts), and the level holds for sizes
// merged and for the grammar's check.
Inference infer_laid_out(const std::vector<Example>& examples, const InferOptions& options, bool layered,
                         bool snapped) {
  Inference out;
  out.tolerance = options.tolerance;
  if (out.tolerance <= 0)
    for (const auto& e : examples) out.tolerance = std::max(out.tolerance, default_tolerance(e));
  std::size_t parts = 0;
  for (const auto& e : examples) parts += e.boxes.size();
  // Each example is cut within its own tolerance, the one check gives it.
  auto own = [&](const Example& e) { return example_tolerance(e, options.tolerance); };
  // Where parts are cut: within float noise once coordinates are snapped.
  auto cut = [&](const Example& e) { return snapped ? default_tolerance(e) : own(e); };

  // Parts whose mesh is their label's turned become R(...){ I(label) }.
  // Orienting and splitting only read the examples, so one runs beside the
  // other: even a single large example keeps two cores busy. The examples
  // split in parallel; their graphs then go into one interned grammar, in
  // order, on this thread.
  PartOrientations oriented;
  const PrimitiveLibrary& library = options.primitives ? *options.primitives : PrimitiveLibrary::builtin();
  std::vector<SplitTree> trees(examples.size());
  // Overlapping parts are found where the split meets them, so examples
  // without any pay nothing more.
  std::vector<std::vector<OverlapPair>> overlaps(layered ? examples.size() : 0);
  run_alongside(
      options.threads, [&] { oriented = orient_parts(examples, library, out.tolerance); },
      [&] {
        parallel_for(
            examples.size(), options.threads,
            [&](std::size_t i) {
              trees[i] = split_boxes(examples[i].boxes, BoxSplitOptions{cut(examples[i])}, examples[i].source,
                                     layered ? &overlaps[i] : nullptr);
            },
            [&](std::size_t done) {
              if (options.progress) options.progress(done, examples.size());
            });
      });
  // Parts set into parts, or painted over one another: each keeps what is
  // visible of it (layered_parts.hpp), and inference starts again on
  // those. Every example's unordered overlaps are reported, not the first.
  if (std::any_of(overlaps.begin(), overlaps.end(), [](const auto& o) { return !o.empty(); })) {
    std::vector<Example> visible(examples.size());
    std::string errors;
    for (std::size_t i = 0; i < examples.size(); ++i) {
      try {
        visible[i] = visible_parts(examples[i], overlaps[i], Layering{options.stack, cut(examples[i])});
      } catch (const Error& e) {
        if (e.kind() != ErrorKind::Input) throw;
        errors += (errors.empty() ? "" : "\n") + std::string(e.what());
      }
    }
    if (!errors.empty()) throw Error(ErrorKind::Input, errors);
    return infer_laid_out(visible, options, false, snapped);
  }
  // Rounding may move a number by a quarter of the smallest example's
  // tolerance: every example then still matches within its own tolerance
  // (check's default), however the rounded numbers of one split add up.
  double smallest = out.tolerance;
  for (const auto& e : examples) smallest = std::min(smallest, own(e));

  Grammar graph;
  // About 1.4 graph nodes per part for large examples (1.36 measured at a
  // million parts, through tidying): room for one and a half.
  graph.reserve(parts + parts / 2);
  const Grammar::Checkpoint empty = graph.checkpoint();
  std::vector<NodeId> roots, placed;
  std::optional<Grammar::Checkpoint> unmerged;
  // One graph per example, in order, into one interned grammar; each tree
  // is dropped once used if `drop_trees` (large examples hold big trees).
  auto build_graphs = [&](const std::vector<Example>& laid_out, const std::vector<int>& quarters, bool drop_trees) {
    roots.clear();
    placed.clear();
    orient_face_parts(trees, laid_out, out.tolerance, oriented);
    for (std::size_t i = 0; i < examples.size(); ++i) {
      roots.push_back(split_graph(graph, trees[i], laid_out[i].boxes, laid_out[i].source, oriented.turns[i],
                                  {cut(examples[i]), &out.warnings, &placed}));
      // Turned back to be laid out: turned again where it is derived.
      if (quarters[i] != 0) roots.back() = turned_node(graph, roots.back(), {{Axis::Z, (4 - quarters[i]) % 4}});
      if (drop_trees) trees[i] = {};
    }
    unmerged = graph.checkpoint();
  };
  // The examples' graphs merged within `tolerance`, numbers tidied (each
  // moved by at most a quarter of `exact`) and frames shared: the merged root.
  auto merged = [&](Grammar& g, double tolerance, double exact, bool draw_sizes, bool fold_unlike = true) {
    MergeOptions merge;
    merge.tolerance = tolerance;
    merge.draw_sizes = draw_sizes;
    merge.fold_unlike = fold_unlike;
    merge.uniform_distributions = options.uniform_distributions;
    merge.placed = placed;
    NodeId root = merge_examples(g, roots, merge);
    root = tidy_numbers(g, root, exact / 4);
    for (Rule& rule : g.rules) rule.body = tidy_numbers(g, rule.body, exact / 4);
    // Written alike now, alternatives that differ at one place share their
    // frame (the same buildings, in fewer lines).
    root = share_frames(g, root);
    for (Rule& rule : g.rules) rule.body = share_frames(g, rule.body);
    return root;
  };

  // Whole buildings turned a quarter are turned back to the layout the
  // others share, and written turned (turned_examples.hpp); those are cut
  // and oriented again. On two threads or more, looking for them takes one
  // while this one builds and merges the graphs of the examples as they
  // are, which is what they are almost always kept as: only when a
  // building turns are those graphs dropped and made again.
  const std::vector<int> as_they_are(examples.size(), 0);
  std::vector<int> quarters = as_they_are;
  std::optional<NodeId> first_merge;
  const std::size_t warnings = out.warnings.size();
  bool built = false;
  if (parts <= kJoinedPartsLimit && options.threads != 1) {
    // The side reads the trees, so none is dropped yet.
    run_alongside(
        options.threads, [&] { quarters = common_orientation(examples, trees, out.tolerance, 1); },
        [&] {
          build_graphs(examples, as_they_are, false);
          first_merge = merged(graph, out.tolerance, smallest, true);
        });
    built = true;
  } else if (parts <= kJoinedPartsLimit) {
    quarters = common_orientation(examples, trees, out.tolerance, 1);
  }
  std::vector<Example> turned;
  if (std::ranges::any_of(quarters, [](int q) { return q != 0; })) {
    if (built) {
      graph.rollback(empty);
      out.warnings.resize(warnings);
      first_merge.reset();
    }
    for (std::size_t i = 0; i < examples.size(); ++i) {
      turned.push_back(turned_example(examples[i], quarters[i]));
      if (quarters[i] != 0) trees[i] = split_boxes(turned[i].boxes, BoxSplitOptions{cut(examples[i])}, turned[i].source);
    }
    oriented = orient_parts(turned, library, out.tolerance);
    build_graphs(turned, quarters, true);
  } else if (!built) {
    build_graphs(examples, as_they_are, true);
  }
  trees = {};
  out.unturned_parts = oriented.unmatched;

  // Generalises the merged graph and writes the grammar; every step holds
  // the examples within `exact`.
  auto generalise_from = [&](Grammar& g, NodeId root, double tolerance, double exact) {
    out.grammar = rules_for(g, root, NamingOptions{options.start});
    // A split seen overflowing in short tiles is that split: checked, so
    // only where the examples are few enough to check quickly.
    if (parts <= kJoinedPartsLimit) unify_overflows(out.grammar, examples, {exact, options.threads});
    // Alternatives told apart only by how many tiles the examples showed
    // (two storeys in most houses, three in the tallest) are one repeat:
    // read from the examples' derivations, so likewise checked.
    // Whether some choice is made once per building and kept below (its
    // bays all balconies or all windows) is read here, kept below.
    // Alternatives the others now derive (a row that happened to hold
    // one door bay, beside a repeat of bays each a window or a door) only
    // draw what no example asked for: dropped. All checked, and all read
    // the examples' witnesses, found once between them where nothing
    // changes.
    bool kept = false;
    if (parts <= kJoinedPartsLimit) {
      Witnesses witnesses;
      join_tile_run_alternatives(out.grammar, examples, {exact, options.threads}, witnesses);
      kept = shows_kept_choices(out.grammar, examples, {exact, options.threads}, witnesses);
      drop_subsumed_options(out.grammar, examples, {exact, options.threads}, witnesses);
    }
    // Sizes that vary together, drawn once: from the lengths of the
    // derivations that reproduce the examples, so only where they are few
    // enough to check quickly.
    if (options.joint_sizes && parts <= kJoinedPartsLimit) {
      JointSizesOptions joint;
      joint.tolerance = exact;
      joint.uniform_distributions = options.uniform_distributions;
      joint.threads = options.threads;
      out.joint = join_sizes(out.grammar, examples, joint);
    }
    // Kept after sizes are joined: the kind is passed down beside the
    // sizes drawn once (joining reads no rule that takes parameters).
    // Checked again only where the witnesses above showed kinds kept.
    if (kept) {
      Witnesses witnesses;
      keep_choices(out.grammar, examples, {exact, options.threads}, witnesses);
    }
    // Rows whose tiles step down (or up) as they go: a recursion with the
    // step, read from the sizes just joined (progressions.hpp).
    if (parts <= kJoinedPartsLimit) fold_progressions(out.grammar, examples, {exact, options.threads});
    // Last: it only rewrites what is written, and joining sizes reads the
    // grammar's structure as rules_for left it. Bounded like joining, as its
    // rounds each read the whole grammar.
    if (options.twin_rules && parts <= kJoinedPartsLimit) out.twins = parameterise_twins(out.grammar);

    // @scope: per axis, the examples' sizes as the distribution they fit
    // best, as every varying size is (a plot width seen ten times between
    // 8 and 20 m reaches a little beyond; four heights seen again and again
    // are a choice of those four), or the one size they share.
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<Observation> sizes;
      for (const auto& e : examples) sizes.push_back({example_size(e)[axis], 1});
      out.grammar.scope[axis] =
          distribution_expr(short_decimals(fit_size(sizes, tolerance, options.uniform_distributions), exact / 4));
    }
    // Unless the plot follows a count drawn once per building (a pagoda as
    // tall as its tiers): read from the examples' derivations, so checked.
    if (parts <= kJoinedPartsLimit) tie_scope_to_counts(out.grammar, examples, {exact, options.threads});
  };
  // Sizes are merged within the largest example tolerance (a house far
  // from the origin is noisy to a centimetre, and its 0.6 m wall is the
  // 0.6 m wall of the house at the origin), which may hold a precise
  // example to less than check does; and numbers are rounded, shares of
  // the largest containers included, which small parts deep inside (a
  // pinwheel nested in pinwheels) feel most. infer never writes what
  // check refuses (docs/inference.md): the grammar must pass check on the examples
  // as they are, and where it does not it is made again, merging within
  // the smallest tolerance, where every example is held to its own, then
  // ten and a hundred times finer. Joining sizes has checked every example
  // within the smallest tolerance, stricter than each one's own: a grammar
  // it passed needs no second check (the city's ten examples: a fifth of
  // infer's time). The steps after it (progressions, twins) keep what
  // derives.
  // Last, the sizes that vary kept as the shares merging found, not drawn
  // in metres (MergeOptions::draw_sizes says when those miss an example).
  struct Attempt {
    double merge, exact;
    bool draw_sizes = true;
    bool fold_unlike = true;
  };
  std::vector<Attempt> attempts{{out.tolerance, smallest}};
  if (smallest < out.tolerance) attempts.push_back({smallest, smallest});
  for (const double finer : {10.0, 100.0}) attempts.push_back({smallest / finer, smallest / finer});
  attempts.push_back({attempts[0].merge, attempts[0].exact, false});
  // Last, rows of unlike tiles left as each example has them (a row of
  // bays in equal thirds read as tiles a third long, which another
  // example's row does not fit): the fewest generalisations, but a
  // grammar rather than none.
  attempts.push_back({attempts[0].merge, attempts[0].exact, false, false});
  std::optional<NotDerived> failed;
  for (std::size_t k = 0; k < attempts.size(); ++k) {
    const auto [tolerance, exact, draw_sizes, fold_unlike] = attempts[k];
    failed.reset();
    if (k > 0) {
      out.tolerance = tolerance;
      out.joint = {};
      out.twins = {};
      graph.rollback(*unmerged);
    }
    generalise_from(graph,
                    k == 0 && first_merge ? *first_merge : merged(graph, tolerance, exact, draw_sizes, fold_unlike),
                    tolerance, exact);
    // Past the parts checked quickly, the grammar is the examples' cuts,
    // merged and tidied only (docs/inference.md, "Large examples").
    if (out.joint.derives_examples || parts > kJoinedPartsLimit) break;
    failed = first_not_derived(out.grammar, examples, options.tolerance, options.threads);
    if (!failed) break;
  }
  if (failed) {
    const Example& e = examples[failed->example];
    throw Error(ErrorKind::Internal,
                "infer: error: no grammar inferred derives " + e.source + ", even with sizes held ten and a "
                    "hundred times closer than its tolerance, kept as shares, or rows of unlike tiles left "
                    "as they are: " +
                    failed->why +
                    "\n  hint: please report this with the examples; a smaller --tolerance may get past it");
  }

  // The first mesh seen for each label stands for all its parts.
  // Each label's canonical mesh (orientation.hpp); an example built in
  // memory may have no meshes: its labels then fall back to the library's
  // box when generated.
  out.primitives = std::move(oriented.canonical);
  return out;
}

}  // namespace

Inference infer(const std::vector<Example>& examples, const InferOptions& options) {
  if (examples.empty()) throw Error(ErrorKind::Usage, "infer: error: no examples given");
  if (options.tolerance <= 0) return infer_laid_out(examples, options, true, false);
  // A noise level given: coordinates that measure one place become one,
  // before parts painted over others are cut (no slivers of a wall
  // between windows a pixel apart). Float noise, the default, needs none.
  std::vector<Example> snapped;
  snapped.reserve(examples.size());
  for (const Example& e : examples) snapped.push_back(snapped_coordinates(e, options.tolerance));
  try {
    return infer_laid_out(snapped, options, true, true);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::Internal && e.kind() != ErrorKind::Limit) throw;
    // No grammar of the snapped examples derives them (a place the noise
    // level cannot settle), or checking one ran past its steps (sizes
    // that fit within the level many ways): the examples as read, as
    // without a level (each within its float noise), and said; check
    // takes either.
    InferOptions as_read = options;
    as_read.tolerance = 0;
    Inference out = infer_laid_out(examples, as_read, true, false);
    const std::string why = e.what();
    out.warnings.insert(out.warnings.begin(),
                        "infer: warning: with coordinates snapped to the noise level " +
                            format_number(options.tolerance) + " m no grammar was found to derive the examples (" +
                            why.substr(0, why.find('\n')) + "): inferred from the coordinates as read" +
                            "\n  hint: a smaller --tolerance may let the examples' rows and columns line up");
    return out;
  }
}

}  // namespace vern
