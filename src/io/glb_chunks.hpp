// The chunks of a GLB file, laid out as glTF 2.0's binary container says.
//
// tinygltf reads GLB files of any container version, a header whose length
// is shorter than the file, and a JSON chunk whose end is not aligned: each
// is a file the specification calls invalid, read as if it were not. The
// loader checks the container here first, so that every reader after it
// (plain_glb.hpp, tinygltf) sees a sound one: the magic "glTF", version 2,
// a length that is the file's, a first chunk of JSON, a second of BIN or
// none, each chunk 4-byte aligned and inside the file, chunks of unknown
// types after those two skipped (the specification asks readers to ignore
// them), and no second JSON or BIN chunk.
#pragma once

#include <span>
#include <string>

namespace vern {

struct GlbChunks {
  std::span<const unsigned char> json;  // the JSON chunk's text, with its padding
  std::span<const unsigned char> bin;   // the BIN chunk's bytes; empty when there is none
  bool has_bin = false;
  // "" when the container is sound; else what is wrong with it, said after
  // "is not a valid GLB file: " ("its header says version 1; ...").
  std::string problem;
};

GlbChunks glb_chunks(std::span<const unsigned char> bytes);

}  // namespace vern
