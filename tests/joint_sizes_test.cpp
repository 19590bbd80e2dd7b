// Sizes that vary together stay together: a garage half as high as its
// house, in every example, is half as high in every variant; sizes that
// vary apart stay apart; a split whose parts vary in one way draws once.
#include "inverse/sizes/joint_sizes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <set>
#include <utility>

#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

// A tower filling the plot's height, a house 4 to 10 m high beside it and
// a garage half as high as the house. The tower keeps the plot from
// carrying the heights: each is a split of its own column.
constexpr const char* kHalfAsHigh = R"(
@scope 12, 8, 10
b --> b2(rand(4, 10))
b2(h) --> split(x){
    ~1 : I(rect) |
    ~2 : split(z){ h : I(rect) | ~1 : nil } |
    ~1 : split(z){ h * 0.5 : I(rect) | ~1 : nil } }
)";

// The same, the garage within 0.3 m of half the house.
constexpr const char* kRoughlyHalf = R"(
@scope 12, 8, 10
b --> b2(rand(4, 10), rand(-0.3, 0.3))
b2(h, e) --> split(x){
    ~1 : I(rect) |
    ~2 : split(z){ h : I(rect) | ~1 : nil } |
    ~1 : split(z){ h * 0.5 + e : I(rect) | ~1 : nil } }
)";

// The same, with a side part and a garage of three kinds each: their
// choices lie below the house's split, so the garage's height follows a
// size outside its choice.
constexpr const char* kAnyGarage = R"(
@scope 12, 8, 10
b --> b2(rand(4, 10))
b2(h) --> split(x){ ~1 : side | ~2 : split(z){ h : I(rect) | ~1 : nil } | ~1 : garage(h) }
side --> I(rect) : 1
side --> split(y){ ~1 : I(rect) | ~1 : I(shed) } : 1
side --> split(y){ ~1 : I(shed) | ~1 : I(rect) } : 1
garage(h) --> split(z){ h * 0.5 : I(rect) | ~1 : nil } : 1
garage(h) --> split(z){ h * 0.5 : I(shed) | ~1 : nil } : 1
garage(h) --> split(z){ h * 0.5 : I(hut) | ~1 : nil } : 1
)";

// House and garage heights drawn apart.
constexpr const char* kApart = R"(
@scope 12, 8, 10
b --> split(x){
    ~1 : I(rect) |
    ~2 : split(z){ rand(4, 10) : I(rect) | ~1 : nil } |
    ~1 : split(z){ rand(2, 5) : I(rect) | ~1 : nil } }
)";

// The thesis's garage (grammar 7.1, as in data/grammars/garage.grm): its
// garage split draws both of its relative sizes, though only their ratio
// shows.
constexpr const char* kGarage = R"(
@start start
@scope 12, 8, 9
start --> split(x){~2 : house | ~1 : garageSide} : 0.5
start --> split(x){~1 : garageSide | ~2 : house} : 0.5
house --> split(z){~2 : I(rect) | ~1 : I(roof)}
garageSide --> split(z){~(rand/2) + 0.75 : I(rect) | ~2 : nil}
)";

Derivation derive_seed(const Grammar& g, std::uint64_t seed) {
  DeriveOptions o;
  o.seed = seed;
  return derive(g, o);
}

std::vector<Example> examples_of(const Grammar& source, std::size_t count) {
  std::vector<Example> out;
  for (std::uint64_t seed = 1; seed <= count; ++seed)
    out.push_back(test::example_of(test::derived_parts(derive_seed(source, seed))));
  return out;
}

Inference inferred_from(const char* text, bool joint, std::size_t examples = 10) {
  const Grammar source = parse_grammar(text, "source.grm");
  InferOptions o;
  o.joint_sizes = joint;
  return infer(examples_of(source, examples), o);
}

// The house's and the garage's heights in a building of kHalfAsHigh's
// layout: the tops of the parts starting at x = 3 and x = 9.
std::optional<std::pair<double, double>> heights(const Derivation& d) {
  std::optional<double> house, garage;
  for (const LabelledBox& b : test::derived_parts(d)) {
    if (std::abs(b.min.x - 3) < 1e-6) house = b.max.z;
    if (std::abs(b.min.x - 9) < 1e-6) garage = b.max.z;
  }
  if (!house || !garage) return std::nullopt;
  return std::make_pair(*house, *garage);
}

