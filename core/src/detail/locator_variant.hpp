// convexloc (internal) — the forwarding members of detail::LocatorVariant (see
// convexloc/detail/locator_variant.hpp): one std::visit each. A dimension's locator file
// includes this and instantiates the class once.
#pragma once

#include <span>
#include <variant>
#include <vector>

#include "convexloc/detail/locator_variant.hpp"

namespace convexloc::detail {

template <class M, class P, class T, class S, class C, class... L>
Location LocatorVariant<M, P, T, S, C, L...>::locate(P p) const noexcept {
  return std::visit([&](const auto& l) { return l.locate(p); }, impl_);
}

template <class M, class P, class T, class S, class C, class... L>
void LocatorVariant<M, P, T, S, C, L...>::locate(std::span<const P> points,
                                                 std::span<Location> out) const noexcept {
  std::visit([&](const auto& l) { l.locate(points, out); }, impl_);
}

template <class M, class P, class T, class S, class C, class... L>
T LocatorVariant<M, P, T, S, C, L...>::trace(P p) const {
  return std::visit([&](const auto& l) { return l.trace(p); }, impl_);
}

template <class M, class P, class T, class S, class C, class... L>
T LocatorVariant<M, P, T, S, C, L...>::trace(P p, TraceOptions options) const {
  return std::visit(
      [&](const auto& l) {
        if constexpr (requires { l.trace(p, options); })
          return l.trace(p, options);
        else
          return l.trace(p);
      },
      impl_);
}

template <class M, class P, class T, class S, class C, class... L>
S LocatorVariant<M, P, T, S, C, L...>::stats() const {
  return std::visit([&](const auto& l) { return l.stats(); }, impl_);
}

template <class M, class P, class T, class S, class C, class... L>
std::vector<C> LocatorVariant<M, P, T, S, C, L...>::cells() const {
  return std::visit([&](const auto& l) { return l.cells(); }, impl_);
}

}  // namespace convexloc::detail
