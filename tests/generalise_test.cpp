// Joining the alternatives of a choice (generalise.hpp): examples that
// differ only deep down come back as one building with choices where they
// differ, not one alternative per example; and only where nothing that
// went together is drawn apart.
#include "inverse/merge/generalise.hpp"

#include <gtest/gtest.h>

#include <set>

#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

// The node a part stands for, through the calls inference writes.
NodeId through_calls(const Grammar& g, NodeId n) {
  while (const auto* call = std::get_if<Call>(&g.op(n))) n = g.rules[call->rule].body;
  return n;
}

// A block between two sheds whose bays are of one of three kinds, chosen
// once per building and kept on every floor; the block's share of the
// plot, the sheds' height and the pavilion's vary continuously, so no two
// examples' top splits are alike. (A style evaluate --random-styles drew.)
constexpr const char* kKeptKind = R"(
@start site
@scope rand(10, 13.5), rand(18.5, 27), rand(10, 14)
site --> plan(rand(4.8, 7.4))
plan(h) --> split(y){ ~0.7 : shed(h) | ~rand(1.5, 2.7) : block(randint(0, 2)) | ~0.7 : shed(h) }
block(b) --> split(z){ ~1 : repeat(z, 3){ floor(b) } | tnormal(2.25, 0.27, 1.7, 2.8) : pavilion }
floor(b) --> repeat(x, 4.2){ bay(b) }
bay(b) : b == 0 --> split(x){ ~1 : I(render) | ~2.4 : I(infill) | ~1 : I(render) }
bay(b) : b == 1 --> split(x){ ~1 : I(render) | ~2.4 : split(x){ ~1 : I(pane) | ~0.4 : I(render) | ~1 : I(pane) } | ~1 : I(render) }
bay(b) : b == 2 --> split(x){ ~1 : I(render) | ~2.4 : split(z){ ~1 : I(loggia) | ~2 : I(pane) } | ~1 : I(render) }
pavilion --> split(x){ ~0.8 : nil | ~1 : I(hip) | ~0.8 : nil }
shed(h) --> split(z){ h : repeat(x, 3.3){ shedBay } | ~1 : R(z, pi / 2){ I(roof) } }
shedBay --> split(x){ ~1 : I(render) | ~1.7 : I(pane) | ~1 : I(render) }
)";

TEST(Generalise, AKindChosenOncePerBuildingIsOneChoiceWhereItActsNotOneBuildingPerKind) {
  const Grammar source = parse_grammar(kKeptKind, "kept.grm");
  const std::vector<Example> examples = test::derived_examples(source, 10);
  const Inference inferred = infer(examples, {});
  const Grammar& g = inferred.grammar;
  const std::string text = write_grammar(g);
  // One site: sheds, block, sheds, whatever the kind.
  const auto* site = std::get_if<Split>(&g.op(through_calls(g, g.rules[g.start_rule].body)));
  ASSERT_NE(site, nullptr) << text;
  ASSERT_EQ(site->parts.size(), 3u) << text;
  // The block: its storeys a choice of the three kinds, under the pavilion.
  const auto* block = std::get_if<Split>(&g.op(through_calls(g, site->parts[1].child)));
  ASSERT_NE(block, nullptr) << text;
  ASSERT_EQ(block->parts.size(), 2u) << text;
  const auto* kinds = std::get_if<Choose>(&g.op(through_calls(g, block->parts[0].child)));
  ASSERT_NE(kinds, nullptr) << text;
  EXPECT_EQ(kinds->options.size(), 3u) << text;
  for (const Example& e : examples) {
    const CheckResult r = check_example(g, e.boxes, example_size(e));
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << text;
  }
}

// Ground floors with a 1.2 m door or a 3 m shop window under a gable or a
// hip roof: which fills the middle and how wide it is go together.
constexpr const char* kDoorOrShop = R"(
@start house
@scope rand(8, 12), 6, rand(6, 9)
house --> split(z){ ~1.5 : ground | ~1 : roof }
ground --> split(x){ ~1 : I(wall) | 1.2 : I(door) | ~1 : I(wall) } : 1
ground --> split(x){ ~1 : I(wall) | 3 : I(shop) | ~1 : I(wall) } : 1
roof --> I(gable) : 1
roof --> I(hip) : 1
)";

