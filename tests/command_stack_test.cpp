// Commands hold their limits whatever `ulimit -s` says (apps/support/
// command_stack.hpp): recursion within --max-depth, grammar text nested
// within the reader's 256 levels and examples cut 500 times deep
// run on a stack of 256 KiB as on Linux's default 8 MiB, where they used to
// end in a segmentation fault. And a thread smaller than the guard's reserve
// (a program embedding the library) is still guarded.
#include "support/command_stack.hpp"

#include <gtest/gtest.h>
#include <pthread.h>

#include <string>

#include "base/error.hpp"
#include "base/stack_guard.hpp"
#include "graph/parser.hpp"
#include "support/child_process.hpp"
#include "support/example_helpers.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

using test::ChildProcess;
using test::ChildSetup;
using test::TempFolder;
using test::write_text;

constexpr std::size_t kSmallStackKib = 256;

test::CommandResult run_on_small_stack(const std::string& program, const std::vector<std::string>& args,
                                       const TempFolder& dir) {
  ChildSetup setup;
  setup.limits.stack_kib = kSmallStackKib;
  ChildProcess child(program, args, dir.path(), setup);
  const ChildProcess::Ended ended = child.wait();
  EXPECT_EQ(ended.signal, 0) << program << " ended by signal " << ended.signal;
  return ended.result;
}

// n levels of `open` ... `close` around `inner`.
std::string nested(int n, const std::string& open, const std::string& inner, const std::string& close) {
  std::string text;
  for (int i = 0; i < n; ++i) text += open;
  text += inner;
  for (int i = 0; i < n; ++i) text += close;
  return text;
}

TEST(CommandStack, RecursionWithinMaxDepthDerivesOnASmallStack) {
  TempFolder dir;
  write_text(dir / "chain.grm",
             "@start start\n"
             "start --> a(900)\n"
             "a(n) : n > 0 --> split(x){ 0.001 : I(rect) | ~1 : a(n - 1) }\n"
             "a(n) : n <= 0 --> I(rect)\n");
  const test::CommandResult r = run_on_small_stack("generate", {"chain.grm", "-o", "out.obj"}, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("901 terminals"), std::string::npos) << r.err;
}

TEST(CommandStack, TextNestedWithinTheReadersBoundReadsOnASmallStack) {
  TempFolder dir;
  write_text(dir / "parens.grm", "a --> split(x){ ~" + nested(250, "(", "1", ")") + " : I(rect) }\n");
  write_text(dir / "calls.grm", "a --> split(x){ ~" + nested(250, "max(", "1", ", 1)") + " : I(rect) }\n");
  write_text(dir / "splits.grm", "a --> " + nested(250, "split(x){ ~1 : ", "I(rect)", " }") + "\n");
  for (const std::string grammar : {"parens.grm", "calls.grm", "splits.grm"}) {
    SCOPED_TRACE(grammar);
    const test::CommandResult r = run_on_small_stack("generate", {grammar, "-o", "out.obj"}, dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
  }
}

TEST(CommandStack, AnExampleCutFiveHundredTimesDeepInfersAndChecksOnASmallStack) {
  TempFolder dir;
  write_text(dir / "peeled.obj", test::boxes_obj(test::peeled_layout(500)));
  const test::CommandResult inferred = run_on_small_stack("infer", {"peeled.obj", "-o", "style.grm"}, dir);
  ASSERT_EQ(inferred.exit_code, 0) << inferred.err;
  const test::CommandResult checked = run_on_small_stack("check", {"style.grm", "peeled.obj"}, dir);
  EXPECT_EQ(checked.exit_code, 0) << checked.out << checked.err;
}

TEST(CommandStack, TheStackIsTheUsersLimitWhenLarger) {
  EXPECT_GE(command_stack_size(), kMinimumStack);
  EXPECT_LE(command_stack_size(), kMaximumStack);
  EXPECT_EQ(run_on_command_stack([] { return static_cast<int>(StackGuard().size() >> 20); }),
            static_cast<int>(command_stack_size() >> 20));
}

// A thread of 256 KiB, smaller than the guard's 512 KiB reserve, reading
// text nested 250 deep: the reader stops with a limit, or reads it, but
// never overflows.
void* read_deep_grammar(void* result) {
  try {
    parse_grammar("a --> split(x){ ~" + nested(250, "(", "1", ")") + " : I(rect) }\n", "deep.grm");
    *static_cast<std::string*>(result) = "read";
  } catch (const Error& e) {
    *static_cast<std::string*>(result) = e.kind() == ErrorKind::Limit ? "limit" : e.what();
  }
  return nullptr;
}

TEST(CommandStack, AThreadSmallerThanTheReserveIsStillGuarded) {
  pthread_attr_t attr;
  ASSERT_EQ(pthread_attr_init(&attr), 0);
  ASSERT_EQ(pthread_attr_setstacksize(&attr, kSmallStackKib << 10), 0);
  std::string result;
  pthread_t thread;
  ASSERT_EQ(pthread_create(&thread, &attr, read_deep_grammar, &result), 0);
  pthread_join(thread, nullptr);
  pthread_attr_destroy(&attr);
  EXPECT_TRUE(result == "read" || result == "limit") << result;
}

}  // namespace
}  // namespace vern
