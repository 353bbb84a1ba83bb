// convexloc — validation and normalisation of convex polygons.
#include "convexloc/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <sstream>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/predicates.hpp"

namespace convexloc {
namespace {

// "(x, y)" with enough digits to find the point again
std::string show(Vec2 p) {
  std::ostringstream s;
  s.precision(17);
  s << '(' << p.x << ", " << p.y << ')';
  return s.str();
}

// b lies on the segment from a to c, given that the three are collinear and distinct
bool between(Vec2 a, Vec2 b, Vec2 c) {
  bool inX = (a.x <= b.x && b.x <= c.x) || (c.x <= b.x && b.x <= a.x);
  bool inY = (a.y <= b.y && b.y <= c.y) || (c.y <= b.y && b.y <= a.y);
  return inX && inY;
}

// 0 for directions in [0, pi), 1 for [pi, 2 pi); exact, from coordinate comparisons
int halfOf(Vec2 from, Vec2 to) {
  return (to.y > from.y || (to.y == from.y && to.x > from.x)) ? 0 : 1;
}

// direction of edge (a, b) comes strictly before that of (c, d) in angle order from +x
bool angleBefore(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  int h1 = halfOf(a, b), h2 = halfOf(c, d);
  if (h1 != h2) return h1 < h2;
  return crossDiff2d(a, b, c, d) > 0;
}

// segments pq and rs share a point (closed segments, exact)
bool segmentsMeet(Vec2 p, Vec2 q, Vec2 r, Vec2 s) {
  int o1 = orient2d(p, q, r), o2 = orient2d(p, q, s);
  int o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && between(p, r, q)) return true;
  if (o2 == 0 && between(p, s, q)) return true;
  if (o3 == 0 && between(r, p, s)) return true;
  if (o4 == 0 && between(r, q, s)) return true;
  return false;
}

}  // namespace

