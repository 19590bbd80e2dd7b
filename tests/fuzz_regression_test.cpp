// Every input a fuzzer ever turned into a finding (fuzz/regressions/<target>/)
// and the seed corpus (fuzz/corpus/<target>/) run through the same entry
// functions as the libFuzzer programs, so the ordinary test suite keeps them
// fixed forever, with any compiler. Plus the harness's own judgement: what
// counts as a finding and what does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "entries/entries.hpp"
#include "entries/folder_opens.hpp"
#include "entries/folder_tree.hpp"
#include "entries/layout.hpp"
#include "entries/scratch_file.hpp"
#include "entries/verdict.hpp"

namespace fs = std::filesystem;
using namespace vern;

namespace vern::fuzz {
// Test names and messages show the target's name, not its bytes.
void PrintTo(const Target& target, std::ostream* os) { *os << target.name; }
}  // namespace vern::fuzz

namespace {

std::vector<std::uint8_t> file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::uint8_t> bytes_of(std::string_view text) { return {text.begin(), text.end()}; }

// The inputs in fuzz/<kind>/<target>/, sorted (READMEs are notes, not inputs).
std::vector<fs::path> inputs(const std::string& kind, std::string_view target) {
  const fs::path folder = fs::path(VERN_SOURCE_DIR) / "fuzz" / kind / target;
  std::vector<fs::path> files;
  if (!fs::is_directory(folder)) return files;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.is_regular_file() && !e.path().filename().string().starts_with("README")) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

class FuzzTarget : public ::testing::TestWithParam<fuzz::Target> {};

TEST_P(FuzzTarget, SavedFindingsStayFixed) {
  for (const fs::path& file : inputs("regressions", GetParam().name)) {
    const std::vector<std::uint8_t> data = file_bytes(file);
    EXPECT_EQ(GetParam().run(data), "") << file;
  }
}

TEST_P(FuzzTarget, SeedCorpusRunsClean) {
  const std::vector<fs::path> files = inputs("corpus", GetParam().name);
  EXPECT_GE(files.size(), 5u) << "the seed corpus of " << GetParam().name << " is missing";
  for (const fs::path& file : files) {
    const std::vector<std::uint8_t> data = file_bytes(file);
    EXPECT_EQ(GetParam().run(data), "") << file;
  }
}

INSTANTIATE_TEST_SUITE_P(Fuzz, FuzzTarget, ::testing::ValuesIn(fuzz::targets().begin(), fuzz::targets().end()),
                         [](const ::testing::TestParamInfo<fuzz::Target>& target) { return std::string(target.param.name); });

TEST(FuzzVerdict, ExpectedErrorsThatSayWhereAreNotFindings) {
  const auto input_error = [] { fail(ErrorKind::Input, "a.grm", {3, 4}, "bad"); return std::string(); };
  EXPECT_EQ(fuzz::judged(input_error, {ErrorKind::Input}, "a.grm"), "");
  // The same error without the file name, or of a kind not expected, is one.
  EXPECT_NE(fuzz::judged(input_error, {ErrorKind::Input}, "b.grm"), "");
  EXPECT_NE(fuzz::judged(input_error, {ErrorKind::Limit}, "a.grm"), "");
  const auto internal = [] { fail(ErrorKind::Internal, "a.grm", {}, "broken"); return std::string(); };
  EXPECT_NE(fuzz::judged(internal, {ErrorKind::Input}, "a.grm").find("Internal"), std::string::npos);
  const auto other = []() -> std::string { throw std::out_of_range("vector"); };
  EXPECT_NE(fuzz::judged(other, {ErrorKind::Input}, "a.grm").find("vector"), std::string::npos);
  EXPECT_EQ(fuzz::judged([] { return std::string("oracle failed"); }, {ErrorKind::Input}, ""), "oracle failed");
}

TEST(FuzzEntries, AcceptGoodInputAndRefuseBadInputWithoutAFinding) {
  EXPECT_EQ(fuzz::grammar_reader(bytes_of("p --> split(x){ ~1 : I(a) | 2 : nil }")), "");
  EXPECT_EQ(fuzz::grammar_reader(bytes_of("p --> split(x){ ~1 : I(a) |")), "");  // a syntax error
  EXPECT_EQ(fuzz::grammar_reader(bytes_of("p --> p")), "");                       // the depth limit
  EXPECT_EQ(fuzz::obj_loader(bytes_of("o wall\nv 0 0 0\nv 1 0 0\nv 0 1 1\nf 1 2 3\n")), "");
  EXPECT_EQ(fuzz::obj_loader(bytes_of("v 0 0 0\nf 1 2 7\n")), "");  // an index out of range
  EXPECT_EQ(fuzz::gltf_loader(bytes_of("{\"asset\": {\"version\": \"2.0\"}}")), "");  // no parts
  EXPECT_EQ(fuzz::gltf_loader(bytes_of("glTF\x02")), "");                            // a truncated GLB
}

TEST(FuzzLayout, BytesDescribeACutBoxAndInferenceDerivesIt) {
  // One example, unit 1; a tree: a 4 x 1 x 2 box split along x (byte 0x1A:
  // split, axis x, 3 parts) into weights 1, 2, 1: part a, empty, part b.
  const std::vector<std::uint8_t> bytes{0x00, 0x01, 3, 0, 1, 0x1A, 0, 1, 0, 0x00, 0x01, 0x04};
  const fuzz::Layout layout = fuzz::decode_layout(bytes);
  ASSERT_EQ(layout.examples.size(), 1u);
  EXPECT_TRUE(layout.valid_by_construction);
  const auto& boxes = layout.examples[0].boxes;
  ASSERT_EQ(boxes.size(), 2u);
  EXPECT_EQ(boxes[0].label, "a");
  EXPECT_EQ(boxes[0].max, glm::dvec3(1, 1, 2));
  EXPECT_EQ(boxes[1].label, "b");
  EXPECT_EQ(boxes[1].min, glm::dvec3(3, 0, 0));
  EXPECT_EQ(fuzz::infer_layout(bytes), "");
  // Free boxes that overlap: inference refuses them, which is no finding.
  const std::vector<std::uint8_t> overlap{0x00, 0x02, 0, 0, 0, 0, 4, 4, 4, 1, 1, 1, 1, 4, 4, 4};
  EXPECT_FALSE(fuzz::decode_layout(overlap).valid_by_construction);
  EXPECT_EQ(fuzz::infer_layout(overlap), "");
}

TEST(FuzzLayout, APeeledLayoutIsACutTreeDeeperThanTheReaderNests) {
  // Bits 0, 6 and 7 of the example byte: 257 slabs peeled along x, y, z
  // in turn, then the core. Its grammar must read back and derive it.
  std::vector<std::uint8_t> bytes{0x00, 0xC1, 0};
  for (int i = 0; i < 257; ++i) bytes.push_back(static_cast<std::uint8_t>(i % 3));
  bytes.push_back(0);
  const fuzz::Layout layout = fuzz::decode_layout(bytes);
  ASSERT_EQ(layout.examples.size(), 1u);
  EXPECT_TRUE(layout.valid_by_construction);
  const auto& boxes = layout.examples[0].boxes;
  ASSERT_EQ(boxes.size(), 258u);
  EXPECT_EQ(boxes[0].max, glm::dvec3(1, 258, 258));
  EXPECT_EQ(boxes[1].min, glm::dvec3(1, 0, 0));
  EXPECT_EQ(boxes[1].max, glm::dvec3(258, 1, 258));
  EXPECT_EQ(fuzz::infer_layout(bytes), "");
}

TEST(FuzzFolderTree, TextDescribesAMainFileAndWhatItNames) {
  const std::string text =
      "grammar outside\n@@ main\n@primitives \"p%20q\"\n@@ file sub/a%20b.obj\no a\n\n@@ repeat ../r.bin 5\nxy"
      "\n@@ link l $ROOT/r.bin\n@@ dir d\n@@ bogus x\n@@ main\nignored";
  const fuzz::FolderTree tree = fuzz::decode_folder_tree(bytes_of(text));
  EXPECT_TRUE(tree.grammar);
  EXPECT_TRUE(tree.outside_files);
  EXPECT_EQ(tree.main, "@primitives \"p%20q\"");  // only names are decoded
  ASSERT_EQ(tree.entries.size(), 4u);
  EXPECT_EQ(tree.entries[0].name, "sub/a b.obj");
  EXPECT_EQ(tree.entries[0].bytes, "o a\n");
  EXPECT_EQ(tree.entries[1].bytes, "xyxyx");
  EXPECT_EQ(tree.entries[2].kind, fuzz::FolderTree::Entry::Kind::Link);
  EXPECT_EQ(tree.entries[2].bytes, "$ROOT/r.bin");
  EXPECT_EQ(tree.entries[3].kind, fuzz::FolderTree::Entry::Kind::Folder);

  // Placed: the main file in in/, "../" in the root, the link as written;
  // nothing leads out of the root, nor through a link.
  const fs::path root = fuzz::scratch_folder("folder-tree-test");
  const std::string more = text + "\n@@ file ../../escape.bin\n@@ file l/through.bin\n@@ link m ../../x";
  const fuzz::PlacedTree placed = fuzz::place_folder_tree(fuzz::decode_folder_tree(bytes_of(more)), root);
  EXPECT_EQ(placed.main, root / "in" / "main.grm");
  EXPECT_TRUE(fs::is_regular_file(root / "in" / "sub" / "a b.obj"));
  EXPECT_EQ(fs::file_size(root / "r.bin"), 5u);
  EXPECT_EQ(fs::read_symlink(root / "in" / "l"), root / "r.bin");
  EXPECT_TRUE(fs::is_directory(root / "in" / "d"));
  EXPECT_FALSE(fs::exists(root.parent_path() / "escape.bin"));
  EXPECT_FALSE(fs::exists(root / "in" / "l" / "through.bin"));
  EXPECT_FALSE(fs::exists(fs::symlink_status(root / "in" / "m")));
  EXPECT_EQ(placed.outside_folders, std::vector<fs::path>{root});
}

TEST(FuzzFolderTree, OpensOutsideTheMainFilesFolderAreSeen) {
  const fs::path root = fuzz::scratch_folder("folder-opens-test");
  std::ofstream(root / "secret.bin") << "x";
  fuzz::FolderOpens opens;
  opens.watch({root});
  EXPECT_TRUE(opens.opened().empty());
  std::ifstream(root / "secret.bin").get();
  EXPECT_EQ(opens.opened(), std::vector<std::string>{(root / "secret.bin").string()});
  EXPECT_TRUE(opens.opened().empty());
}

TEST(FuzzFolderTree, AFileALinkLeadsOutToIsRefusedWithoutAFinding) {
  // The URI names a link in the glTF's folder that leads to a file above it.
  const std::string gltf =
      "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4,\"uri\":\"b.bin\"}]}";
  EXPECT_EQ(fuzz::indirect_inputs(bytes_of("\n@@ main\n" + gltf + "\n@@ file ../s.bin\nabcd\n@@ link b.bin ../s.bin")), "");
  EXPECT_EQ(fuzz::indirect_inputs(bytes_of("outside\n@@ main\n" + gltf + "\n@@ file ../s.bin\nabcd\n@@ link b.bin ../s.bin")), "");
}

}  // namespace
