// Layout faults: overlapping parts and parts outside the start scope.
#include "forward/layout_faults.hpp"

#include <gtest/gtest.h>

#include "support/derive_helpers.hpp"

namespace vern {
namespace {

using test::derive_text;

TEST(LayoutFaults, ASplitHasNone) {
  const Derivation d = derive_text("a --> split(x){ ~1 : I(rect) | 2 : I(window) | ~1 : nil }", {10, 4, 3});
  const LayoutFaults f = find_faults(d);
  EXPECT_TRUE(f.valid()) << f.first;
}

TEST(LayoutFaults, PartsSharingVolumeAreOverlaps) {
  const Derivation shifted = derive_text("a --> S(2, 4, 4){ I(rect) }\n", {4, 4, 4});
  EXPECT_TRUE(find_faults(shifted).valid());
  const Derivation twice = derive_text(
      "a --> split(x){ 3 : I(rect) | ~1 : T(-1, 0, 0){ I(window) } }\n", {4, 4, 4});
  const LayoutFaults f = find_faults(twice);
  EXPECT_EQ(f.overlaps, 1u);
  EXPECT_EQ(f.outside, 0u);
  EXPECT_NE(f.first.find("'window' #1 overlaps 'rect' #0 by 1 x 4 x 4"), std::string::npos) << f.first;
}

TEST(LayoutFaults, TouchingAndFlatPartsAreNotOverlaps) {
  // Side by side (touching at x = 2) and a zero-thickness face on top.
  const Derivation d = derive_text(
      "a --> split(x){ 2 : I(rect) | ~1 : b }\n"
      "b --> comp(f){ top : I(window) | front : I(window) }\n", {4, 4, 4});
  EXPECT_TRUE(find_faults(d).valid()) << find_faults(d).first;
}

TEST(LayoutFaults, PartsBeyondTheStartScopeAreOutside) {
  const Derivation d = derive_text("a --> T(0, 0, 3){ S(4, 4, 2){ I(roof) } }\n", {4, 4, 4});
  const LayoutFaults f = find_faults(d);
  EXPECT_EQ(f.outside, 1u);
  EXPECT_EQ(f.overlaps, 0u);
  EXPECT_NE(f.first.find("'roof' #0 reaches outside"), std::string::npos) << f.first;
}

}  // namespace
}  // namespace vern
