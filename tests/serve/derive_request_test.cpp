// The editor's question and its answers: buildings with what made each
// part, errors at their line and column, runaway grammars stopped, and
// requests that are not the question refused.
#include "serve/derive_request.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace vern {
namespace {

using nlohmann::json;

json ask(const std::string& request, int expect_status = 200) {
  const ServeSession session;
  const ApiAnswer answer = derive_request(request, session);
  EXPECT_EQ(answer.status, expect_status) << answer.body;
  return json::parse(answer.body);
}

json ask_text(const std::string& text, int seed = 1, int count = 1) {
  return ask(json{{"text", text}, {"seed", seed}, {"count", count}}.dump());
}

constexpr const char* kHouse =
    "@scope 10, 8, 6\n"
    "house --> split(z){ ~2 : floor(1) | ~1 : I(roof) }\n"
    "floor(n) --> split(x){ ~1 : I(wall) | ~rand(1, 2) : I(window) | ~1 : I(wall) }\n";

TEST(DeriveRequest, EachPartComesWithItsPlaceAndTheRulesThatMadeIt) {
  const json a = ask_text(kHouse, 4, 2);
  ASSERT_TRUE(a["ok"].get<bool>()) << a.dump();
  ASSERT_EQ(a["buildings"].size(), 2u);
  EXPECT_EQ(a["buildings"][0]["seed"], 4);
  EXPECT_EQ(a["buildings"][1]["seed"], 5);
  const json& parts = a["buildings"][0]["parts"];
  ASSERT_EQ(parts.size(), 4u);  // wall, window, wall, roof
  const json& labels = a["labels"];
  const json& window = parts[1];
  EXPECT_EQ(labels[window["label"].get<int>()], "window");
  // Inserted by the I(window) on line 3, through house then floor(1).
  EXPECT_EQ(window["at"][0], 3);
  EXPECT_EQ(window["chain"], "house > floor(1)");
  ASSERT_EQ(window["rules"].size(), 2u);
  EXPECT_EQ(a["rules"][window["rules"][1].get<int>()]["label"], "floor");
  EXPECT_EQ(a["rules"][window["rules"][1].get<int>()]["line"], 3);
  // The roof fills the top third of the 10 x 8 x 6 plot: its matrix maps
  // the unit box there (columns: x axis, y axis, z axis, origin).
  const json& roof = parts[3];
  EXPECT_EQ(labels[roof["label"].get<int>()], "roof");
  const std::vector<double> m = roof["matrix"];
  EXPECT_DOUBLE_EQ(m[0], 10);
  EXPECT_DOUBLE_EQ(m[5], 8);
  EXPECT_DOUBLE_EQ(m[10], 2);
  EXPECT_DOUBLE_EQ(m[14], 4);
  // The roof's own mesh (a gable, not a box) and each label's colour.
  EXPECT_GT(a["meshes"]["roof"]["positions"].size(), 0u);
  EXPECT_NE(a["meshes"]["roof"], a["meshes"]["wall"]);
  EXPECT_EQ(a["colours"]["window"].size(), 3u);
  // Seeds draw: the window's width differs from building to building.
  EXPECT_NE(a["buildings"][0]["parts"][1]["matrix"][0], a["buildings"][1]["parts"][1]["matrix"][0]);
}

TEST(DeriveRequest, AGrammarThatDoesNotReadIsAnErrorAtItsLineAndColumn) {
  const json a = ask_text("house --> split(z){\n    ~1 : I(wall) |\n    ~1 I(roof) }\n");
  ASSERT_FALSE(a["ok"].get<bool>()) << a.dump();
  EXPECT_EQ(a["error"]["kind"], "input");
  EXPECT_EQ(a["error"]["line"], 3);
  EXPECT_EQ(a["error"]["column"], 8);
  EXPECT_NE(a["error"]["message"].get<std::string>().find("expected ':'"), std::string::npos) << a.dump();
  EXPECT_FALSE(a["error"]["hint"].get<std::string>().empty());
}

TEST(DeriveRequest, ARunawayGrammarStopsAtTheSessionsLimitsAsAnError) {
  const json a = ask_text("a --> split(x){ ~1 : a | ~1 : a }\n");
  ASSERT_FALSE(a["ok"].get<bool>()) << a.dump();
  EXPECT_EQ(a["error"]["kind"], "limit");
  EXPECT_EQ(a["error"]["line"], 1);
  const json b = ask_text("a --> repeat(x, 0.000001){ I(rect) }\n");
  ASSERT_FALSE(b["ok"].get<bool>()) << b.dump();
  EXPECT_EQ(b["error"]["kind"], "limit");
}

TEST(DeriveRequest, PastTheSessionsPartsTheRestOfThePageIsLeftOutAndSaid) {
  ServeSession session;
  session.most_parts = 1000;
  const std::string rows = json{{"text", "a --> repeatN(x, 20){ repeatN(y, 20){ I(rect) } }\n"}, {"count", 5}}.dump();
  const json a = json::parse(derive_request(rows, session).body);  // 400 parts a building
  ASSERT_TRUE(a["ok"].get<bool>()) << a.dump().substr(0, 300);
  EXPECT_EQ(a["buildings"].size(), 3u);  // 3 x 400 reaches 1,000
  EXPECT_NE(a["note"].get<std::string>().find("the first 3 of 5 buildings"), std::string::npos) << a["note"];
  session.most_parts = 2000;
  EXPECT_EQ(json::parse(derive_request(rows, session).body)["note"], "");
}

TEST(DeriveRequest, APlotSizeGivenReplacesTheGrammarsScope) {
  const json a = ask(json{{"text", kHouse}, {"size", {20, 8, 6}}}.dump());
  ASSERT_TRUE(a["ok"].get<bool>()) << a.dump();
  EXPECT_EQ(a["buildings"][0]["size"], json({20.0, 8.0, 6.0}));
  EXPECT_DOUBLE_EQ(a["buildings"][0]["parts"][3]["matrix"][0].get<double>(), 20.0);  // the roof spans it
  for (const char* bad : {"[1, 2]", "[1, 2, 0]", "[1, -2, 3]", "\"big\"", "[1, 2, 1e9]"}) {
    const json r = ask("{\"text\": \"a --> nil\", \"size\": " + std::string(bad) + "}", 400);
    EXPECT_NE(r["error"]["message"].get<std::string>().find("size"), std::string::npos) << bad;
  }
}

TEST(DeriveRequest, RequestsThatAreNotTheQuestionAreRefusedSayingWhy) {
  for (const char* bad : {"", "not json", "[1, 2]", "{\"seed\": 1}", "{\"text\": 3}", "{\"text\": \"a --> nil\", \"seed\": -1}",
                          "{\"text\": \"a --> nil\", \"count\": 0}", "{\"text\": \"a --> nil\", \"count\": 65}",
                          "{\"text\": \"a --> nil\", \"count\": 1.5}"}) {
    const json a = ask(bad, 400);
    EXPECT_FALSE(a["ok"].get<bool>()) << bad;
    EXPECT_FALSE(a["error"]["message"].get<std::string>().empty()) << bad;
  }
}

TEST(DeriveRequest, TheSessionSaysTheGrammarAndTheExamplesParts) {
  ServeSession session;
  session.grammar_name = "g.grm";
  session.grammar_text = "a --> I(\"<b>\")\n";
  Example e;
  e.source = "ex.obj";
  LabelledBox b;
  b.label = "wall";
  b.max = {1, 2, 3};
  e.boxes.push_back(b);
  session.examples.push_back(e);
  const json s = json::parse(session_json(session));
  EXPECT_EQ(s["name"], "g.grm");
  EXPECT_EQ(s["text"], "a --> I(\"<b>\")\n");
  ASSERT_EQ(s["examples"].size(), 1u);
  EXPECT_EQ(s["examples"][0]["parts"][0]["label"], "wall");
  EXPECT_EQ(s["examples"][0]["parts"][0]["max"][2], 3.0);
  EXPECT_EQ(s["colours"]["wall"].size(), 3u);
}

}  // namespace
}  // namespace vern
