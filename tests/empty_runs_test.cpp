// A run of no tiles: a door bay at the start of a row is the row with its
// run of bays zero long (inverse/merge/empty_runs.hpp).
#include "inverse/merge/empty_runs.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "graph/writer.hpp"
#include "inverse/merge/merge.hpp"
#include "inverse/write/rule_naming.hpp"
#include "support/example_graphs.hpp"

namespace vern {
namespace {

// A row of bays 3.5 m wide with a door bay after `bays` of them, as one
// example's graph: no run before the door when bays is 0.
std::string row(int bays) {
  const std::string bay = "repeat(x, 3.5){ split(x){ ~1 : I(wall) | ~1.5 : I(window) | ~1 : I(wall) } }";
  const double run = 3.5 * bays, rest = 21 - run - 3.5;
  std::string text = "split(x){ ";
  if (bays > 0) text += "~" + std::to_string(run) + " : " + bay + " | ";
  return text + "~1 : I(wall) | ~1.5 : I(door) | ~1 : I(wall) | ~" + std::to_string(rest) + " : " + bay + " }";
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

}  // namespace
}  // namespace vern
