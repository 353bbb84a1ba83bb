// convexloc — the vertex where a line's side function is largest, by bisection: O(log N).
//
// With g(i) the sign of f(v_(i+1)) - f(v_i) (edge i rises, is level, or falls), the ring
// reads, cyclically: a rising run, at most one level edge, a falling run, at most one level
// edge (see ring2d.hpp). Let v_m be the first largest vertex after v_0. If edge 0 rises,
// "g(i) > 0 and f(v_i) >= f(v_0)" holds exactly for i in [0, m): before m the ring rises
// from v_0; at m it stops rising; after m it either falls or rises again from below f(v_0)
// towards v_n = v_0. If edge 0 falls, or is the level edge at the smallest end, "g(i) > 0 or
// f(v_i) <= f(v_0)" holds exactly for i in [0, m): the ring first falls below f(v_0), then
// rises; past m it falls back towards f(v_0) from strictly above (m = n, read as 0, when v_0
// itself is largest). If edge 0 is the level edge at the largest end, v_0 is largest. Either
// predicate is true on a prefix of [0, n), so the first index where it fails is found by
// bisection, each step two exact comparisons.
#include <cstdint>
#include <span>

#include "intersect/ring2d.hpp"

namespace convexloc::detail {

std::uint32_t bisectLargest(std::span<const Vec2> ring, LineProbe& line) noexcept {
  const std::uint32_t n = static_cast<std::uint32_t>(ring.size());
  auto rises = [&](std::uint32_t i) { return line.rise(ring[i], ring[nextOf(i, n)]); };
  const int first = rises(0);
  if (first == 0 && rises(n - 1) > 0) return 0;  // edge 0 is level at the largest end
  const bool risesFirst = first > 0;
  auto beforeLargest = [&](std::uint32_t i) {
    const int g = rises(i), fromStart = line.rise(ring[0], ring[i]);
    return risesFirst ? (g > 0 && fromStart >= 0) : (g > 0 || fromStart <= 0);
  };
  std::uint32_t lo = 0, hi = n;  // beforeLargest(lo) holds; hi is the first index known to fail
  while (hi - lo > 1) {
    const std::uint32_t mid = lo + (hi - lo) / 2;
    if (beforeLargest(mid))
      lo = mid;
    else
      hi = mid;
  }
  return hi == n ? 0 : hi;
}

}  // namespace convexloc::detail
