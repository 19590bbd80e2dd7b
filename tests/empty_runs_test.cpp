// A run of no tiles: a door bay at the start of a row is the row with its
// run of bays zero long (inverse/merge/empty_runs.hpp).
#include "inverse/merge/empty_runs.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "graph/nodes_below.hpp"
#include "graph/writer.hpp"
#include "inverse/merge/merge.hpp"
#include "inverse/write/rule_naming.hpp"
#include "support/example_graphs.hpp"

namespace vern {
namespace {

// A row of bays 3.5 m wide with a door bay after `bays` of them, as one
// example's graph: no run before the door when bays is 0.
std::string row(int bays, const std::string& opening = "window") {
  const std::string bay = "repeat(x, 3.5){ split(x){ ~1 : I(wall) | ~1.5 : I(" + opening + ") | ~1 : I(wall) } }";
  const double run = 3.5 * bays, rest = 21 - run - 3.5;
  std::string text = "split(x){ ";
  if (bays > 0) text += "~" + std::to_string(run) + " : " + bay + " | ";
  return text + "~1 : I(wall) | ~1.5 : I(door) | ~1 : I(wall) | ~" + std::to_string(rest) + " : " + bay + " }";
}

// The rows of a merged graph: splits with the door among their parts.
std::vector<NodeId> door_rows(const Grammar& g, NodeId merged) {
  const LabelId door = *g.find_label("door");
  std::vector<NodeId> rows;
  for (const NodeId id : nodes_below(g, merged))
    if (const auto* s = std::get_if<Split>(&g.op(id)))
      for (const SplitPart& p : s->parts)
        if (const auto* prim = std::get_if<Primitive>(&g.op(p.child)); prim && prim->label == door) rows.push_back(id);
  return rows;
}

TEST(EmptyRuns, ADoorBayAtTheStartIsTheRowWithNoBaysBeforeIt) {
  Grammar g;
  std::vector<std::string> texts;
  for (int bays : {0, 1, 2, 0, 1, 2}) texts.push_back(row(bays));
  const NodeId merged = merge_examples(g, test::example_graphs(g, texts), test::uniform_merge());
  const auto* front = std::get_if<Split>(&g.op(merged));
  ASSERT_NE(front, nullptr) << write_grammar(rules_for(g, merged, {}));
  ASSERT_EQ(front->parts.size(), 5u) << write_grammar(rules_for(g, merged, {}));
  const auto run = literal_range(front->parts[0].size.value);
  ASSERT_TRUE(run) << write_grammar(rules_for(g, merged, {}));
  EXPECT_EQ(run->lo, 0);
  EXPECT_NEAR(run->hi, 7, 1e-9);
}

TEST(EmptyRuns, StoreysWhoseBaysDifferAreRowsWithTheirRunZeroLongToo) {
  // Storeys of a house, each with the door bay after the house's number
  // of bays, their other bays of windows or of panels: the storeys of a
  // house are a repeat of a choice of rows, and the houses with the door
  // bay first have rows of one part fewer. Those rows are the others
  // with their run zero long: every row in the merged choice has the run.
  Grammar g;
  std::vector<std::string> texts;
  for (int bays : {0, 1, 2, 0, 1, 2})
    texts.push_back("split(z){ ~3 : " + row(bays) + " | ~3 : " + row(bays, "panel") + " | ~3 : " + row(bays, "panel") +
                    " | ~3 : " + row(bays) + " }");
  const NodeId merged = merge_examples(g, test::example_graphs(g, texts), test::uniform_merge());
  const std::vector<NodeId> rows = door_rows(g, merged);
  ASSERT_FALSE(rows.empty()) << write_grammar(rules_for(g, merged, {}));
  for (const NodeId r : rows) EXPECT_EQ(std::get<Split>(g.op(r)).parts.size(), 5u) << write_grammar(rules_for(g, merged, {}));
}

TEST(EmptyRuns, StoreysAllAlikeWithTheDoorBayFirstGainTheRunOfStoreysThatDiffer) {
  // Houses with the door bay first whose storeys all came out alike (a
  // repeat of one row) beside houses whose storeys differ (a repeat of a
  // choice of rows): the one row is the others with their run zero long.
  Grammar g;
  std::vector<std::string> texts;
  for (int bays : {0, 1, 2, 0, 1, 2}) {
    const std::string second = bays == 0 ? row(bays) : row(bays, "panel");
    texts.push_back("split(z){ ~3 : " + row(bays) + " | ~3 : " + second + " | ~3 : " + second + " | ~3 : " + row(bays) +
                    " }");
  }
  const NodeId merged = merge_examples(g, test::example_graphs(g, texts), test::uniform_merge());
  const std::vector<NodeId> rows = door_rows(g, merged);
  ASSERT_FALSE(rows.empty()) << write_grammar(rules_for(g, merged, {}));
  for (const NodeId r : rows) EXPECT_EQ(std::get<Split>(g.op(r)).parts.size(), 5u) << write_grammar(rules_for(g, merged, {}));
}

}  // namespace
}  // namespace vern
