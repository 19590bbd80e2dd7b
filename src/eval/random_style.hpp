// Random styles: a measure of inference that cannot be fitted (issue 23,
// item 4). Each seed composes a building style from a set of classes,
// each drawn independently at a known rate, with random numbers, random
// structure and random labels, so that results can be read per class.
// Deterministic: the same seed gives the same text, byte for byte, on
// every machine (the draws come from the project's own RandomStream).
//
// Every style declares a varying plot (`@scope rand(..), rand(..),
// rand(..)`) and holds by construction:
//   - its buildings are valid: parts come from splits and repeats only, so
//     nothing overlaps and nothing leaves the plot, and the absolute parts
//     of every split fit its smallest container, so no part is dropped or
//     squeezed to nothing;
//   - its buildings fill their plot on every axis, so the style derives its
//     own buildings on their extents (precision_recall's self_recall is 1:
//     the style is a fair judge).
// The seed of a measurement is chosen when measuring and never tuned on
// (docs/evaluation.md, "Random styles").
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vern {

enum class StyleClass : std::uint8_t {
  SharedSize,
  LinearSize,
  ConstantInVarying,
  SharedTile,
  AlignedRepeat,
  RecursiveTiers,
  SpecialTile,
  KeptChoice,
  ContinuousSizes,
  MixedSplit,
  Alternatives,
  TurnedRoof,
  GroundFloor,
  Wings,
  NilGap,
  TileChoice,
};

struct StyleClassInfo {
  StyleClass id;
  std::string_view name;  // as evaluate's per-class table prints it
  double rate;            // the share of styles that contain it
};

// The classes, each drawn independently at its rate. The first nine are
// issue 23's; the rest are data/styles' and real fronts' (every style also has splits of
// shares, repeats whose count follows a varying length, and parameters):
//   shared_size        a size drawn once and passed to parts in different
//                      subtrees: both wings of a U one width d, all four
//                      ranges of a courtyard one depth d, an L's range as deep
//                      as its wing is wide, or the annexes (aisles) of a row
//                      or hall one wall height h
//   linear_size        a podium u drawn once and storeys above it k * u + b
//                      high in metres (k is not 1), storeys repeated inside
//   constant_in_varying  a cornice of c metres between storeys and roof, or
//                      piers of c metres at both ends of the main front,
//                      inside a building whose size varies
//   shared_tile        one bay size for every repeat of bays: the main
//                      front's storeys and ground floor and the annexes' walls
//   aligned_repeat     a door bay at a random index on the ground floor,
//                      every storey's bays lined up on it (the index passed
//                      down to every storey)
//   recursive_tiers    a crown of 2 to 6 tiers, each set in by a fixed margin
//                      in metres: a recursive rule with a count and a condition
//   special_tile       a special bay among repeated ones at a random index
//                      (a door among shop bays, a loggia among windows)
//   kept_choice        the kind of bay (window, balcony, pair, panel) chosen
//                      once per building and passed down to every storey
//   continuous_sizes   sizes drawn from continuous ranges (rand, tnormal):
//                      plan shares, ground floor, roof, walls, windows
//   mixed_split        bays that mix parts in metres (window, sill, lintel,
//                      pillars) with parts in shares
//   alternatives       the main roof one of 2-3 kinds, chosen with priorities
//   turned_roof        roof pieces turned a quarter (R(z, pi / 2)): the
//                      annexes' and wings', or the main roof where there are none
//   ground_floor       a ground floor unlike the storeys: its own height in
//                      metres and its own bays (shop fronts between pillars)
//   wings              an L, U or courtyard plan (else one block, a row along
//                      x or a hall of aisles along y)
//   nil_gap            empty space: a yard between the blocks of a row, or a
//                      roof pavilion with air on both sides (L, U and
//                      courtyard plans and tiers leave empty space too)
//   tile_choice        a choice made per tile: each bay of the main front
//                      its kind (a window bay) or, at lower odds, another
//                      (a balcony bay), wherever it stands
inline constexpr std::array<StyleClassInfo, 16> kStyleClasses{{
    {StyleClass::SharedSize, "shared_size", 0.4},
    {StyleClass::LinearSize, "linear_size", 0.4},
    {StyleClass::ConstantInVarying, "constant_in_varying", 0.4},
    {StyleClass::SharedTile, "shared_tile", 0.4},
    {StyleClass::AlignedRepeat, "aligned_repeat", 0.4},
    {StyleClass::RecursiveTiers, "recursive_tiers", 0.4},
    {StyleClass::SpecialTile, "special_tile", 0.4},
    {StyleClass::KeptChoice, "kept_choice", 0.4},
    {StyleClass::ContinuousSizes, "continuous_sizes", 0.5},
    {StyleClass::MixedSplit, "mixed_split", 0.5},
    {StyleClass::Alternatives, "alternatives", 0.4},
    {StyleClass::TurnedRoof, "turned_roof", 0.4},
    {StyleClass::GroundFloor, "ground_floor", 0.5},
    {StyleClass::Wings, "wings", 0.4},
    {StyleClass::NilGap, "nil_gap", 0.4},
    {StyleClass::TileChoice, "tile_choice", 0.3},
}};

std::string_view class_name(StyleClass c);

struct RandomStyle {
  std::string text;                 // the grammar, parseable as it is
  std::vector<StyleClass> classes;  // the classes it contains, in kStyleClasses order
  bool has(StyleClass c) const;
};

RandomStyle random_style(std::uint64_t seed);

// The seed of style `index` (0, 1, ...) of a run with seed `run_seed`:
// mixed, so styles i and i + 1 share nothing, and runs of nearby seeds
// share no style.
std::uint64_t random_style_seed(std::uint64_t run_seed, std::uint32_t index);

}  // namespace vern
