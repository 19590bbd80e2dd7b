// A scope whose length along one world axis is left open (for check.hpp).
//
// A split part whose end lies in empty space, where no box face marks it
// (the top of a skyscraper plot above its towers), has no length the cuts
// could give. Its child is asked instead which lengths it accepts
// (Matcher::lengths, check_lengths.cpp): at(l) is the scope the part would
// have at length l, and operations below compose their own change of scope
// with it, so the question reaches the terminals, whose world bounds move
// linearly with l.
#pragma once

#include <functional>
#include <utility>

#include "forward/scope.hpp"

namespace vern::check_detail {

struct FreeScope {
  std::function<Scope(double)> at;  // the scope for length l in [lmin, lmax]
  int world = 0;                    // the open world axis
  double lmin = 0, lmax = 0;
};

// The scope f makes of fs's scope, for every length.
inline FreeScope compose(const FreeScope& fs, std::function<Scope(const Scope&)> f) {
  return {[at = fs.at, f = std::move(f)](double l) { return f(at(l)); }, fs.world, fs.lmin, fs.lmax};
}

}  // namespace vern::check_detail