// The largest distance of a variant's garage from half its house, over
// 100 variants of g.
double worst_miss_of_half(const Grammar& g) {
  double worst = 0;
  std::size_t measured = 0;
  for (std::uint64_t seed = 1001; seed <= 1100; ++seed) {
    const auto h = heights(derive_seed(g, seed));
    if (!h) continue;
    ++measured;
    worst = std::max(worst, std::abs(h->second - 0.5 * h->first));
  }
  EXPECT_GE(measured, 90u) << write_grammar(g);
  return worst;
}

void expect_every_example_derivable(const char* text, const Grammar& g, std::size_t examples = 10) {
  for (const Example& e : examples_of(parse_grammar(text, "source.grm"), examples)) {
    const CheckResult r = check_example(g, e.boxes, example_size(e));
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << write_grammar(g);
  }
}

TEST(JointSizes, AGarageHalfAsHighAsItsHouseStaysHalfAsHigh) {
  const Inference joint = inferred_from(kHalfAsHigh, true);
  expect_every_example_derivable(kHalfAsHigh, joint.grammar);
  EXPECT_GE(joint.joint.regions, 1u);
  EXPECT_LT(worst_miss_of_half(joint.grammar), 1e-3) << write_grammar(joint.grammar);
  // Drawn on their own, the two heights part: tall garages on short houses.
  const Inference apart = inferred_from(kHalfAsHigh, false);
  EXPECT_GT(worst_miss_of_half(apart.grammar), 0.5) << write_grammar(apart.grammar);
}

TEST(JointSizes, AGarageRoughlyHalfAsHighStaysClose) {
  const Inference joint = inferred_from(kRoughlyHalf, true);
  expect_every_example_derivable(kRoughlyHalf, joint.grammar);
  // The examples stray 0.3 m from half the house; the variants a little
  // more where the fitted line leaves the true one, never metres.
  EXPECT_LT(worst_miss_of_half(joint.grammar), 0.6) << write_grammar(joint.grammar);
  const Inference apart = inferred_from(kRoughlyHalf, false);
  EXPECT_GT(worst_miss_of_half(apart.grammar), 0.6) << write_grammar(apart.grammar);
}

TEST(JointSizes, AGarageOfAnyKindFollowsItsHouse) {
  const Inference joint = inferred_from(kAnyGarage, true, 16);
  expect_every_example_derivable(kAnyGarage, joint.grammar, 16);
  EXPECT_LT(worst_miss_of_half(joint.grammar), 1e-3) << write_grammar(joint.grammar);
  const Inference apart = inferred_from(kAnyGarage, false, 16);
  EXPECT_GT(worst_miss_of_half(apart.grammar), 0.5) << write_grammar(apart.grammar);
}

TEST(JointSizes, SizesDrawnApartStayApart) {
  const Inference joint = inferred_from(kApart, true);
  expect_every_example_derivable(kApart, joint.grammar);
  EXPECT_EQ(joint.joint.regions, 0u) << write_grammar(joint.grammar);
  // Over 100 variants the two heights show no straight-line relation.
  std::vector<std::pair<double, double>> hs;
  for (std::uint64_t seed = 1001; seed <= 1100; ++seed)
    if (const auto h = heights(derive_seed(joint.grammar, seed))) hs.push_back(*h);
  ASSERT_GE(hs.size(), 90u);
  double mx = 0, my = 0;
  for (const auto& [x, y] : hs) {
    mx += x / static_cast<double>(hs.size());
    my += y / static_cast<double>(hs.size());
  }
  double sxx = 0, syy = 0, sxy = 0;
  for (const auto& [x, y] : hs) {
    sxx += (x - mx) * (x - mx);
    syy += (y - my) * (y - my);
    sxy += (x - mx) * (y - my);
  }
  EXPECT_LT(std::abs(sxy / std::sqrt(sxx * syy)), 0.5) << write_grammar(joint.grammar);
}

// A slab with a box centred on it, 2 to 8 times as wide as each inset.
constexpr const char* kCentred = R"(
@scope 10, 6, 8
b --> split(z){ ~1 : I(rect) | ~3 : split(x){ ~1 : nil | ~rand(2, 8) : I(rect) | ~1 : nil } }
)";

// The largest difference between the left and the right inset of the
// upper box, over 100 variants of g.
double worst_off_centre(const Grammar& g) {
  double worst = 0;
  for (std::uint64_t seed = 1001; seed <= 1100; ++seed) {
    const std::vector<LabelledBox> parts = test::derived_parts(derive_seed(g, seed));
    double width = 0;
    for (const LabelledBox& b : parts) width = std::max(width, b.max.x);
    for (const LabelledBox& b : parts)
      if (b.min.z > 1e-6) worst = std::max(worst, std::abs(b.min.x - (width - b.max.x)));
  }
  return worst;
}

