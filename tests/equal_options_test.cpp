// Alternatives that are the same operation become one.
#include "inverse/merge/equal_options.hpp"

#include <gtest/gtest.h>

#include "graph/writer.hpp"
#include "support/example_graphs.hpp"

namespace vern {
namespace {

TEST(EqualOptions, SameChildIsOneOptionWhereTheFirstStoodWithThePrioritiesAdded) {
  Grammar g;
  const auto r = test::example_graphs(g, {"I(a)", "I(b)"});
  Choose c;
  c.options = {{Expr{}, Expr::number(2), r[0]}, {Expr{}, Expr::number(1), r[1]}, {Expr{}, Expr{}, r[0]}};
  EXPECT_TRUE(join_equal_options(c));
  ASSERT_EQ(c.options.size(), 2u);
  EXPECT_EQ(c.options[0].child, r[0]);
  EXPECT_EQ(c.options[0].priority.literal(), 3.0);  // no priority counts as 1
  EXPECT_EQ(c.options[1].child, r[1]);
  EXPECT_FALSE(join_equal_options(c));
}

TEST(EqualOptions, ConditionsAndPrioritiesThatAreNotNumbersKeepTheirOptions) {
  Grammar g;
  const auto r = test::example_graphs(g, {"I(a)"});
  Choose c;
  c.options = {{Expr{}, Expr::number(1), r[0]},
               {Expr::param(0), Expr::number(1), r[0]},
               {Expr{}, Expr::param(0), r[0]}};
  EXPECT_FALSE(join_equal_options(c));
  EXPECT_EQ(c.options.size(), 3u);
}

}  // namespace
}  // namespace vern
