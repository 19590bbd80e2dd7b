// Vernacular's public API: example buildings into a grammar of their
// style, and the grammar into new buildings. Everything here is in
// namespace vernacular; errors are thrown as vernacular::Failure.
//
//   auto examples = vernacular::read_examples({"examples/"});
//   auto style = vernacular::infer(examples);
//   style.save("style.grm");
//   auto houses = vernacular::derive_many(style.grammar, 10);
//   vernacular::write_buildings(houses, style.grammar, "houses.glb");
#pragma once

#include "vernacular/check.hpp"
#include "vernacular/derive.hpp"
#include "vernacular/error.hpp"
#include "vernacular/grammar.hpp"
#include "vernacular/infer.hpp"
#include "vernacular/io.hpp"

namespace vernacular {

// The library's version, "MAJOR.MINOR.PATCH" (the commands' --version).
const char* version();

}  // namespace vernacular