ConvexPolygon::ConvexPolygon(std::span<const Vec2> points, std::span<const std::size_t> lines) {
  const std::size_t n = points.size();
  auto lineOf = [&](std::size_t input) -> std::size_t {
    return lines.empty() ? 0 : lines[input];
  };
  auto name = [&](std::size_t input) {
    return "vertex " + std::to_string(input + 1) + ' ' + show(points[input]);
  };
  if (!lines.empty() && lines.size() != n)
    throw UsageError("ConvexPolygon: lines must be empty or match the points");
  if (n > kMaxPolygonVertices)
    throw GeometryError("too many vertices: " + std::to_string(n) + " (the limit is " +
                        std::to_string(kMaxPolygonVertices) + ")");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      throw GeometryError(name(i) + " has a coordinate that is not a finite number", lineOf(i));
  }
  std::size_t lastLine = n == 0 ? 0 : lineOf(n - 1);
  if (n < 3)
    throw GeometryError("a polygon needs at least 3 vertices, got " + std::to_string(n), lastLine);

  // all collinear: report that, rather than whatever a later check would trip on
  {
    std::size_t far = 1;
    while (far < n && points[far] == points[0]) ++far;
    if (far == n)
      throw GeometryError("fewer than 3 distinct vertices: all " + std::to_string(n) +
                              " are " + show(points[0]),
                          lastLine);
    bool flat = true;
    for (std::size_t i = far + 1; i < n && flat; ++i)
      flat = orient2d(points[0], points[far], points[i]) == 0;
    if (flat) {
      // distinct count, for a precise message when there are only two
      std::vector<Vec2> sorted(points.begin(), points.end());
      std::sort(sorted.begin(), sorted.end(),
                [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
      std::size_t distinct = std::unique(sorted.begin(), sorted.end()) - sorted.begin();
      if (distinct < 3)
        throw GeometryError("fewer than 3 distinct vertices (" + std::to_string(distinct) +
                                " distinct among " + std::to_string(n) + ")",
                            lastLine);
      throw GeometryError("all " + std::to_string(n) +
                              " vertices are collinear: the polygon has no area",
                          lastLine);
    }
  }

  // drop repeats and collinear middle vertices; a spike (doubling back) is an error
  std::deque<std::uint32_t> ring;
  auto collapse = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    // true when b must go; throws when a-b-c doubles back
    if (points[a] == points[b] || points[b] == points[c]) return true;
    if (orient2d(points[a], points[b], points[c]) != 0) return false;
    if (points[a] == points[c] || !between(points[a], points[b], points[c]))
      throw GeometryError("the boundary doubles back on itself at " + name(b) +
                              ": the polygon is self-intersecting",
                          lineOf(b));
    return true;
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!ring.empty() && points[ring.back()] == points[i]) {
      ++repeated_;
      continue;
    }
    ring.push_back(i);
    while (ring.size() >= 3 &&
           collapse(ring[ring.size() - 3], ring[ring.size() - 2], ring[ring.size() - 1])) {
      ring.erase(ring.end() - 2);
    }
  }
  for (bool changed = true; changed && ring.size() >= 3;) {
    changed = false;
    if (points[ring.back()] == points[ring.front()]) {
      ring.pop_back();
      ++repeated_;
      changed = true;
    } else if (collapse(ring[ring.size() - 2], ring.back(), ring.front())) {
      ring.pop_back();
      changed = true;
    } else if (collapse(ring.back(), ring.front(), ring[1])) {
      ring.pop_front();
      changed = true;
    }
  }
  if (ring.size() < 3)
    throw GeometryError("fewer than 3 vertices remain after dropping repeated and collinear ones",
                        lastLine);

  const std::size_t m = ring.size();
  auto at = [&](std::size_t k) { return points[ring[k % m]]; };
  std::vector<int> turn(m);
  std::size_t left = 0, right = 0;
  for (std::size_t k = 0; k < m; ++k) {
    turn[k] = orient2d(at(k + m - 1), at(k), at(k + 1));
    (turn[k] > 0 ? left : right) += 1;
  }
  if (left > 0 && right > 0) {
    // a crossing is the better diagnosis when there is one; look for it where affordable
    if (m <= 4096) {
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = i + 2; j < m; ++j) {
          if (i == 0 && j == m - 1) continue;  // neighbours through the wrap
          if (segmentsMeet(at(i), at(i + 1), at(j), at(j + 1)))
            throw GeometryError("self-intersecting: the edge from " + name(ring[i]) +
                                    " crosses the edge from " + name(ring[j]),
                                lineOf(ring[j]));
        }
    }
    int majority = left >= right ? 1 : -1;
    std::size_t k = 0;
    while (turn[k] == majority) ++k;
    throw GeometryError("not convex: reflex " + name(ring[k]), lineOf(ring[k]));
  }
  clockwise_ = right > 0;
  if (clockwise_) std::reverse(ring.begin(), ring.end());

  // locally convex; convex and simple only if the edge directions turn once around
  std::size_t wraps = 0;
  for (std::size_t k = 0; k < m; ++k) {
    if (!angleBefore(at(k), at(k + 1), at(k + 1), at(k + 2))) {
      if (++wraps == 2)
        throw GeometryError("self-intersecting: the boundary winds around more than once (at " +
                                name(ring[(k + 1) % m]) + ")",
                            lineOf(ring[(k + 1) % m]));
    }
  }

  vertices_.reserve(m);
  source_.reserve(m);
  for (std::uint32_t idx : ring) {
    vertices_.push_back(points[idx]);
    source_.push_back(idx);
  }
  dropped_ = n - m;
  bounds_ = {vertices_[0], vertices_[0]};
  for (Vec2 v : vertices_) {
    bounds_.lo.x = std::min(bounds_.lo.x, v.x);
    bounds_.lo.y = std::min(bounds_.lo.y, v.y);
    bounds_.hi.x = std::max(bounds_.hi.x, v.x);
    bounds_.hi.y = std::max(bounds_.hi.y, v.y);
  }
}

double ConvexPolygon::area() const noexcept {
  long double twice = 0;
  Vec2 o = vertices_[0];
  for (std::size_t i = 1; i + 1 < vertices_.size(); ++i) {
    Vec2 a = vertices_[i], b = vertices_[i + 1];
    twice += (static_cast<long double>(a.x) - o.x) * (static_cast<long double>(b.y) - o.y) -
             (static_cast<long double>(a.y) - o.y) * (static_cast<long double>(b.x) - o.x);
  }
  return static_cast<double>(twice / 2);
}

}  // namespace convexloc
