// The plain GLB reader against tinygltf: whatever it reads, it reads as
// tinygltf does, and what it declines is left to tinygltf.
#include "io/plain_glb.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "io/gltf_container.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = VERN_SOURCE_DIR;

std::vector<unsigned char> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

std::uint32_t word(const std::string& glb, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, glb.data() + at, 4);
  return v;
}

// A GLB's JSON text and binary chunk, and a GLB made of them again.
struct Glb {
  std::string json, bin;

  static Glb of(const std::string& glb) {
    const std::uint32_t json_length = word(glb, 12);
    const std::size_t json_end = kGlbJsonOffset + json_length;
    Glb out{glb.substr(kGlbJsonOffset, json_length), ""};
    if (json_end < glb.size()) out.bin = glb.substr(json_end + 8, word(glb, json_end));
    return out;
  }

  // As the writer lays a GLB out (gltf_container.hpp).
  std::string bytes() const {
    return glb_header(json.size(), bin.size()) + json + glb_between(json.size(), bin.size()) + bin;
  }

  // The JSON with its first `from` replaced by `to`; fails the test when
  // there is no `from`.
  Glb with(const std::string& from, const std::string& to) const {
    Glb out = *this;
    const std::size_t at = out.json.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) out.json.replace(at, from.size(), to);
    return out;
  }
};

bool plain(const std::string& glb) { return read_plain_glb(bytes_of(glb)).has_value(); }
std::string disagreement(const std::string& glb) { return plain_glb_disagreement(bytes_of(glb)); }

// The test corpus's GLB of two parts, as `generate` writes it.
const std::string& two_parts() {
  static const std::string glb = test::read_file(kSource / "fuzz/corpus/gltf_loader/two_parts.glb");
  return glb;
}

TEST(PlainGlb, BundledExamplesAndGeneratedFilesAreReadAsTinygltfReadsThem) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(kSource / "data/examples/skyscraper_city")) files.push_back(e.path());
  for (const auto& e : fs::directory_iterator(kSource / "fuzz/corpus/gltf_loader"))
    if (e.path().extension() == ".glb") files.push_back(e.path());
  ASSERT_GE(files.size(), 14u);
  for (const fs::path& file : files) {
    const std::string glb = test::read_file(file);
    // All are plain: what `generate` writes and the corpus's hand-made
    // strips, fans and matrices.
    EXPECT_TRUE(plain(glb)) << file;
    EXPECT_EQ(disagreement(glb), "") << file;
  }
}

TEST(PlainGlb, WhatJsonAllowsBeyondWhatWritersWriteReadsTheSame) {
  const Glb base = Glb::of(two_parts());
  const std::string node = R"({"name":"rect","mesh":0,"matrix":[)";
  ASSERT_NE(base.json.find(node), std::string::npos);
  const std::vector<Glb> cases = {
      // Numbers in every form JSON has, and ones only a double holds.
      base.with(node, node + "-0,1e2,1E-2,0.5e+1,-12.25,123456789012345678901234,-9223372036854775809,"),
      // White space anywhere, keys in another order.
      base.with(R"({"asset":{"generator":"Vernacular","version":"2.0"},)",
                "\n{ \"asset\" : {\t\"version\":\"2.0\" , \"generator\" : \"Vernacular\" } ,\r\n"),
  };
  for (const Glb& c : cases) {
    EXPECT_TRUE(plain(c.bytes())) << c.json.substr(0, 300);
    EXPECT_EQ(disagreement(c.bytes()), "");
  }
  // T/R/S proper: the matrix key and its numbers replaced.
  std::string json = base.json;
  const std::size_t at = json.find(node);
  const std::size_t end = json.find(']', at);
  json.replace(at, end + 1 - at,
               R"({"name":"rect","mesh":0,"translation":[1,2,3],)"
               R"("rotation":[0,0,0.7071068,0.7071068],"scale":[2,2,2])");
  const Glb trs{json, base.bin};
  EXPECT_TRUE(plain(trs.bytes()));
  EXPECT_EQ(disagreement(trs.bytes()), "");
  // "-0" is the integer 0 to JSON libraries, so +0.0, not -0.0.
  const auto model = read_plain_glb(bytes_of(cases[0].bytes()));
  ASSERT_TRUE(model);
  const double first = model->nodes[1].matrix.at(0);
  EXPECT_EQ(first, 0.0);
  EXPECT_FALSE(std::signbit(first));
}