TEST(Generalise, ALengthThatGoesWithWhatFillsItIsNeverDrawnApartFromIt) {
  const Grammar source = parse_grammar(kDoorOrShop, "door_or_shop.grm");
  const Inference inferred = infer(test::derived_examples(source, 12), {});
  const std::string text = write_grammar(inferred.grammar);
  std::set<std::string> seen;
  for (std::uint64_t seed = 1001; seed <= 1040; ++seed) {
    DeriveOptions o;
    o.seed = seed;
    for (const LabelledBox& b : test::derived_parts(derive(inferred.grammar, o))) {
      seen.insert(b.label);
      if (b.label == "door") {
        EXPECT_NEAR(b.max.x - b.min.x, 1.2, 1e-6) << seed << "\n" << text;
      } else if (b.label == "shop") {
        EXPECT_NEAR(b.max.x - b.min.x, 3, 1e-6) << seed << "\n" << text;
      }
    }
  }
  // Both kinds of each were drawn: the test saw what it checks.
  for (const char* label : {"door", "shop", "gable", "hip"}) EXPECT_TRUE(seen.count(label)) << label << "\n" << text;
}

TEST(Generalise, PlacesChosenTogetherStayTogetherBesideAPlaceChosenFreely) {
  // Houses whose ground floor and storeys come in three kinds that go
  // together (a door bay's place, kept on every storey), under a roof of
  // any of three kinds: all nine combinations seen, three times each.
  // Said freely, a variant would put storeys of one kind on a ground floor
  // of another; listed, nine alternatives repeat each roof three times.
  // The roof becomes a choice in each of three houses.
  // Built interned, as merging leaves the examples' graphs: one node per
  // distinct part. Each house in its own proportions, as examples on plots
  // of their own are: alike splits are not one frame, alternatives are.
  Grammar g;
  double storeys_share = 2;
  auto primitive = [&](const std::string& label) { return g.intern({Primitive{g.label_id(label)}, {}}); };
  Choose houses_seen;
  for (const char* kind : {"a", "b", "c"})
    for (const char* roof : {"hip", "gable", "flat"}) {
      Split house{Expr::axis(Axis::Z), {}};
      house.parts.push_back({Size{Expr::number(4), false}, primitive(std::string("ground_") + kind)});
      house.parts.push_back({Size{Expr::number(storeys_share += 0.1), true}, primitive(std::string("storeys_") + kind)});
      house.parts.push_back({Size{Expr::number(1), true}, primitive(roof)});
      houses_seen.options.push_back({Expr{}, Expr::number(3), g.intern({std::move(house), {}})});
    }
  const NodeId all = g.intern({std::move(houses_seen), {}});
  bool changed = false;
  const NodeId root = generalise_free_parts(g, all, MergeOptions{},
                                            FrameKinds::AlikeAndAlternatives, RowBook{}, changed);
  ASSERT_TRUE(changed);
  const auto* houses = std::get_if<Choose>(&g.op(root));
  ASSERT_NE(houses, nullptr) << write_grammar(g);
  std::set<NodeId> distinct;
  for (const auto& o : houses->options) distinct.insert(o.child);
  ASSERT_EQ(distinct.size(), 3u);
  for (const NodeId house : distinct) {
    const auto& split = std::get<Split>(g.op(house));
    const auto& ground = std::get<Primitive>(g.op(split.parts[0].child));
    const auto& storeys = std::get<Primitive>(g.op(split.parts[1].child));
    EXPECT_EQ(g.label(ground.label).substr(7), g.label(storeys.label).substr(8));
    const auto* roof = std::get_if<Choose>(&g.op(split.parts[2].child));
    ASSERT_NE(roof, nullptr);
    EXPECT_EQ(roof->options.size(), 3u);
  }
}

}  // namespace
}  // namespace vern
