// serve as a user starts it: a page on the loopback interface only, the
// grammar's buildings derived for several tabs at once, nothing outside
// the page's files handed out, the grammar file never written, and what is
// wrong on the command line said before anything listens.
#include <gtest/gtest.h>

#include <httplib.h>

#include <chrono>
#include <fstream>
#include <future>
#include <regex>
#include <sstream>
#include <thread>

#include "support/child_process.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;
using test::ChildProcess;
using test::TempFolder;

// The port serve says it listens on, waiting up to 20 s for the line.
int port_of(const ChildProcess& child) {
  const std::regex address(R"(serve: http://127\.0\.0\.1:(\d+)/)");
  for (int i = 0; i < 200; ++i) {
    std::smatch m;
    const std::string err = child.err_so_far();
    if (std::regex_search(err, m, address)) return std::stoi(m[1]);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ADD_FAILURE() << "serve said no address: " << child.err_so_far();
  return -1;
}

// The local addresses listening on `port`, from /proc/net/tcp (hex, as the
// kernel writes them: 0100007F is 127.0.0.1).
std::vector<std::string> listening_addresses(int port) {
  std::ifstream tcp("/proc/net/tcp");
  std::string line;
  std::vector<std::string> out;
  char hex[8];
  std::snprintf(hex, sizeof hex, "%04X", port);
  std::getline(tcp, line);
  while (std::getline(tcp, line)) {
    std::istringstream words(line);
    std::string slot, local, remote, state;
    words >> slot >> local >> remote >> state;
    if (state == "0A" && local.size() > 5 && local.substr(local.size() - 4) == hex) out.push_back(local.substr(0, 8));
  }
  return out;
}

TEST(ServeCli, ThePageAndItsBuildingsOnLoopbackOnly) {
  TempFolder dir;
  const std::string grammar = test::read_file(VERN_SOURCE_DIR "/data/grammars/garage.grm");
  test::write_text(dir / "garage.grm", grammar);
  const auto written = fs::last_write_time(dir / "garage.grm");
  ChildProcess serve("serve", {"garage.grm", "--port", "0"}, dir.path());
  const int port = port_of(serve);
  ASSERT_GT(port, 0);
  EXPECT_EQ(listening_addresses(port), std::vector<std::string>{"0100007F"});

  httplib::Client client("127.0.0.1", port);
  auto page = client.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("<textarea"), std::string::npos);
  auto three = client.Get("/vendor/three.module.js");
  ASSERT_TRUE(three);
  EXPECT_EQ(three->status, 200);
  EXPECT_GT(three->body.size(), 100000u);
  for (const char* outside : {"/../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/vendor/../../../etc/passwd",
                              "/node_modules/three/package.json", "/garage.grm"}) {
    auto r = client.Get(outside);
    ASSERT_TRUE(r) << outside;
    EXPECT_EQ(r->status, 404) << outside;
    EXPECT_EQ(r->body.find("root:"), std::string::npos) << outside;
  }
  auto session = client.Get("/api/session");
  ASSERT_TRUE(session);
  EXPECT_NE(session->body.find("\"name\":\"garage.grm\""), std::string::npos) << session->body.substr(0, 300);

  // Several tabs at once, each its own seeds.
  std::vector<std::future<std::string>> tabs;
  for (int tab = 0; tab < 4; ++tab)
    tabs.push_back(std::async(std::launch::async, [port, tab] {
      httplib::Client c("127.0.0.1", port);
      const std::string body = R"({"text": "@scope 10, 10, 10\nb --> split(x){ ~1 : I(rect) | ~rand(1, 3) : I(roof) }", "seed": )" +
                               std::to_string(tab + 1) + R"(, "count": 2})";
      auto r = c.Post("/api/derive", body, "application/json");
      return r ? std::to_string(r->status) + " " + r->body : std::string("no answer");
    }));
  for (auto& tab : tabs) {
    const std::string answer = tab.get();
    EXPECT_EQ(answer.rfind("200 {", 0), 0u) << answer.substr(0, 200);
    EXPECT_NE(answer.find("\"ok\":true"), std::string::npos) << answer.substr(0, 200);
  }
  auto bad = client.Post("/api/derive", "not json", "application/json");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  auto big = client.Post("/api/derive", std::string(5u << 20, ' '), "application/json");
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 413);
  // Edits live in the browser: the file is as it was.
  EXPECT_EQ(test::read_file(dir / "garage.grm"), grammar);
  EXPECT_EQ(fs::last_write_time(dir / "garage.grm"), written);
}

TEST(ServeCli, ExamplesAloneStartFromTheirInferredGrammar) {
  TempFolder dir;
  ChildProcess serve("serve", {VERN_SOURCE_DIR "/data/examples/garage", "--port", "0"}, dir.path());
  const int port = port_of(serve);
  ASSERT_GT(port, 0);
  httplib::Client client("127.0.0.1", port);
  auto session = client.Get("/api/session");
  ASSERT_TRUE(session);
  EXPECT_NE(session->body.find("\"name\":\"inferred.grm\""), std::string::npos);
  EXPECT_NE(session->body.find("building -->"), std::string::npos);
  EXPECT_EQ(std::count(session->body.begin(), session->body.end(), '{') > 10, true);
  EXPECT_NE(session->body.find("variant_009.obj"), std::string::npos);  // the ten examples, to show beside
}

TEST(ServeCli, WhatIsWrongIsSaidBeforeAnythingListens) {
  TempFolder dir;
  auto r = test::run_program("serve", {}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("nothing to serve"), std::string::npos) << r.err;
  test::write_text(dir / "a.grm", "a --> nil\n");
  test::write_text(dir / "b.grm", "b --> nil\n");
  r = test::run_program("serve", {"a.grm", "b.grm"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("two grammars"), std::string::npos) << r.err;
  test::write_text(dir / "broken.grm", "a --> split(x){ ~1 I(rect) }\n");
  r = test::run_program("serve", {"broken.grm"}, dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("broken.grm:1:"), std::string::npos) << r.err;
  // A port another program holds.
  ChildProcess first("serve", {"a.grm", "--port", "0"}, dir.path());
  const int port = port_of(first);
  ASSERT_GT(port, 0);
  r = test::run_program("serve", {"a.grm", "--port", std::to_string(port)}, dir.path());
  EXPECT_EQ(r.exit_code, 5) << r.err;
  EXPECT_NE(r.err.find("could not listen on 127.0.0.1:" + std::to_string(port)), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vern
