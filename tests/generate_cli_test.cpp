// The generate command as a user meets it: outputs, determinism, errors,
// exit codes, and files left untouched when a run fails.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>

#include "support/run_command.hpp"

namespace vern {
namespace {

using test::list_folder;
using test::read_file;
using test::run_program;
using test::TempFolder;
using test::write_text;

const std::string kGrammars = VERN_SOURCE_DIR "/data/grammars/";
const std::string kEveryOperation = VERN_SOURCE_DIR "/tests/data/every_operation.grm";

TEST(GenerateCli, HelpDescribesUsageAndExitCodes) {
  const auto r = run_program("generate", {"--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("usage: generate GRAMMAR.grm"), std::string::npos);
  EXPECT_NE(r.out.find("--threads"), std::string::npos);
  EXPECT_NE(r.out.find("exit codes"), std::string::npos);
}

TEST(GenerateCli, WritesOneFilePerVariantIntoAFolder) {
  TempFolder dir;
  const auto r = run_program("generate", {kGrammars + "garage.grm", "-n", "3", "--seed", "7", "-o", "out/"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(list_folder(dir / "out"), (std::vector<std::string>{"variant_000.mtl", "variant_000.obj", "variant_001.mtl",
                                                               "variant_001.obj", "variant_002.mtl", "variant_002.obj"}));
  const std::string obj = read_file(dir / "out/variant_000.obj");
  EXPECT_NE(obj.find("o rect\n"), std::string::npos);
  EXPECT_NE(obj.find("o roof\n"), std::string::npos);
  EXPECT_NE(r.err.find("3 buildings"), std::string::npos);
}

TEST(GenerateCli, VariantIUsesSeedSPlusI) {
  TempFolder dir;
  ASSERT_EQ(run_program("generate", {kGrammars + "better_roofs.grm", "-n", "4", "--seed", "7", "-o", "all/", "-q"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_program("generate", {kGrammars + "better_roofs.grm", "--seed", "10", "-o", "one/", "-q"}, dir.path()).exit_code, 0);
  // Same geometry; only the header naming the file and its .mtl differs.
  auto body = [](const std::string& obj) { return obj.substr(obj.find("\no ")); };
  EXPECT_EQ(body(read_file(dir / "all/variant_003.obj")), body(read_file(dir / "one/variant_000.obj")));
  EXPECT_NE(body(read_file(dir / "all/variant_002.obj")), body(read_file(dir / "one/variant_000.obj")));
}

TEST(GenerateCli, SameSeedSameBytesWithOneOrTwoThreads) {
  TempFolder dir;
  for (const std::string ext : {".obj", ".glb", ".gltf"}) {
    // Same file name in two folders: an OBJ names its .mtl, so names matter.
    for (const std::string threads : {"1", "2"}) {
      std::filesystem::create_directories(dir / ("j" + threads));
      const auto r = run_program("generate", {kGrammars + "skyscraper_city.grm", "-n", "3", "--seed", "5", "-j", threads,
                                              "-q", "-o", "city" + ext},
                                 dir / ("j" + threads));
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const std::string one = read_file(dir / ("j1/city" + ext));
    const std::string two = read_file(dir / ("j2/city" + ext));
    EXPECT_GT(one.size(), 100000u);
    // EXPECT_TRUE, not EXPECT_EQ: a diff of two megabyte strings is no help.
    EXPECT_TRUE(one == two) << ext << " differs between 1 and 2 threads";
  }
}

TEST(GenerateCli, OneFileLaysVariantsOutWithoutOverlap) {
  TempFolder dir;
  ASSERT_EQ(run_program("generate", {kGrammars + "garage.grm", "-n", "4", "--spacing", "2", "-o", "row.obj", "-q"}, dir.path()).exit_code, 0);
  const std::string obj = read_file(dir / "row.obj");
  for (const char* name : {"\ng variant_000\n", "\ng variant_003\n"}) EXPECT_NE(obj.find(name), std::string::npos) << name;
  // Four 12 x 8 plots on a 2 x 2 grid, 2 m apart: x reaches 12 + 2 + 12 = 26.
  EXPECT_NE(obj.find("\nv 26 "), std::string::npos);
  EXPECT_EQ(obj.find("\nv 27"), std::string::npos);
}

TEST(GenerateCli, ScopeAndStartOptions) {
  TempFolder dir;
  const auto r = run_program("generate", {kGrammars + "garage.grm", "--scope", "3", "2", "1", "--start", "house", "-o", "h.obj", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string obj = read_file(dir / "h.obj");
  EXPECT_EQ(obj.find("o roof"), obj.rfind("o roof"));  // one house, one roof
  // The ridge: 3 long, mid-depth, on top, written y-up as Blender reads
  // OBJ: the grammar's (3, 1, 1) is (3, 1, -1).
  EXPECT_TRUE(obj.starts_with("# Written by Vernacular: one object per terminal, named by its label.\n# up y\n"));
  EXPECT_NE(obj.find("\nv 3 1 -1\n"), std::string::npos);
  // --up z writes the grammar's frame as it is, and says so.
  const auto z = run_program("generate", {kGrammars + "garage.grm", "--scope", "3", "2", "1", "--start", "house", "--up", "z",
                                          "-o", "z.obj", "-q"}, dir.path());
  ASSERT_EQ(z.exit_code, 0) << z.err;
  const std::string z_obj = read_file(dir / "z.obj");
  EXPECT_NE(z_obj.find("\n# up z\n"), std::string::npos);
  EXPECT_NE(z_obj.find("\nv 3 1 1\n"), std::string::npos);
  // glTF is y-up by its specification: --up is for OBJ only.
  const auto glb = run_program("generate", {kGrammars + "garage.grm", "--up", "z", "-o", "h.glb", "-q"}, dir.path());
  EXPECT_EQ(glb.exit_code, 2);
  EXPECT_NE(glb.err.find("--up applies to OBJ output only"), std::string::npos) << glb.err;
  const auto x = run_program("generate", {kGrammars + "garage.grm", "--up", "x", "-o", "x.obj", "-q"}, dir.path());
  EXPECT_EQ(x.exit_code, 2) << x.err;
}

// EXT_mesh_gpu_instancing stays required (a fallback of plain nodes would
// be drawn twice where it is read): the help says who reads it, and that
// Blender 3.4 refuses it, before a user finds out in Blender.
TEST(GenerateCli, InstancingHelpSaysWhichViewersReadIt) {
  const auto r = run_program("generate", {"--help"});
  ASSERT_EQ(r.exit_code, 0);
  const std::string help = r.out.substr(r.out.find("--instancing"));
  for (const char* said : {"required", "three.js and Babylon.js read it", "Blender 3.4 refuses the file"})
    EXPECT_NE(help.find(said), std::string::npos) << said << "\n" << help;
}

TEST(GenerateCli, UsageErrorsExitWithTwo) {
  auto r = run_program("generate", {});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no grammar file given"), std::string::npos);
  r = run_program("generate", {kGrammars + "garage.grm", "--sede", "3"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown option '--sede'\n  hint: did you mean '--seed'?"), std::string::npos);
  r = run_program("generate", {kGrammars + "garage.grm", "-n"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--count needs 1 value"), std::string::npos);
  r = run_program("generate", {kGrammars + "garage.grm", "-n", "many"});
  EXPECT_EQ(r.exit_code, 2);
  r = run_program("generate", {kGrammars + "garage.grm", "--format", "stl"});
  EXPECT_EQ(r.exit_code, 2);
  r = run_program("generate", {kGrammars + "garage.grm", "-o", kGrammars + "garage.grm"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is the grammar file itself"), std::string::npos);
}

TEST(GenerateCli, BadGrammarExitsWithThreeAndWritesNothing) {
  TempFolder dir;
  write_text(dir / "bad.grm", "plot --> split(x){ ~1 : I(rect) | ~1 : hose }\nhouse --> I(rect)\n");
  write_text(dir / "keep.obj", "precious");
  const auto r = run_program("generate", {"bad.grm", "-o", "keep.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(r.err, "bad.grm:1:40: error: unknown rule 'hose'\n  hint: did you mean 'house'?\n");
  EXPECT_EQ(read_file(dir / "keep.obj"), "precious");
  EXPECT_EQ(list_folder(dir.path()), (std::vector<std::string>{"bad.grm", "keep.obj"}));
}

TEST(GenerateCli, LimitsExitWithFourAndNameTheFlag) {
  TempFolder dir;
  write_text(dir / "runaway.grm", "p --> q\nq --> split(x){ ~1 : I(rect) | ~1 : q }\n");
  auto r = run_program("generate", {"runaway.grm", "-o", "out.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("--max-depth"), std::string::npos);
  r = run_program("generate", {"runaway.grm", "--max-terminals", "10", "-o", "out.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("more than 10 terminals"), std::string::npos);
  EXPECT_EQ(list_folder(dir.path()), (std::vector<std::string>{"runaway.grm"}));
}

TEST(GenerateCli, UnwritableOutputExitsWithFiveAndLeavesNoTemporary) {
  TempFolder dir;
  write_text(dir / "file", "x");
  const auto r = run_program("generate", {kGrammars + "garage.grm", "-o", (dir / "file/sub.obj").string()});
  EXPECT_EQ(r.exit_code, 5);
  EXPECT_NE(r.err.find("file/sub.obj: error: cannot write here"), std::string::npos) << r.err;
  EXPECT_EQ(list_folder(dir.path()), (std::vector<std::string>{"file"}));
}

TEST(GenerateCli, UnknownPrimitiveWarnsOnceAndStrictFails) {
  TempFolder dir;
  write_text(dir / "g.grm", "p --> split(x){ ~1 : I(tower) | ~1 : I(tower) | ~1 : I(rect) }\n");
  auto r = run_program("generate", {"g.grm", "-o", "a.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("g.grm:1:22: warning: unknown primitive 'tower': inserting a box labelled 'tower'; the known primitives are: corner, door"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("warning"), r.err.rfind("warning"));
  EXPECT_NE(read_file(dir / "a.obj").find("o tower"), std::string::npos);
  r = run_program("generate", {"g.grm", "--strict", "-o", "b.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_FALSE(std::filesystem::exists(dir / "b.obj"));
}

TEST(GenerateCli, UserPrimitivesFromAFolderOrTheGrammar) {
  TempFolder dir;
  std::filesystem::create_directories(dir / "prims");
  // A tower: a tall triangle pyramid of 4 vertices, in any coordinates,
  // modelled z-up and saying so.
  write_text(dir / "prims/tower.obj",
             "# up z\nv 0 0 0\nv 4 0 0\nv 0 4 0\nv 0 0 8\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");
  write_text(dir / "g.grm", "p --> I(tower)\n");
  write_text(dir / "h.grm", "@primitives \"prims\"\np --> I(tower)\n");
  auto r = run_program("generate", {"g.grm", "--primitives", "prims", "--scope", "2", "2", "2", "-o", "a.obj"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const std::string a = read_file(dir / "a.obj");
  EXPECT_NE(a.find("\nv 0 2 0\n"), std::string::npos);  // normalised to the unit box, scaled to 2, written y-up
  r = run_program("generate", {"h.grm", "--scope", "2", "2", "2", "-o", "b.obj"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto body = [](const std::string& obj) { return obj.substr(obj.find("\no ")); };
  EXPECT_EQ(body(read_file(dir / "b.obj")), body(a));
}

}  // namespace
}  // namespace vern

namespace vern {
namespace {

// Seconds a command takes.
double timed(const std::function<void()>& run) {
  const auto started = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

// Names are found by hash, not by reading every name defined before them:
// 200 000 constants (each using the one before) took 95 s to read, 200 000
// primitive names a minute. Linear, both take well under a second (the
// bound leaves room for the sanitizers).
TEST(GenerateCli, ManyConstantsAndPrimitiveNamesReadInLinearTime) {
  TempFolder dir;
  constexpr int kNames = 200'000;
  std::string constants = "c0 = 1\n";
  for (int i = 1; i < kNames; ++i) constants += "c" + std::to_string(i) + " = c" + std::to_string(i - 1) + "\n";
  constants += "p --> split(x){ ~c" + std::to_string(kNames - 1) + " : I(rect) | ~1 : I(window) }\n";
  write_text(dir / "constants.grm", constants);
  std::string primitives = "p --> split(x){ ~1 : I(a0)";
  for (int i = 1; i < kNames; ++i) primitives += " | ~1 : I(a" + std::to_string(i) + ")";
  primitives += " }\n";
  write_text(dir / "primitives.grm", primitives);

  for (const std::string grammar : {"constants.grm", "primitives.grm"}) {
    test::CommandResult r;
    const double seconds = timed([&] { r = run_program("generate", {grammar, "-q", "-o", "out.glb"}, dir.path()); });
    EXPECT_EQ(r.exit_code, 0) << grammar << "\n" << r.err.substr(0, 2000);
    EXPECT_LT(seconds, 30.0) << grammar;
  }
}

}  // namespace
}  // namespace vern

namespace vern {
namespace {

std::vector<std::string> vertex_lines(const std::string& obj) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while (at < obj.size()) {
    const std::size_t end = obj.find('\n', at);
    const std::string line = obj.substr(at, end == std::string::npos ? std::string::npos : end - at);
    if (line.starts_with("v ")) out.push_back(line);
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return out;
}

TEST(GenerateCli, ShardsWriteTogetherWhatTheOneRunWrites) {
  TempFolder dir;
  const std::string grammar = VERN_SOURCE_DIR "/data/grammars/skyscraper_city.grm";
  for (const std::string format : {"obj", "glb"}) {
    const std::string all = "all_" + format + "/", parts = "parts_" + format + "/";
    ASSERT_EQ(run_program("generate", {grammar, "-n", "7", "--seed", "3", "--format", format, "-q", "-o", all}, dir.path())
                  .exit_code,
              0);
    for (const std::string shard : {"1/3", "2/3", "3/3"}) {
      const auto r = run_program("generate", {grammar, "-n", "7", "--seed", "3", "--format", format, "--shard", shard,
                                              "-q", "-o", parts},
                                 dir.path());
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const std::vector<std::string> files = list_folder(dir / all);
    ASSERT_EQ(list_folder(dir / parts), files);
    for (const std::string& f : files) EXPECT_EQ(read_file(dir / parts / f), read_file(dir / all / f)) << f;
  }
  // One file: each shard's buildings stand where they stand in the run's.
  ASSERT_EQ(run_program("generate", {grammar, "-n", "5", "-q", "-o", "city.obj"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_program("generate", {grammar, "-n", "5", "--shard", "1/2", "-q", "-o", "a.obj"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_program("generate", {grammar, "-n", "5", "--shard", "2/2", "-q", "-o", "b.obj"}, dir.path()).exit_code, 0);
  std::vector<std::string> joined = vertex_lines(read_file(dir / "a.obj"));
  const std::vector<std::string> b = vertex_lines(read_file(dir / "b.obj"));
  EXPECT_FALSE(b.empty());
  joined.insert(joined.end(), b.begin(), b.end());
  EXPECT_EQ(joined, vertex_lines(read_file(dir / "city.obj")));
}

TEST(GenerateCli, AShardThatIsNoneOfTheRunsIsAUsageError) {
  TempFolder dir;
  const std::string grammar = VERN_SOURCE_DIR "/data/grammars/garage.grm";
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"--shard", "4/3"}, {"--shard", "0/3"}, {"--shard", "three"}, {"-n", "2", "--shard", "2/5"}}) {
    std::vector<std::string> all = {grammar, "-o", "out/"};
    all.insert(all.end(), args.begin(), args.end());
    const auto r = run_program("generate", all, dir.path());
    EXPECT_EQ(r.exit_code, 2) << args.back();
    EXPECT_NE(r.err.find("--shard"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("hint:"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  }
}

}  // namespace
}  // namespace vern