// How many splits of g (as its rules reach them) draw two or more of
// their sizes.
std::size_t splits_drawing_twice(const Grammar& g) {
  std::size_t count = 0;
  std::vector<bool> seen(g.node_count(), false);
  std::vector<NodeId> stack;
  for (const Rule& r : g.rules) stack.push_back(r.body);
  while (!stack.empty()) {
    const NodeId id = stack.back();
    stack.pop_back();
    if (seen[id]) continue;
    seen[id] = true;
    if (const auto* s = std::get_if<Split>(&g.op(id))) {
      std::size_t draws = 0;
      for (const SplitPart& p : s->parts) draws += p.size.value.draws_random() ? 1 : 0;
      count += draws >= 2 ? 1 : 0;
    }
    for_each_child(g.op(id), [&](NodeId c) { stack.push_back(c); });
  }
  return count;
}

TEST(JointSizes, EqualInsetsStayEqual) {
  // Three shares, each drawn, where the examples vary in one way: the two
  // insets are one share, s1, and the box the rest.
  const Inference joint = inferred_from(kCentred, true);
  expect_every_example_derivable(kCentred, joint.grammar);
  EXPECT_LT(worst_off_centre(joint.grammar), 1e-3) << write_grammar(joint.grammar);
  // Drawn apart, the insets still stay equal: merging keeps parts that
  // are in one ratio in every example in that ratio, and draws the box
  // beside them (size_plan.hpp, plan_drawn_sizes): one draw either way.
  const Inference apart = inferred_from(kCentred, false);
  EXPECT_LT(worst_off_centre(apart.grammar), 1e-3) << write_grammar(apart.grammar);
  EXPECT_EQ(splits_drawing_twice(apart.grammar), 0u) << write_grammar(apart.grammar);
}

TEST(JointSizes, ASplitThatVariesInOneWayDrawsOnce) {
  const Inference joint = inferred_from(kGarage, true);
  expect_every_example_derivable(kGarage, joint.grammar);
  EXPECT_EQ(splits_drawing_twice(joint.grammar), 0u) << write_grammar(joint.grammar);
  EXPECT_GE(joint.joint.joined, 1u);
  // The garage's height still ranges over what the examples showed.
  const Inference apart = inferred_from(kGarage, false);
  EXPECT_GE(splits_drawing_twice(apart.grammar), 1u) << write_grammar(apart.grammar);
}

// A stack along z: a ground storey 3 to 5 m high, a middle part twice as
// high plus 1 m, and a top taking the rest of a plot drawn apart.
constexpr const char* kTwicePlusOne = R"(
@scope 12, 8, rand(16, 24)
b --> b2(rand(3, 5))
b2(h) --> split(z){ h : I(rect) | h * 2 + 1 : I(mid) | ~1 : I(roof) }
)";

// The stack as merging may write it: as three shares (as it did for a
// random style whose storeys held a choice of rows), or with the middle
// drawn in metres. The ground's share of a plot that varies on its own
// follows no line of the middle's, nor of its metres; its metres do.
constexpr const char* kStackOfShares = R"(
@scope 12, 8, 20
b --> split(z){ ~rand(2.5, 5.5) : I(rect) | ~rand(6, 12) : I(mid) | ~rand(0.01, 15) : I(roof) }
)";
constexpr const char* kMixedStack = R"(
@scope 12, 8, 20
b --> split(z){ ~rand(2.5, 5.5) : I(rect) | rand(6, 12) : I(mid) | ~rand(0.01, 15) : I(roof) }
)";

// The largest distance of a variant's middle part from twice its ground
// storey plus 1 m, over 100 variants of g.
double worst_miss_of_twice_plus_one(const Grammar& g) {
  double worst = 0;
  std::size_t measured = 0;
  for (std::uint64_t seed = 1001; seed <= 1100; ++seed) {
    std::optional<double> ground, mid;
    for (const LabelledBox& b : test::derived_parts(derive_seed(g, seed))) {
      if (b.label == "rect") ground = b.max.z - b.min.z;
      if (b.label == "mid") mid = b.max.z - b.min.z;
    }
    if (!ground || !mid) continue;
    ++measured;
    worst = std::max(worst, std::abs(*mid - (2 * *ground + 1)));
  }
  EXPECT_GE(measured, 90u) << write_grammar(g);
  return worst;
}

