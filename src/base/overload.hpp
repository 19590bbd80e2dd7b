// Overload{lambdas...}: the usual helper for std::visit over a variant.
#pragma once

namespace vern {

template <class... F>
struct Overload : F... {
  using F::operator()...;
};
template <class... F>
Overload(F...) -> Overload<F...>;

}  // namespace vern
