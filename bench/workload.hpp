// Synthetic workloads for the benchmarks (issue 5, item 1): random
// guillotine layouts of labelled boxes for the inverse direction, random
// grammars for the forward direction. Seeded: the same options give the
// same boxes and the same text, byte for byte, on every machine (the draws
// come from the project's own RandomStream, not from <random>'s
// implementation-defined distributions).
//
// Command line (bench/main.cpp hands these to workload_main):
//   vern_bench --make-layout N [--depth D] [--branching B] [--gaps P] [--seed S] -o FILE.obj
//   vern_bench --make-grammar R [--branching B] [--seed S] -o FILE.grm
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "eval/random_grammar.hpp"
#include "inverse/load/example.hpp"

namespace vern {

// A layout is made top down: the root box is cut along its longest axis
// (never the axis its parent was cut along, so each level is a real level
// of the split tree) into 2..branching pieces, each given a share of the
// boxes; a piece with one box is that box. At level `depth` a piece holding
// several boxes is cut into all of them in one row. Coordinates are whole
// millimetres (as exporters round them), so neighbours share their faces
// exactly and the default tolerance (1e-6 of the extent) never joins two
// distinct cuts.
struct LayoutOptions {
  std::size_t boxes = 1000;  // exactly this many labelled boxes
  int depth = 16;            // levels of cuts at most (>= 1)
  int branching = 4;         // pieces per cut at most (>= 2), before the last level
  double gaps = 0.1;         // chance that a cut also leaves one empty piece (nil)
  std::uint64_t seed = 1;
};

// The boxes in depth-first order, labelled from a small set of building
// parts (wall, window, ...), objects named "label.index" like Blender's.
// Throws vern::Error (Usage) for options out of range, or when a row at the
// last level would need pieces thinner than a millimetre (raise depth).
std::vector<LabelledBox> random_layout(const LayoutOptions& options);

// Labelled OBJ: each box an object `o name` with 8 vertices and 6 quads
// facing outwards, as the OBJ writer writes a box primitive (without
// normals and texture coordinates).
std::string layout_obj(const std::vector<LabelledBox>& boxes);

// `vern_bench --make-layout ...` / `--make-grammar ...`: writes the file
// (atomically) and returns the exit code; vern::Error is reported as by the
// other commands.
bool is_workload_command(const char* arg);
int workload_main(int argc, char** argv);

}  // namespace vern