TEST(PlainGlb, EverythingElseIsLeftToTinygltf) {
  const Glb base = Glb::of(two_parts());
  ASSERT_TRUE(plain(base.bytes()));
  const std::vector<std::pair<std::string, std::string>> edits = {
      {R"("name":"rect","mesh")", R"("name":"r\u0065ct","mesh")"},             // an escape
      {R"("name":"rect","mesh")", "\"name\":\"r\xC3\xA9" "ct\",\"mesh\""},      // beyond ASCII
      {R"("name":"rect","mesh")", R"("name":"rect","name":"rect","mesh")"},   // a duplicate key
      {R"("name":"rect","mesh")", R"("name":"rect","extras":{},"mesh")"},     // a key outside the form
      {R"("name":"rect","mesh")", R"("name":"rect","extensions":{"EXT_mesh_gpu_instancing":{}},"mesh")"},
      {R"("name":"rect","mesh":0)", R"("name":"rect","mesh":-1)"},            // a negative index
      {R"("name":"rect","mesh":0)", R"("name":"rect","mesh":0.0)"},           // an index written as a fraction
      {R"("name":"rect","mesh":0,"matrix":[)", R"("name":"rect","mesh":0,"translation":[0,0,0],"matrix":[)"},
      {R"("name":"rect","mesh":0,"matrix":[)", R"("name":"rect","mesh":0,"matrix":[1e400,)"},  // no double holds it
      {R"("name":"rect","mesh":0,"matrix":[)", R"("name":"rect","mesh":0,"matrix":[01,)"},     // not JSON
      {R"("version":"2.0")", R"("versions":"2.0")"},                         // no asset version
      {R"("componentType":5126,)", ""},                                       // a required key missing
      {R"("componentType":5126,)", R"("componentType":5000,)"},               // a type tinygltf refuses
      {R"("byteLength")", R"("uri":"two_parts.bin","byteLength")"},           // a buffer in another file
      {R"("buffers":[{"byteLength":1464}])", R"("buffers":[{"byteLength":0}])"},  // tinygltf throws on it
      {R"("scene":0,)", R"("scene":0,"animations":[],)"},                     // a part of glTF beyond the form
      {R"("scene":0,)", R"("scene":0,,)"},                                    // not JSON
  };
  for (const auto& [from, to] : edits) {
    const Glb edited = base.with(from, to);
    EXPECT_FALSE(plain(edited.bytes())) << to;
  }
  // The container: a short length, another version, bytes after the JSON
  // (glb_chunks.hpp checks it first).
  std::string glb = base.bytes();
  EXPECT_FALSE(plain(glb.substr(0, glb.size() - 4)));
  EXPECT_FALSE(plain(glb.substr(0, 4) + std::string("\1\0\0\0", 4) + glb.substr(8)));
  EXPECT_FALSE(plain(glb + std::string(4, '\0')));
  Glb trailing = base;
  trailing.json += "x";
  EXPECT_FALSE(plain(trailing.bytes()));
}

// Random edits of a small file: whenever the plain reader reads the
// result, tinygltf reads it too, the same. Half the edits change a digit
// (most results stay JSON, with other numbers, indices and lengths); the
// others put JSON's punctuation, digits or letters anywhere.
TEST(PlainGlb, RandomEditsAreReadAsTinygltfReadsThemOrLeftToIt) {
  const Glb base = Glb::of(test::read_file(kSource / "fuzz/corpus/gltf_loader/strip_fan_matrix.glb"));
  const std::string digits = "0123456789", alphabet = "0123456789-+.eE,:[]{}\" \\aAzu";
  std::mt19937 rng(20261203);
  std::size_t read = 0, declined = 0;
  for (int i = 0; i < 10000; ++i) {
    Glb edited = base;
    const int edits = 1 + static_cast<int>(rng() % 2);
    for (int e = 0; e < edits; ++e) {
      std::string& json = edited.json;
      const std::size_t at = rng() % json.size();
      if (rng() % 2 == 0) {
        const std::size_t digit = json.find_first_of(digits, at);
        if (digit != std::string::npos) json[digit] = digits[rng() % digits.size()];
        continue;
      }
      const char c = alphabet[rng() % alphabet.size()];
      switch (rng() % 3) {
        case 0: json[at] = c; break;
        case 1: json.insert(at, 1, c); break;
        default: json.erase(at, 1); break;
      }
    }
    const std::string glb = edited.bytes();
    (plain(glb) ? read : declined) += 1;
    ASSERT_EQ(disagreement(glb), "") << edited.json;
  }
  // Both paths were taken often (else the test shows nothing).
  EXPECT_GE(read, 2000u) << declined;
  EXPECT_GE(declined, 2000u) << read;
}

}  // namespace
}  // namespace vern
