// A grammar's round trip on a page (evaluate --report): buildings the
// source grammar derives (the examples inference learnt from) beside
// buildings of the grammar it learnt, the figures evaluate measured and
// the learnt grammar.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "forward/primitive_library.hpp"
#include "graph/grammar.hpp"
#include "report/html_report.hpp"
#include "report/raster.hpp"

namespace vern {

struct RoundTripInput {
  std::string name;  // the source grammar's name
  const Grammar* source = nullptr;
  const Grammar* learnt = nullptr;
  const PrimitiveLibrary* primitives = nullptr;  // the source's meshes, which the learnt grammar's labels name too
  std::string learnt_text;                       // the learnt grammar as infer writes it
  std::vector<std::pair<std::string, std::string>> figures;
  std::vector<std::string> notes;
  std::uint64_t example_seed = 1;     // evaluate's examples: seeds 1 to k
  std::uint64_t variant_seed = 1001;  // and its variants, of both grammars
  std::uint32_t shown = 6;            // pictures of each
  unsigned threads = 1;
  RasterView view;
};

// Throws vern::Error as derive() does, but for a building that stops at a
// limit: that one is left out and said in a note.
ReportSection round_trip_section(const RoundTripInput& input);

}  // namespace vern
