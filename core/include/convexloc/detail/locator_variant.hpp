// convexloc (detail) — one locator of a dimension, its method chosen at run time.
//
// LocatorVariant holds one of the dimension's locators in a std::variant and forwards the
// common interface (locate, the batch, trace, stats, cells) to it; Locator2D and Locator3D
// derive from it and add only their constructor, which builds the variant. The forwarding
// members are defined in core (src/detail/locator_variant.hpp) and instantiated there once
// per dimension, so a caller's code holds one call per query, not the dispatch.
#pragma once

#include <span>
#include <utility>
#include <variant>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/methods.hpp"

namespace convexloc::detail {

// Method: the dimension's method enum, in the order of Locators; Point, Trace, Stats, Cell:
// the dimension's types.
template <class Method, class Point, class Trace, class Stats, class Cell, class... Locators>
class LocatorVariant {
 public:
  // the method built
  Method method() const noexcept { return static_cast<Method>(impl_.index()); }
  // the class of p (exact)
  Location locate(Point p) const noexcept;
  // out[i] = locate(points[i]) over the shorter of the two spans; allocates nothing
  void locate(std::span<const Point> points, std::span<Location> out) const noexcept;
  // the steps locate(p) takes, and its answer
  Trace trace(Point p) const;
  // the same with `options` (ignored by the methods without a radius filter)
  Trace trace(Point p, TraceOptions options) const;
  // size and shape of the subdivision
  Stats stats() const;
  // the subdivision as drawable geometry (empty for methods without cells)
  std::vector<Cell> cells() const;
  // the underlying locator, for method-specific introspection; null for another method
  template <class T>
  const T* get() const noexcept {
    return std::get_if<T>(&impl_);
  }

 protected:
  explicit LocatorVariant(std::variant<Locators...> impl) : impl_(std::move(impl)) {}

 private:
  std::variant<Locators...> impl_;
};

}  // namespace convexloc::detail
