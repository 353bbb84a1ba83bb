// convexloc — the table of methods.
#include "convexloc/methods.hpp"

namespace convexloc {
namespace {

// in the order of Method2D
constexpr MethodInfo kInfo2D[] = {
    {"halfplane", "O(N)", "", "tests the point against every edge", "", false},
    {"wedge", "O(log N)", "", "bisection over the fan of triangles from vertex 0", "", false},
    {"slab", "O(log N)", "", "binary search over slabs at the vertices' heights", "", false},
    {"uniform", "O(1)", "", "equal horizontal slabs, each listing its edges", "slab count",
     false},
    {"polar", "O(1)", "", "polar slabs around a centre, each listing its edges",
     "slabs per octant", true},
};

// in the order of Method3D
constexpr MethodInfo kInfo3D[] = {
    {"halfspace", "O(F)", "", "tests the point against every face plane", "", false},
    {"walk", "O(sqrt F)", "expected",
     "walks across the faces toward the ray from the centre, then tests one plane", "", false},
    {"cubemap", "O(1)", "",
     "a grid on each face of a cube around the centre, each cell listing the faces it sees",
     "grid cells per cube-face side", true},
};

// the entry of `table` named `name`, if any
template <class Method, std::size_t N>
std::optional<Method> byName(const MethodInfo (&table)[N], std::string_view name) noexcept {
  for (std::size_t i = 0; i < N; ++i)
    if (table[i].name == name) return static_cast<Method>(i);
  return std::nullopt;
}

}  // namespace

const MethodInfo& methodInfo(Method2D m) noexcept { return kInfo2D[static_cast<int>(m)]; }
const MethodInfo& methodInfo(Method3D m) noexcept { return kInfo3D[static_cast<int>(m)]; }

std::optional<Method2D> parseMethod2D(std::string_view name) noexcept {
  return byName<Method2D>(kInfo2D, name);
}
std::optional<Method3D> parseMethod3D(std::string_view name) noexcept {
  return byName<Method3D>(kInfo3D, name);
}

}  // namespace convexloc
