// convexloc — the methods, by name: what each one is, what it costs, what its resolution means.
//
// One table for the command-line tool, the viewer's panels and the locators alike, so that a
// method is named and described the same way everywhere.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace convexloc {

// the 2D methods, in the paper's order
enum class Method2D : std::uint8_t { Halfplane, Wedge, Slab, Uniform, Polar };

// the 3D methods
enum class Method3D : std::uint8_t { Halfspace, Walk, Cubemap };

// every 2D method, in order
inline constexpr Method2D kAllMethods2D[] = {Method2D::Halfplane, Method2D::Wedge, Method2D::Slab,
                                             Method2D::Uniform, Method2D::Polar};
// every 3D method, in order
inline constexpr Method3D kAllMethods3D[] = {Method3D::Halfspace, Method3D::Walk,
                                             Method3D::Cubemap};

// What a user is told about one method.
struct MethodInfo {
  std::string_view name;        // "polar": what --method takes
  std::string_view cost;        // the cost of one query in O notation: "O(1)"
  std::string_view costNote;    // what qualifies the cost ("expected"), or empty
  std::string_view summary;     // how it finds the answer, in one line
  std::string_view resolution;  // what --resolution sets, or empty when the method has none
  bool paper = false;           // the paper's new method (polar, cubemap)
};

// the facts about one method
const MethodInfo& methodInfo(Method2D m) noexcept;
const MethodInfo& methodInfo(Method3D m) noexcept;

// "halfplane", "wedge", "slab", "uniform", "polar"
inline std::string_view toString(Method2D m) noexcept { return methodInfo(m).name; }
// "halfspace", "walk", "cubemap"
inline std::string_view toString(Method3D m) noexcept { return methodInfo(m).name; }

// How trace() runs a query. The radius filter is convexloc's own shortcut (a cell's two
// radii decide most points before any predicate); without it polar and cubemap queries run
// exactly as the paper describes, the cell's edges (faces) deciding. Either way the answer is
// locate(p)'s.
struct TraceOptions {
  bool radii = true;  // polar, cubemap: let the cell's radii decide first
};

// the method with that name, if any
std::optional<Method2D> parseMethod2D(std::string_view name) noexcept;
std::optional<Method3D> parseMethod3D(std::string_view name) noexcept;

}  // namespace convexloc
