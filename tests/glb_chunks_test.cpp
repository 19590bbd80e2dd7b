#include "io/glb_chunks.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "io/gltf_container.hpp"

namespace vern {
namespace {

std::string u32(std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); }

std::string chunk(const std::string& type, const std::string& data) {
  return u32(static_cast<std::uint32_t>(data.size())) + type + data;
}

// A GLB of these chunks, its header's length its own.
std::string glb(const std::string& chunks, std::uint32_t version = 2) {
  return "glTF" + u32(version) + u32(static_cast<std::uint32_t>(12 + chunks.size())) + chunks;
}

const std::string kJson = chunk("JSON", "{}  "), kBin = chunk(std::string("BIN\0", 4), std::string(8, '\1'));

GlbChunks chunks_of(const std::string& bytes) {
  return glb_chunks({reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()});
}

std::string problem(const std::string& bytes) { return chunks_of(bytes).problem; }

TEST(GlbChunks, TheJsonAndBinChunksOfASoundFile) {
  // The chunks are views into the bytes, which must outlive them.
  const std::string both = glb(kJson + kBin), json_only = glb(kJson);
  GlbChunks c = chunks_of(both);
  EXPECT_EQ(c.problem, "");
  EXPECT_EQ(std::string(c.json.begin(), c.json.end()), "{}  ");
  EXPECT_EQ(c.bin.size(), 8u);
  EXPECT_TRUE(c.has_bin);
  c = chunks_of(json_only);
  EXPECT_EQ(c.problem, "");
  EXPECT_FALSE(c.has_bin);
  // Chunks of other types after those two are for extensions: skipped.
  EXPECT_EQ(problem(glb(kJson + kBin + chunk("XTRA", "abcd"))), "");
  // What the writer writes is sound.
  const std::string json = "{\"asset\":{\"version\":\"2.0\"}}";
  const std::string bin(12, '\0');
  EXPECT_EQ(problem(glb_header(json.size(), bin.size()) + json + glb_between(json.size(), bin.size()) + bin), "");
}

TEST(GlbChunks, TheHeaderIsVersion2AndTellsTheFilesLength) {
  EXPECT_EQ(problem(""), "it ends inside the 12-byte GLB header");
  EXPECT_EQ(problem("glTF" + u32(2)), "it ends inside the 12-byte GLB header");
  EXPECT_EQ(problem("glTX" + glb(kJson).substr(4)), "it does not start with the magic 'glTF'");
  EXPECT_EQ(problem(glb(kJson, 1)), "its header says container version 1; only version 2 (glTF 2.0) is read");
  EXPECT_EQ(problem(glb(kJson, 3)), "its header says container version 3; only version 2 (glTF 2.0) is read");
  const std::string sound = glb(kJson + kBin);
  EXPECT_EQ(problem(sound + "    "), "the length its header gives is not the file's length");
  EXPECT_EQ(problem(sound.substr(0, sound.size() - 4)), "the length its header gives is not the file's length");
}

TEST(GlbChunks, ChunksAreAlignedInsideTheFileAndInOrder) {
  EXPECT_EQ(problem(glb("")), "it has no JSON chunk");
  EXPECT_EQ(problem(glb(u32(4))), "chunk 0 ends inside its 8-byte header");
  EXPECT_EQ(problem(glb(u32(400) + "JSON" + "{}  ")), "chunk 0 runs past the end of the file");
  EXPECT_EQ(problem(glb(chunk("JSON", "{} "))), "chunk 0's length is not a multiple of 4: chunks are 4-byte aligned");
  EXPECT_EQ(problem(glb(chunk("JSON", ""))), "its JSON chunk is empty");
  EXPECT_EQ(problem(glb(kBin + kJson)), "its first chunk is not the JSON chunk");
  EXPECT_EQ(problem(glb(kJson + kJson)), "it has a second JSON chunk (chunk 1)");
  EXPECT_EQ(problem(glb(kJson + chunk("XTRA", "abcd") + kBin)),
            "its BIN chunk is chunk 2, not chunk 1 right after the JSON chunk");
  EXPECT_EQ(problem(glb(kJson + kBin + kBin)), "its BIN chunk is chunk 2, not chunk 1 right after the JSON chunk");
  EXPECT_EQ(problem(glb(kJson + kBin + "ab")), "chunk 2 ends inside its 8-byte header");
}

}  // namespace
}  // namespace vern
