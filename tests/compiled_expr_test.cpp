// Compiled expressions (forward/compiled_expr.hpp) against the tree
// evaluator they stand in for: on random expressions over every operator
// and function, with parameters and constants that may be axes, zero or
// negative, the code either gives the same bits and leaves the random
// stream in the same state, or stops exactly where the tree evaluator
// reports an error.
#include "forward/compiled_expr.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>

#include "forward/evaluate.hpp"

namespace vern {
namespace {

// Random expressions; small numbers so that == and division by zero happen.
class ExprGenerator {
 public:
  explicit ExprGenerator(std::uint64_t seed) : rng_(seed) {}

  Expr make(int depth) {
    if (depth == 0 || pick(4) == 0) return leaf();
    switch (pick(4)) {
      case 0: return Expr::unary(pick(2) ? UnaryOp::Neg : UnaryOp::Not, make(depth - 1));
      case 1:
      case 2: return Expr::binary(static_cast<BinaryOp>(pick(13)), make(depth - 1), make(depth - 1));
      default: return call(depth);
    }
  }

 private:
  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }

  Expr leaf() {
    switch (pick(6)) {
      case 0: return Expr::param(static_cast<std::uint32_t>(pick(3)));
      case 1: return Expr::constant(static_cast<std::uint32_t>(pick(3)));
      case 2: return Expr::axis(static_cast<Axis>(pick(3)));
      default: {
        constexpr double kNumbers[] = {0, 1, 2, -1, 0.5, 3, 1e308, -2.5};
        return Expr::number(kNumbers[pick(8)]);
      }
    }
  }

  Expr call(int depth) {
    const auto f = static_cast<Function>(pick(14));
    const FunctionInfo& info = function_info(f);
    std::size_t argc = static_cast<std::size_t>(info.min_args);
    if (f == Function::Rand) argc = pick(2) ? 2 : 0;
    if (info.max_args < 0) argc += pick(3);
    std::vector<Expr> args;
    for (std::size_t i = 0; i < argc; ++i) args.push_back(make(depth - 1));
    return Expr::call(f, std::move(args));
  }

  std::mt19937_64 rng_;
};

const Value kParams[] = {2.5, Value::axis(Axis::Y), 0.0};
const Value kConstants[] = {1.0, -3.0, Value::axis(Axis::X)};

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// The tree evaluator's answer; nullopt where it throws.
std::optional<Value> tree(const Expr& e, RandomStream& random) {
  EvalContext ctx{kParams, kConstants, &random};
  try {
    return evaluate(e, ctx);
  } catch (const EvaluationError&) {
    return std::nullopt;
  }
}

TEST(CompiledExpr, CodeAgreesWithTheTreeEvaluator) {
  ExprGenerator gen(12345);
  int ran = 0, stopped = 0;
  for (int n = 0; n < 20000; ++n) {
    const Expr e = gen.make(1 + n % 5);
    ExprCode code;
    const CompiledExpr c = code.value(e);
    for (std::uint64_t key = 1; key <= 3; ++key) {
      RandomStream expected_stream(key);
      const std::optional<Value> expected = tree(e, expected_stream);
      RandomStream stream(key);
      switch (c.form) {
        case ExprForm::Literal:
          ASSERT_TRUE(expected && expected->is_number() && same_bits(expected->number(), c.literal));
          break;
        case ExprForm::Axis: ASSERT_TRUE(expected && *expected == Value::axis(static_cast<Axis>(c.index))); break;
        case ExprForm::Param: ASSERT_TRUE(expected && *expected == kParams[c.index]); break;
        case ExprForm::Constant: ASSERT_TRUE(expected && *expected == kConstants[c.index]); break;
        case ExprForm::Code: {
          double result = 0;
          if (run(code.at(c.index), kParams, kConstants, stream, result)) {
            ++ran;
            ASSERT_TRUE(expected.has_value()) << "code ran where the tree evaluator fails";
            ASSERT_TRUE(expected->is_number());
            ASSERT_TRUE(same_bits(expected->number(), result) || (std::isnan(result) && std::isnan(expected->number())))
                << result << " vs " << expected->number();
            // Same draws: the next one agrees.
            ASSERT_TRUE(same_bits(stream.uniform(), expected_stream.uniform()));
          } else {
            ++stopped;
            ASSERT_FALSE(expected.has_value()) << "code stopped where the tree evaluator succeeds";
          }
          break;
        }
        case ExprForm::Slow: break;
        case ExprForm::Absent: FAIL();
      }
    }
  }
  // The generator reaches both outcomes often.
  EXPECT_GT(ran, 5000);
  EXPECT_GT(stopped, 1000);
}

TEST(CompiledExpr, NumbersAreLiteralOnlyWhenFinite) {
  ExprCode code;
  const Expr sum = Expr::binary(BinaryOp::Add, Expr::number(1), Expr::number(2));
  EXPECT_EQ(code.number(sum).form, ExprForm::Literal);
  EXPECT_EQ(code.number(sum).literal, 3.0);
  const Expr huge = Expr::binary(BinaryOp::Mul, Expr::number(1e308), Expr::number(10));
  EXPECT_EQ(code.number(huge).form, ExprForm::Code);  // inf: the caller's check reports it
  const Expr by_zero = Expr::binary(BinaryOp::Div, Expr::number(1), Expr::number(0));
  EXPECT_EQ(code.number(by_zero).form, ExprForm::Code);  // not folded: the error is the tree evaluator's
}

TEST(CompiledExpr, ShortCircuitSkipsTheRightSideAndItsDraws) {
  ExprCode code;
  // 0 && rand() draws nothing, so it folds to 0.
  const Expr e = Expr::binary(BinaryOp::And, Expr::number(0), Expr::call(Function::Rand, {}));
  const CompiledExpr c = code.number(e);
  EXPECT_EQ(c.form, ExprForm::Literal);
  EXPECT_EQ(c.literal, 0.0);
}

TEST(CompiledExpr, ChoiceIsLeftToTheTreeEvaluator) {
  ExprCode code;
  const Expr e = Expr::call(Function::Choice, {Expr::axis(Axis::X), Expr::axis(Axis::Z)});
  EXPECT_EQ(code.value(e).form, ExprForm::Slow);
  EXPECT_EQ(code.number(Expr::binary(BinaryOp::Add, e, Expr::number(1))).form, ExprForm::Slow);
}

TEST(CompiledExpr, AxesAreKnownWhenWritten) {
  EXPECT_EQ(ExprCode::axis(Expr::axis(Axis::Z)).form, ExprForm::Axis);
  EXPECT_EQ(ExprCode::axis(Expr::axis(Axis::Z)).index, 2u);
  EXPECT_EQ(ExprCode::axis(Expr::number(1)).index, 1u);
  EXPECT_EQ(ExprCode::axis(Expr::number(1.5)).form, ExprForm::Slow);
  EXPECT_EQ(ExprCode::axis(Expr::param(0)).form, ExprForm::Param);
}

}  // namespace
}  // namespace vern
