// The fuzz targets' entry points, shared by the libFuzzer programs in fuzz/
// and by tests/fuzz_regression_test.cpp, so that every input a fuzzer ever
// found keeps being run by the ordinary test suite, with or without clang.
//
// Each entry feeds one input through a part of the toolkit and judges the
// outcome. An input may be accepted or rejected with the vern::Error the
// contract promises for bad input (kind Input, with a message that names
// where); that is not a finding. A finding is anything else: an exception of
// another kind or type, a broken invariant of the result, or a failed
// oracle (a written grammar that parses to a different graph, an inferred
// grammar that does not derive its example). Crashes and sanitizer reports
// are findings too, but those the process reports by itself.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace vern::fuzz {

using Bytes = std::span<const std::uint8_t>;

// Returns "" when the input was handled as the contract says, else a
// description of the finding.
using Entry = std::string (*)(Bytes input);

// Grammar text: parse; when it parses, write it, parse that again and
// compare graphs and derivations; derive with small limits.
std::string grammar_reader(Bytes input);

// OBJ text: read it as the example loader does and check the meshes'
// invariants; when it has objects, load it as an example.
std::string obj_loader(Bytes input);

// glTF JSON or GLB bytes (by the "glTF" magic): load as an example and
// check its invariants; a GLB the plain reader takes must read as
// tinygltf reads it.
std::string gltf_loader(Bytes input);

// A small layout of labelled boxes (see layout.hpp): infer a grammar from
// it and check that the grammar derives every example.
std::string infer_layout(Bytes input);

// A small folder tree (see folder_tree.hpp): a glTF example whose URIs, or
// a grammar whose @primitives, name files in it, beside it, above it or
// through links, with --allow-outside-files off or on. Load it as infer
// and generate do; nothing outside the main file's folder may be opened
// unless allowed, and nothing written.
std::string indirect_inputs(Bytes input);

// A request body for serve's /api/derive (serve/derive_request.hpp): the
// answer is JSON, 200 with buildings or a located error of the grammar's
// own, or 400 saying why; nothing thrown.
std::string editor_request(Bytes input);

struct Target {
  std::string_view name;  // also the folder name under fuzz/corpus and fuzz/regressions
  Entry run;
};

// All targets, in a fixed order.
std::span<const Target> targets();

}  // namespace vern::fuzz
