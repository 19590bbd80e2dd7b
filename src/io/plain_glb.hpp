// Reading the common GLB file without tinygltf's JSON document.
//
// tinygltf parses a GLB's JSON into an nlohmann::json document and then
// into its model: for the city's examples (20,000 nodes, each with a
// matrix) that was a quarter of infer's instructions. Most files, and all
// that `generate` writes, use a small part of glTF: nodes with names,
// meshes, matrices or T/R/S and children; meshes of primitives; accessors,
// buffer views and one binary chunk; materials (ignored). read_plain_glb
// reads exactly those, straight into the fields of tinygltf::Model that
// inference reads, and declines anything else: an extension, an unknown
// key, a duplicate key, a string escape, a value tinygltf would refuse.
// A declined file goes to tinygltf as before, so every file is read as
// tinygltf reads it and every error is tinygltf's (a differential test and
// the glTF fuzz target hold the two readers to that).
#pragma once

#include <optional>
#include <span>
#include <string>

#include <tiny_gltf.h>

namespace vern {

// The model, or nothing when the file is not a plain GLB. Only the fields
// load_gltf_example reads are filled (read_fields_difference lists them).
std::optional<tinygltf::Model> read_plain_glb(std::span<const unsigned char> bytes);

// For tests and fuzzing: "" when read_plain_glb declines the file or reads
// what tinygltf reads in every field inference uses (numbers bit for bit),
// else what differs ("node 3 matrix", or tinygltf's refusal).
std::string plain_glb_disagreement(std::span<const unsigned char> bytes);

}  // namespace vern
