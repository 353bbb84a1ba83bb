// convexloc (internal) — the O(N) search for an extreme vertex that the line and plane
// baselines share.
#pragma once

#include <cstdint>
#include <span>

namespace convexloc::detail {

// a vertex where the probe's side function is largest, by comparing every vertex with the
// best so far (probe.rise(u, v) > 0 when v is strictly larger): O(N) exact comparisons
template <class Point, class Probe>
std::uint32_t scanLargest(std::span<const Point> vertices, Probe& probe) noexcept {
  std::uint32_t best = 0;
  for (std::uint32_t i = 1; i < vertices.size(); ++i)
    if (probe.rise(vertices[best], vertices[i]) > 0) best = i;
  return best;
}

}  // namespace convexloc::detail
