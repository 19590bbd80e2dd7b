// Expressions as flat post-order trees: shape, children, equality, hashing.
#include "graph/expr.hpp"

#include <gtest/gtest.h>

namespace vern {
namespace {

TEST(Expr, PostOrderKeepsSubtreeSizesAndChildren) {
  // min(a + 2, 3) with a = param 0
  Expr sum = Expr::binary(BinaryOp::Add, Expr::param(0), Expr::number(2));
  Expr e = Expr::call(Function::Min, {sum, Expr::number(3)});
  ASSERT_EQ(e.nodes().size(), 5u);
  EXPECT_EQ(e.node(e.root()).size, 5u);
  const auto kids = e.children(e.root());
  ASSERT_EQ(kids.size(), 2u);
  EXPECT_EQ(e.node(kids[0]).kind, ExprKind::Binary);
  EXPECT_EQ(e.node(kids[1]).number, 3.0);
  const auto sum_kids = e.children(kids[0]);
  EXPECT_EQ(e.node(sum_kids[0]).kind, ExprKind::Param);
  EXPECT_EQ(e.node(sum_kids[1]).number, 2.0);
}

// A one-node Expr keeps its place in the text without a heap block, and
// copies, moves and growth keep it.
TEST(Expr, OneNodeKeepsItsLocation) {
  const SourceLoc at{3, 7}, plus{3, 9}, other{4, 1};
  Expr e = Expr::number(2, at);
  EXPECT_EQ(e.loc(), at);
  Expr copy = e;
  EXPECT_EQ(copy.loc(), at);
  Expr moved = std::move(copy);
  EXPECT_EQ(moved.loc(), at);
  moved = Expr::param(0, other);
  EXPECT_EQ(moved.loc(), other);
  const Expr sum = Expr::binary(BinaryOp::Add, e, Expr::number(1), plus);
  ASSERT_EQ(sum.nodes().size(), 3u);
  EXPECT_EQ(sum.loc(0), at);
  EXPECT_EQ(sum.loc(1), SourceLoc{});
  EXPECT_EQ(sum.loc(), plus);
  EXPECT_EQ(sum, Expr::binary(BinaryOp::Add, Expr::number(2), Expr::number(1)));  // places take no part
  EXPECT_EQ(Expr().loc(), SourceLoc{});
}

TEST(Expr, NegatedLiteralIsOneLiteral) {
  Expr e = Expr::unary(UnaryOp::Neg, Expr::number(2.5));
  EXPECT_EQ(e, Expr::number(-2.5));
  EXPECT_EQ(e.literal(), -2.5);
  // A negated parameter stays an operation.
  EXPECT_EQ(Expr::unary(UnaryOp::Neg, Expr::param(1)).nodes().size(), 2u);
}

TEST(Expr, EqualityAndHashIgnoreSourceLocations) {
  Expr a = Expr::binary(BinaryOp::Mul, Expr::number(2, {1, 3}), Expr::constant(0, {1, 7}), {1, 5});
  Expr b = Expr::binary(BinaryOp::Mul, Expr::number(2), Expr::constant(0));
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.hash(), b.hash());
  Expr c = Expr::binary(BinaryOp::Mul, Expr::number(2), Expr::constant(1));
  EXPECT_NE(a, c);
  EXPECT_NE(a.hash(), c.hash());
}

TEST(Expr, KnowsWhetherItDrawsOrUsesParameters) {
  EXPECT_TRUE(Expr::call(Function::Rand, {Expr::number(1), Expr::number(2)}).draws_random());
  EXPECT_FALSE(Expr::call(Function::Max, {Expr::number(1), Expr::param(0)}).draws_random());
  EXPECT_TRUE(Expr::call(Function::Max, {Expr::number(1), Expr::param(0)}).uses_params());
}

TEST(Expr, FunctionTableIsIndexedByFunction) {
  for (const auto& info : function_table()) {
    EXPECT_EQ(&function_info(info.function), &info);
    EXPECT_EQ(find_function(info.name), info.function);
  }
  EXPECT_FALSE(find_function("nosuch").has_value());
}

}  // namespace
}  // namespace vern
