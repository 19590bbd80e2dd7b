// The report of one inferred style (infer --report): its examples as read
// beside new buildings of the grammar inferred from them, the grammar
// itself and its figures, in one HTML file (report/html_report.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "forward/primitive_library.hpp"
#include "graph/grammar.hpp"
#include "inverse/load/example.hpp"
#include "inverse/load/layered_parts.hpp"
#include "report/html_report.hpp"
#include "report/raster.hpp"

namespace vern {

struct StyleReportInput {
  std::string title;         // the grammar's file name
  std::string grammar_text;  // as written, header and all
  const Grammar* grammar = nullptr;
  const PrimitiveLibrary* primitives = nullptr;  // the meshes the grammar's labels insert
  const std::vector<Example>* examples = nullptr;
  // How overlapping parts are painted (infer's --stack, and --tolerance or
  // 0 for each example's own): each example is drawn as inference reads
  // it, a window set into its wall seen in it.
  Layering layering;
  std::vector<std::pair<std::string, std::string>> figures;
  std::vector<std::string> notes;  // infer's warnings
  std::uint64_t first_seed = 1;    // new building i is derived with seed first_seed + i
  std::uint32_t new_buildings = 8;
  std::size_t max_examples = 12;  // pictures of the first examples only, past it (the count is said)
  unsigned threads = 1;           // pictures drawn on this many threads (same bytes)
  RasterView view;
};

// Throws vern::Error as derive() does, but for a new building that stops
// at a limit: that one is left out and said in a note.
Report style_report(const StyleReportInput& input);

// Where pictures of these examples are seen from when every one is thin
// along x or along y (facades): straight in front of its broad side, an
// elevation. None for buildings, seen from their front corner.
std::optional<glm::dvec3> elevation_eye(const std::vector<Example>& examples);

// "house.obj (building 2 of 3)" for "examples/house.obj (building 2 of 3)":
// an example's name without its folders.
std::string example_caption(const std::string& source);

}  // namespace vern