TEST(JointSizes, SharesWhoseMetresFollowAnotherPartAreReadInMetres) {
  const std::vector<Example> examples = examples_of(parse_grammar(kTwicePlusOne, "source.grm"), 12);
  for (const char* merged : {kStackOfShares, kMixedStack}) {
    Grammar g = parse_grammar(merged, "merged.grm");
    EXPECT_GT(worst_miss_of_twice_plus_one(g), 0.5);
    const JointSizes joint = join_sizes(g, examples, JointSizesOptions{});
    EXPECT_TRUE(joint.derives_examples) << write_grammar(g);
    EXPECT_LT(worst_miss_of_twice_plus_one(g), 1e-3) << write_grammar(g);
  }
}

// Two sheds one height h on either side of a house, the three widths
// drawn apart: the split of three shares that all vary brings two draws
// of its own to the region (its rest subtracts both), where check pins
// down one per split; the sheds' height joins all the same.
constexpr const char* kShedsOfOneHeight = R"(
@scope rand(20, 30), 8, 12
b --> b2(rand(3, 7))
b2(h) --> split(x){ ~rand(1, 2) : shed(h) | ~rand(2, 4) : I(house) | ~rand(0.8, 1.6) : shed(h) }
shed(h) --> split(z){ h : I(shed) | ~1 : nil }
)";

// The largest difference between the two sheds' heights, over 100
// variants of g.
double worst_shed_mismatch(const Grammar& g) {
  double worst = 0;
  std::size_t measured = 0;
  for (std::uint64_t seed = 1001; seed <= 1100; ++seed) {
    std::vector<double> tops;
    for (const LabelledBox& b : test::derived_parts(derive_seed(g, seed)))
      if (b.label == "shed") tops.push_back(b.max.z);
    if (tops.size() != 2) continue;
    ++measured;
    worst = std::max(worst, std::abs(tops[0] - tops[1]));
  }
  EXPECT_GE(measured, 90u) << write_grammar(g);
  return worst;
}

TEST(JointSizes, ASplitOfSharesThatAllVaryLeavesTheRestOfItsRegionJoined) {
  const Inference joint = inferred_from(kShedsOfOneHeight, true, 12);
  expect_every_example_derivable(kShedsOfOneHeight, joint.grammar, 12);
  EXPECT_GE(joint.joint.regions, 1u) << write_grammar(joint.grammar);
  EXPECT_LT(worst_shed_mismatch(joint.grammar), 1e-3) << write_grammar(joint.grammar);
  const Inference apart = inferred_from(kShedsOfOneHeight, false, 12);
  EXPECT_GT(worst_shed_mismatch(apart.grammar), 0.5) << write_grammar(apart.grammar);
}

// A shop front with its door after zero to three bays, and storeys of
// windows whose loggia stands above the door: the storeys repeat, so the
// loggia's place is a size inside a repeat that follows one outside it.
constexpr const char* kLoggiaOverTheDoor = R"(
@scope rand(20, 40), 1, rand(10, 16)
f --> b(randint(0, 3))
b(k) --> split(z){ 4 : floor0(k) | ~1 : repeat(z, 3){ floor1(k) } }
floor0(k) --> split(x){ 4.3 * k : repeatN(x, k){ shop } | 4.3 : door | ~1 : repeat(x, 4.3){ shop } }
floor1(k) --> split(x){ 4.3 * k : repeatN(x, k){ win } | 4.3 : accent | ~1 : repeat(x, 4.3){ win } }
shop --> split(x){ ~1 : I(pier) | 3 : I(shopfront) | ~1 : I(pier) }
door --> split(x){ ~1 : I(wall) | 1.5 : I(door) | ~1 : I(wall) }
win --> split(x){ ~1 : I(wall) | 1.5 : I(window) | ~1 : I(wall) }
accent --> split(x){ ~1 : I(wall) | 1.5 : I(loggia) | ~1 : I(wall) }
)";

// Variants of g, out of 100, with a loggia not above the door.
std::size_t loggias_astray(const Grammar& g) {
  std::size_t astray = 0, measured = 0;
  for (std::uint64_t seed = 1001; seed <= 1100; ++seed) {
    const std::vector<LabelledBox> parts = test::derived_parts(derive_seed(g, seed));
    std::optional<double> door;
    for (const LabelledBox& b : parts)
      if (b.label == "door") door = b.min.x;
    if (!door) continue;
    ++measured;
    for (const LabelledBox& b : parts)
      if (b.label == "loggia" && std::abs(b.min.x - *door) > 1e-6) {
        ++astray;
        break;
      }
  }
  EXPECT_GE(measured, 90u) << write_grammar(g);
  return astray;
}

