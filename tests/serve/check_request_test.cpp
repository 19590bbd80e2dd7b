// The inference view's question: which examples the editor's text
// derives, with check's witness, or check's reason where it does not.
#include "serve/check_request.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "graph/writer.hpp"
#include "inverse/infer.hpp"
#include "inverse/load/example.hpp"

namespace vern {
namespace {

using nlohmann::json;

ServeSession garage_session() {
  ServeSession session;
  for (const auto& file : example_files({VERN_SOURCE_DIR "/data/examples/garage"}))
    session.examples.push_back(load_example(file));
  return session;
}

json ask(const std::string& text, const ServeSession& session) {
  const ApiAnswer a = check_request(json{{"text", text}}.dump(), session);
  EXPECT_EQ(a.status, 200) << a.body;
  return json::parse(a.body);
}

TEST(CheckRequest, EachExampleIsDerivableWithItsWitnessOrNotWithItsReason) {
  const ServeSession session = garage_session();
  ASSERT_EQ(session.examples.size(), 10u);
  // The grammar inferred from them derives all ten, each with its witness.
  const std::string inferred = write_grammar(infer(session.examples, InferOptions{}).grammar);
  json a = ask(inferred, session);
  ASSERT_TRUE(a["ok"].get<bool>()) << a.dump();
  ASSERT_EQ(a["examples"].size(), 10u);
  for (const json& e : a["examples"]) {
    EXPECT_TRUE(e["derivable"].get<bool>()) << e.dump();
    EXPECT_FALSE(e["witness"].empty()) << e.dump();
  }
  EXPECT_NE(a["examples"][0]["name"].get<std::string>().find("variant_000.obj"), std::string::npos);
  // A plain block derives none of them: each says why.
  a = ask("building --> I(rect)\n", session);
  ASSERT_TRUE(a["ok"].get<bool>()) << a.dump();
  for (const json& e : a["examples"]) {
    EXPECT_FALSE(e["derivable"].get<bool>()) << e.dump();
    EXPECT_FALSE(e["reason"].get<std::string>().empty()) << e.dump();
  }
}

TEST(CheckRequest, ATextThatDoesNotReadIsAnErrorAtItsLine) {
  const json a = ask("building --> split(x){ ~1 I(rect) }\n", garage_session());
  ASSERT_FALSE(a["ok"].get<bool>()) << a.dump();
  EXPECT_EQ(a["error"]["line"], 1);
  const ApiAnswer bad = check_request("[]", ServeSession{});
  EXPECT_EQ(bad.status, 400);
}

}  // namespace
}  // namespace vern
