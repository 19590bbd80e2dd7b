// Where a split may cut the example's boxes (check.hpp): along one axis of
// a scope, the positions no box crosses.
//
// Checking a split places its part boundaries only there (the cuts of the
// ordered-box algorithm), so a placement is a choice of cuts, not of
// lengths; the boxes between two cuts are the part's contents.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "forward/scope.hpp"
#include "inverse/load/example.hpp"

namespace vern::check_detail {

// Boxes, as indices into the example's.
using BoxList = std::vector<std::uint32_t>;

// A scope's own axis as a world axis: local coordinate t along it is
// sign * (world - origin). Only scopes whose frame is a signed permutation
// (quarter turns) can be cut along an axis this way.
struct AxisMap {
  int world = 0;
  double sign = 1;
  double origin = 0;
  double local(double w) const { return sign * (w - origin); }
  double world_of(double t) const { return origin + sign * t; }
};

// The scope's axis a as a world axis; nothing when the scope is turned
// by an angle other than a quarter turn.
std::optional<AxisMap> axis_map(const Scope& s, Axis a);

// The positions along a scope's axis where parts may begin or end: the
// faces of the boxes that no box crosses, snapped within the tolerance,
// and the two ends of the scope. A position with flat boxes on it (zero
// thickness along the axis) appears twice, the flat boxes in the
// zero-length segment between the two copies, so a boundary there can give
// them to either side.
struct Cuts {
  std::vector<double> at;           // local positions, ascending
  // The boxes of segment k, [at[k], at[k+1]], are in_order[prefix[k] ..
  // prefix[k + 1]): one list, not one per segment (a cut scope's segments
  // are many, and most tries of a choice cut one and fail).
  BoxList in_order;
  std::vector<std::size_t> prefix;  // boxes in segments before k
  BoxList outside;                  // boxes beyond the scope's ends
  std::size_t segments() const { return prefix.size() - 1; }
  std::size_t between(std::size_t j, std::size_t e) const { return prefix[e] - prefix[j]; }
  BoxList boxes(std::size_t j, std::size_t e) const {
    return BoxList(in_order.begin() + static_cast<std::ptrdiff_t>(prefix[j]),
                   in_order.begin() + static_cast<std::ptrdiff_t>(prefix[e]));
  }
};

// The cuts of `inside` (indices into `boxes`) along am, on a scope of
// `length` along it; coordinates within cut_tol (<= tol) are one, and
// within tol of a scope's end, that end. Boxes beyond the scope's ends by
// more than tol are collected in Cuts::outside.
Cuts make_cuts(const std::vector<LabelledBox>& boxes, const BoxList& inside, const AxisMap& am, double length,
               double tol, double cut_tol);
// The same into c, whose lists keep their room (CutsCache reuses them).
void make_cuts(const std::vector<LabelledBox>& boxes, const BoxList& inside, const AxisMap& am, double length,
               double tol, double cut_tol, Cuts& c);

// The cuts of the same boxes along the same axis, kept for a while: the
// alternatives of a choice each split the same boxes, mostly along the
// same axis, and sorting the faces is most of the cost of a failed try.
// An entry replaced that no split still holds is refilled in place: a
// city's check cuts 50,000 times, and making five lists each time cost
// more than cutting one or two boxes.
class CutsCache {
 public:
  CutsCache(const std::vector<LabelledBox>& boxes, double tol, double cut_tol)
      : boxes_(boxes), tol_(tol), cut_tol_(cut_tol) {}
  std::shared_ptr<const Cuts> of(const BoxList& inside, const AxisMap& am, double length);

 private:
  struct Entry {
    BoxList boxes;
    int world;
    double sign, origin, length;
    std::shared_ptr<Cuts> cuts;
  };
  const std::vector<LabelledBox>& boxes_;
  double tol_, cut_tol_;
  std::vector<Entry> entries_;
  std::size_t next_ = 0;
};

// "x = 0, 6.5, 10": the cuts in world coordinates, for messages.
std::string cuts_text(const Cuts& c, const AxisMap& am);

}  // namespace vern::check_detail