TEST(JointSizes, ASizeEveryTileKeepsFollowsASizeOutsideTheRepeat) {
  const Inference joint = inferred_from(kLoggiaOverTheDoor, true);
  expect_every_example_derivable(kLoggiaOverTheDoor, joint.grammar);
  EXPECT_EQ(loggias_astray(joint.grammar), 0u) << write_grammar(joint.grammar);
  const Inference apart = inferred_from(kLoggiaOverTheDoor, false);
  EXPECT_GT(loggias_astray(apart.grammar), 10u) << write_grammar(apart.grammar);
}

TEST(JointSizes, OneSlotInEveryAlternativeIsSizedFromAllTheirExamples) {
  // A door bay after none to three bays, lined up on every storey: each
  // bay count is an alternative of its own, and each saw two or three of
  // the ten examples. Sized alternative by alternative, the storeys
  // followed the ground floor (1.5 u + 2.5 m) in some and were drawn
  // apart in others; the slot pooled over every alternative's examples is
  // that line in each, so every variant's storeys follow its ground floor.
  const Grammar source = parse_grammar(R"(
@start hall
@scope rand(20, 30), 10, rand(15, 21)
hall --> mansion(rand(3.6, 5), randint(0, 3))
mansion(u, k) --> split(z){ u : ground(k) | 1.5 * u + 2.5 : repeat(z, 3.5){ storey(k) } | ~1 : I(roof) }
ground(k) --> split(x){ 3.5 * k : repeatN(x, k){ shop } | 3.5 : door | ~1 : repeat(x, 3.5){ shop } }
shop --> split(x){ 0.3 : I(pillar) | ~1 : I(glass) | 0.3 : I(pillar) }
storey(k) --> split(x){ 3.5 * k : repeatN(x, k){ bay } | 3.5 : feature | ~1 : repeat(x, 3.5){ bay } }
bay --> split(x){ ~1 : I(brick) | 1.4 : I(window) | ~1 : I(brick) }
door --> split(x){ ~1 : I(brick) | 1.4 : I(door) | ~1 : I(brick) }
feature --> split(x){ ~1 : I(brick) | 1.4 : I(balcony) | ~1 : I(brick) }
)", "hall.grm");
  const Inference inferred = infer(test::derived_examples(source, 10), {});
  for (std::uint64_t seed = 101; seed <= 140; ++seed) {
    double ground = 0, roof = 0;  // the door's top, the roof's bottom
    for (const LabelledBox& b : test::derived_parts(inferred.grammar, seed)) {
      if (b.label == "door") ground = b.max.z;
      if (b.label == "roof") roof = b.min.z;
    }
    ASSERT_GT(ground, 0) << seed;
    EXPECT_NEAR(roof - ground, 1.5 * ground + 2.5, 1e-6) << "seed " << seed << "\n" << write_grammar(inferred.grammar);
  }
}

TEST(JointSizes, ASizeEveryTileOfABuildingKeepsIsDrawnOncePerBuilding) {
  // Each house has one window width, kept on every storey; the widths
  // differ from house to house. Merging writes the width inside the
  // storeys' repeat, where each storey drew its own; every storey of a
  // variant keeps one width, as every storey of an example did.
  const Grammar source = parse_grammar(R"(
@start house
@scope rand(10, 16), 8, rand(12, 20)
house --> body(rand(0.8, 1.8))
body(w) --> split(z){ 4 : I(ground) | ~1 : repeat(z, 3){ storey(w) } | 1 : I(roof) }
storey(w) --> split(x){ ~1 : I(wall) | w : I(window) | ~1 : I(wall) }
)", "house.grm");
  const Inference inferred = infer(test::derived_examples(source, 10), {});
  std::size_t measured = 0, mixed = 0;
  std::set<double> widths;
  for (std::uint64_t seed = 101; seed <= 140; ++seed) {
    std::optional<double> first;
    bool same = true;
    std::size_t windows = 0;
    for (const LabelledBox& b : test::derived_parts(inferred.grammar, seed)) {
      if (b.label != "window") continue;
      ++windows;
      const double w = b.max.x - b.min.x;
      if (!first) first = w;
      same = same && std::abs(w - *first) <= 1e-6;
    }
    if (windows < 2) continue;
    ++measured;
    widths.insert(std::round(*first * 1000) / 1000);
    mixed += same ? 0 : 1;
  }
  EXPECT_GE(measured, 30u) << write_grammar(inferred.grammar);
  EXPECT_EQ(mixed, 0u) << write_grammar(inferred.grammar);
  EXPECT_GT(widths.size(), 5u) << write_grammar(inferred.grammar);  // still drawn, per building
  for (const Example& e : test::derived_examples(source, 10)) {
    const CheckResult r = check_example(inferred.grammar, e.boxes, example_size(e));
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << write_grammar(inferred.grammar);
  }
}

