// Fuzz bytes as example buildings: small layouts of labelled boxes.
//
// Random bytes rarely make a valid OBJ with non-overlapping parts, so the
// inference target reads them as a compact description instead. Every byte
// string is some layout (missing bytes read as 0), and small changes to the
// bytes make small changes to the layout, which is what a fuzzer needs.
//
//   header   1 byte   bits 0-1: examples - 1 (1..3, 3 read as 1)
//                     bits 2-4: grid unit (1, 0.5, 0.25, 0.1, 3, 0.001, 1000, 0.3)
//                     bit 5: coordinates rounded to 32-bit floats, as exporters write them
//                     bit 6: examples moved from the origin by a fraction of their size
//   example  1 byte   bit 0: 1 = a tree of cuts, 0 = free boxes
//     free   bits 1-4: boxes - 1; per box 7 bytes: label, x, y, z (% 32), dx, dy, dz (% 16, 0 = flat)
//     tree   3 bytes: the box's size (1 + % 24 each), then the cuts, depth first:
//            per container 1 byte: % 4 == 0 a part (label: (byte >> 2) % 6), 1 empty space,
//            2-3 a split along (byte >> 2) % 3 into 2 + (byte >> 4) % 3 parts, one byte of
//            weight (1 + % 4) per part; at depth 3 or after 48 parts every container is a part.
//     peeled (a tree whose bits 6 and 7 are set too) 1 byte: 257 + % 128 slabs, then per slab 1 byte:
//            its axis (% 3) and label (>> 2); each peels a unit off the rest, and the core
//            left is the last part (label: 1 byte): a cut tree deeper than the reader nests text.
//
// Labels are a to f. A tree-of-cuts example never has overlapping parts, so
// inference must accept it; free boxes may overlap, and then inference must
// refuse them with an Input error.
#pragma once

#include <vector>

#include "entries.hpp"
#include "inverse/load/example.hpp"

namespace vern::fuzz {

struct Layout {
  std::vector<Example> examples;  // bounds computed; no meshes
  // Every example is a tree of cuts: no overlaps, so inference must succeed.
  bool valid_by_construction = true;
};

Layout decode_layout(Bytes input);

}  // namespace vern::fuzz
