#include "inverse/check/check_bindings.hpp"

#include <algorithm>

namespace vern::check_detail {

void Bindings::open_unknowns(const Expr& e, std::vector<int>& out) const {
  for (const auto& n : e.nodes()) {
    if (n.kind != ExprKind::Param && n.kind != ExprKind::Constant) continue;
    const Slot& slot = n.kind == ExprKind::Param ? param(n.index) : constant(n.index);
    if (slot.unknown >= 0 && !unknowns_[static_cast<std::size_t>(slot.unknown)].value &&
        std::find(out.begin(), out.end(), slot.unknown) == out.end())
      out.push_back(slot.unknown);
  }
}

void Bindings::drop_unknowns(std::size_t count) {
  std::erase_if(trail_, [&](const auto& t) { return static_cast<std::size_t>(t.first) >= count; });
  unknowns_.resize(count);
}

}  // namespace vern::check_detail