// A block whose two fronts take one storey height, drawn once per
// building (as data/styles/dev/storey_kept.grm).
constexpr const char* kStoreysKept = R"(
@start block
@scope rand(20, 30), rand(12, 16), rand(12, 20)
block --> body(rand(2.8, 3.6))
body(s) --> split(y){ ~1 : front(s) | ~1.5 : I(core) | ~1 : front(s) }
front(s) --> split(z){ 4 : I(shop) | ~1 : repeat(z, s){ repeat(x, 3){ split(x){ ~1 : I(wall) | 1.2 : I(window) | ~1 : I(wall) } } } }
)";

// The heights of a building's window rows on the front at y = 0 and on
// the one behind, sorted.
std::pair<std::vector<double>, std::vector<double>> window_rows(const Grammar& g, std::uint64_t seed) {
  std::set<double> front, back;
  for (const LabelledBox& b : test::derived_parts(g, seed)) {
    if (b.label != "window") continue;
    (b.min.y < 1e-6 ? front : back).insert(std::round(b.min.z * 1e6) / 1e6);
  }
  return {{front.begin(), front.end()}, {back.begin(), back.end()}};
}

TEST(JointSizes, ATileSizeBothFrontsKeepIsDrawnOncePerBuilding) {
  // Merged, each front's storeys were repeat(z, rand(...)), drawn apart:
  // the fronts of one variant stood in storeys of different heights.
  const Grammar source = parse_grammar(kStoreysKept, "block.grm");
  const Inference inferred = infer(test::derived_examples(source, 10), {});
  std::size_t apart = 0;
  for (std::uint64_t seed = 101; seed <= 140; ++seed) {
    const auto [front, back] = window_rows(inferred.grammar, seed);
    apart += front == back ? 0 : 1;
  }
  EXPECT_EQ(apart, 0u) << write_grammar(inferred.grammar);
  for (const Example& e : test::derived_examples(source, 10)) {
    const CheckResult r = check_example(inferred.grammar, e.boxes, example_size(e));
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << write_grammar(inferred.grammar);
  }
}

TEST(JointSizes, ADrawnTileSizeIsDrawnFromTheSizesThatGaveTheTiles) {
  // A storey height s drawn from 2.8 to 3.6 m gives ceil(L / s) storeys
  // of L / n, lower than s: drawn from the storeys' heights (2.25 to
  // 3.39 m), variants had storeys the style never makes. The sizes that
  // gave each building's storeys span the style's range.
  const Grammar source = parse_grammar(kStoreysKept, "block.grm");
  const Inference inferred = infer(test::derived_examples(source, 30), {});
  std::size_t outside = 0, measured = 0;
  double lowest = 10, highest = 0;
  for (std::uint64_t seed = 101; seed <= 160; ++seed) {
    DeriveOptions o;
    o.seed = seed;
    const Derivation d = derive(inferred.grammar, o);
    const auto [front, back] = window_rows(inferred.grammar, seed);
    if (front.size() < 2) continue;
    ++measured;
    // Storeys from the shop's top (4 m) to the building's top, n of them.
    const double top = d.start.size.z, storey = front[1] - front[0], n = std::round((top - 4) / storey);
    // Some s in [2.8, 3.6] gives n storeys: ceil((top - 4) / s) == n.
    const double lo = (top - 4) / n, hi = n > 1 ? (top - 4) / (n - 1) : 1e9;
    outside += hi > 2.8 && lo <= 3.6 ? 0 : 1;
    lowest = std::min(lowest, storey);
    highest = std::max(highest, storey);
  }
  EXPECT_GE(measured, 50u);
  EXPECT_EQ(outside, 0u) << write_grammar(inferred.grammar);
  EXPECT_GT(highest - lowest, 0.4) << write_grammar(inferred.grammar);  // still drawn
}

TEST(JointSizes, APieceInTwoPlacesKeepsEachPlacesOwnSize) {
  // One bay, wall, door, wall, with a 1.5 m door on the ground floor and
  // a 1.2 m one on every storey: merged into one piece, its door was
  // choice(1.2, 1.5), and variants put either anywhere.
  const Grammar source = parse_grammar(R"(
@start front
@scope rand(10, 16), 1, rand(8, 12)
front --> split(z){ 4 : repeat(x, 3){ bay(1.5) } | ~1 : repeat(z, 3){ repeat(x, 3){ bay(1.2) } } }
bay(w) --> split(x){ ~1 : I(wall) | w : I(door) | ~1 : I(wall) }
)",
                                       "front.grm");
  const Inference inferred = infer(test::derived_examples(source, 10), {});
  std::size_t doors = 0, misplaced = 0;
  for (std::uint64_t seed = 101; seed <= 130; ++seed)
    for (const LabelledBox& b : test::derived_parts(inferred.grammar, seed)) {
      if (b.label != "door") continue;
      ++doors;
      const double width = b.max.x - b.min.x, expected = b.min.z < 1e-6 ? 1.5 : 1.2;
      misplaced += std::abs(width - expected) <= 1e-6 ? 0 : 1;
    }
  EXPECT_GE(doors, 100u);
  EXPECT_EQ(misplaced, 0u) << write_grammar(inferred.grammar);
}

TEST(JointSizes, RunsOfTilesBesideASpecialTileTakeTheirCountFromTheirShare) {
  // Six equal bays, the entrance at any of them: the runs before and
  // after it were repeats of a drawn tile size, putting shop bays unlike
  // the entrance beside it; their counts follow the runs' shares.
  const Grammar source = parse_grammar(R"(
@start row
@scope rand(16, 36), 1, 4.2
row --> bays(randint(0, 5))
bays(k) --> split(x){ ~k : repeatN(x, k){ shop } | ~1 : split(x){ ~1 : I(wall) | 1.8 : I(entrance) | ~1 : I(wall) } | ~(5 - k) : repeatN(x, 5 - k){ shop } }
shop --> split(x){ 0.3 : I(pier) | ~1 : I(shopwindow) | 0.3 : I(pier) }
)",
                                       "row.grm");
  const Inference inferred = infer(test::derived_examples(source, 30), {});
  EXPECT_TRUE(test::source_derives_variants(source, inferred.grammar, 101, 130));
}

TEST(JointSizes, AWeightThatFollowsADrawInMetresIsASizeToo) {
  // Storeys 2u + 4.5 m high over an arcade u high, gables above, beside
  // two lodges: merging read the front's weights in the storeys' scale
  // (they spread least), so the storeys were one weight (~14.6) beside
  // the drawn arcade and gables, and joint sizes, which looked at draws
  // only, never saw the line (no variant kept it from ten examples). A
  // weight whose length varies may follow a draw. (A random style of
  // evaluate --random-styles 300 --seed 999, style 151.)
  const Grammar source = parse_grammar(R"(
@start lot
@scope rand(26.5, 40), rand(6.5, 8.5), rand(29, 39.5)
lot --> split(x){ ~0.7 : lodge | ~1.1 : lodge | ~2.3 : front(rand(3.9, 6.2), randint(0, 1)) }
front(u, b) --> split(x){ 1 : I(column) | ~1 : body(u, b) | 1 : I(column) }
body(u, b) --> split(z){ u : arcade | 2 * u + 4.5 : repeat(z, 3.5){ level(b) } | ~1 : gables }
arcade --> repeat(x, 4.5){ split(x){ ~1 : I(column) | ~8 : I(vitrine) | ~1 : I(column) } }
level(b) --> repeat(x, 4.5){ travee(b) }
travee(b) : b == 0 --> split(x){ ~1 : I(rect) | ~2.3 : I(panel) | ~1 : I(rect) }
travee(b) : b == 1 --> split(x){ ~1 : I(rect) | ~2.3 : split(z){ ~1 : I(balcony) | ~2 : I(window) } | ~1 : I(rect) }
gables --> I(roof) : 2
gables --> I(hip) : 1
lodge --> split(z){ ~2.8 : repeat(x, 4.5){ split(x){ ~1 : I(wall) | ~1.5 : I(window) | ~1 : I(wall) } } | ~1 : I(roof) }
)",
                                       "lot.grm");
  const Inference inferred = infer(test::derived_examples(source, 10), {});
  std::size_t measured = 0, kept = 0;
  for (std::uint64_t seed = 101; seed <= 140; ++seed) {
    double arcade = 0, top = 0;
    for (const LabelledBox& b : test::derived_parts(inferred.grammar, seed)) {
      if (b.label == "vitrine") arcade = b.max.z;
      if (b.label == "rect") top = std::max(top, b.max.z);
    }
    if (arcade == 0 || top == 0) continue;
    ++measured;
    kept += std::abs(top - (3 * arcade + 4.5)) <= 1e-6 ? 1 : 0;
  }
  EXPECT_GE(measured, 30u);
  EXPECT_EQ(kept, measured) << write_grammar(inferred.grammar);
}

TEST(JointSizes, ASizeEqualToAnEarlierOneThatFollowsADrawIsTheSame) {
  // A house h high, a shed and a store each within 0.3 m of half the
  // house but as high as each other: the shed follows the house loosely
  // (a line and a deviation drawn), the store is equal to the shed. It was
  // compared with the draws only, so it followed the house with a
  // deviation of its own, and a variant's shed and store differed.
  const Grammar source = parse_grammar(R"(
@scope 12, 8, 10
b --> body(rand(4, 10), rand(-0.3, 0.3))
body(h, e) --> split(x){
    ~1 : I(rect) |
    ~2 : split(z){ h : I(house) | ~1 : nil } |
    ~1 : split(z){ h * 0.5 + e : I(shed) | ~1 : nil } |
    ~1 : split(z){ h * 0.5 + e : I(store) | ~1 : nil } }
)",
                                       "sheds.grm");
  const Inference inferred = infer(test::derived_examples(source, 10), {});
  std::size_t measured = 0, apart = 0;
  for (std::uint64_t seed = 101; seed <= 140; ++seed) {
    std::optional<double> shed, store;
    for (const LabelledBox& b : test::derived_parts(inferred.grammar, seed)) {
      if (b.label == "shed") shed = b.max.z;
      if (b.label == "store") store = b.max.z;
    }
    if (!shed || !store) continue;
    ++measured;
    apart += std::abs(*shed - *store) <= 1e-6 ? 0 : 1;
  }
  EXPECT_GE(measured, 30u);
  EXPECT_EQ(apart, 0u) << write_grammar(inferred.grammar);
}

// A grammar learnt from 30 examples of tests/data/NAME, and the parts of
// its variants of seeds 1001 to 1040.
struct Learnt {
  Grammar grammar;
  std::vector<std::vector<LabelledBox>> variants;
};
Learnt learnt_from(const std::string& name) {
  const Grammar source = read_grammar_file(std::string(VERN_SOURCE_DIR "/tests/data/") + name);
  Learnt out{infer(examples_of(source, 30), {}).grammar, {}};
  for (std::uint64_t seed = 1001; seed <= 1040; ++seed)
    out.variants.push_back(test::derived_parts(derive_seed(out.grammar, seed)));
  return out;
}

// Where joining sizes keeps its draws to the values seen (a variant would
// leave some part no room), a choice of values stays a choice: the door
// bay after none, one or two bays of 3.8 m (choice(0, 3.8, 7.6)) does not
// become a range that puts it off the bays' grid.
TEST(JointSizes, ADrawKeptToTheValuesSeenStaysAChoiceOfThem) {
  const Learnt learnt = learnt_from("door_bays_on_grid.grm");
  std::size_t doors = 0, astray = 0;
  for (const std::vector<LabelledBox>& parts : learnt.variants)
    for (const LabelledBox& b : parts) {
      if (b.label != "portal") continue;
      ++doors;
      // Each door 1.2 m wide in the middle of a 3.8 m bay: 1.3 m past a
      // multiple of 3.8 from the row's start at x = 0.
      const double bays = (b.min.x - 1.3) / 3.8;
      astray += std::abs(bays - std::round(bays)) * 3.8 > 1e-3 ? 1 : 0;
    }
  EXPECT_GE(doors, 40u);
  EXPECT_EQ(astray, 0u) << write_grammar(learnt.grammar);
}

// The storeys' bays before their balcony bay are the ground floor's bays
// before the door, a run of none to two bays: drawn once for both, a run
// of no bays allowed (tests/data/storeys_on_door_bay.grm says why), so
// the storeys' balcony bays stand over the door. Not yet in houses of two
// storeys, which the examples give as two parts, not a repeat, each
// drawing its own run (12 of 125 railings; 83 before): at most one in
// ten astray.
TEST(JointSizes, ARunOfTilesDrawnOnceForTheStoreysMayBeNoTiles) {
  const Learnt learnt = learnt_from("storeys_on_door_bay.grm");
  std::size_t railings = 0, astray = 0;
  for (const std::vector<LabelledBox>& parts : learnt.variants) {
    std::optional<double> door;  // the door bay's left side
    for (const LabelledBox& b : parts)
      if (b.label == "portal") door = b.min.x - 0.9;
    if (!door) continue;
    for (const LabelledBox& b : parts) {
      if (b.label != "railing") continue;
      ++railings;
      astray += std::abs(b.min.x - 1 - *door) > 1e-3 ? 1 : 0;
    }
  }
  EXPECT_GE(railings, 40u);
  EXPECT_LE(10 * astray, railings) << astray << " of " << railings << "\n" << write_grammar(learnt.grammar);
}

}  // namespace
}  // namespace vern
