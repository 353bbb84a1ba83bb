// convexloc — validation and normalisation of convex polygons.
//
// The constructor is a pipeline of checks, each throwing its own GeometryError naming its
// witness: the input itself (sizes, finite coordinates), all points collinear, the ring
// without repeats and collinear middle vertices (a spike doubles back), every turn the same
// way (else a crossing or a reflex vertex), and the edge directions winding once. A ring
// whose turns are all strict left turns and whose edge directions turn once around is the
// boundary of a strictly convex polygon.
#include "convexloc/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/predicates.hpp"
#include "detail/polyhedron_build.hpp"

namespace convexloc {

std::string detail::show(Vec2 p) {
  std::ostringstream s;
  s.precision(17);
  s << '(' << p.x << ", " << p.y << ')';
  return s.str();
}

namespace {

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

// the input points with their source lines, to name a witness in an error
struct Input {
  std::span<const Vec2> points;
  std::span<const std::size_t> lines;

  std::size_t size() const { return points.size(); }
  Vec2 operator[](std::size_t i) const { return points[i]; }
  std::size_t lineOf(std::size_t i) const { return lines.empty() ? 0 : lines[i]; }
  // the line of the last point: where a whole-polygon problem is reported
  std::size_t lastLine() const { return points.empty() ? 0 : lineOf(points.size() - 1); }
  std::string name(std::size_t i) const {
    return "vertex " + std::to_string(i + 1) + ' ' + detail::show(points[i]);
  }
};

// the input ring as indices of input points
struct Ring {
  std::deque<std::uint32_t> at;
};

// === Checks, in order; each throws its own error naming its witness

// the sizes and every coordinate finite
void checkInput(const Input& in) {
  const std::size_t n = in.size();
  if (!in.lines.empty() && in.lines.size() != n)
    throw UsageError("ConvexPolygon: lines must be empty or match the points");
  if (n > kMaxPolygonVertices)
    throw GeometryError("too many vertices: " + std::to_string(n) + " (the limit is " +
                        std::to_string(kMaxPolygonVertices) + ")");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(in[i].x) || !std::isfinite(in[i].y))
      throw GeometryError(in.name(i) + " has a coordinate that is not a finite number",
                          in.lineOf(i));
  }
  if (n < 3)
    throw GeometryError("a polygon needs at least 3 vertices, got " + std::to_string(n),
                        in.lastLine());
}

// all collinear: report that, rather than whatever a later check would trip on
void rejectCollinear(const Input& in) {
  const std::size_t n = in.size();
  std::size_t far = 1;
  while (far < n && in[far] == in[0]) ++far;
  if (far == n)
    throw GeometryError(
        "fewer than 3 distinct vertices: all " + std::to_string(n) + " are " + detail::show(in[0]),
        in.lastLine());
  bool flat = true;
  for (std::size_t i = far + 1; i < n && flat; ++i) flat = orient2d(in[0], in[far], in[i]) == 0;
  if (!flat) return;
  // distinct count, for a precise message when there are only two
  std::vector<Vec2> sorted(in.points.begin(), in.points.end());
  std::sort(sorted.begin(), sorted.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::size_t distinct = std::unique(sorted.begin(), sorted.end()) - sorted.begin();
  if (distinct < 3)
    throw GeometryError("fewer than 3 distinct vertices (" + std::to_string(distinct) +
                            " distinct among " + std::to_string(n) + ")",
                        in.lastLine());
  throw GeometryError(
      "all " + std::to_string(n) + " vertices are collinear: the polygon has no area",
      in.lastLine());
}

// whether b must go from a-b-c (a repeat, or on the segment from a to c); throws where the
// boundary doubles back at b
bool collapses(const Input& in, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  if (in[a] == in[b] || in[b] == in[c]) return true;
  if (orient2d(in[a], in[b], in[c]) != 0) return false;
  if (in[a] == in[c] || !between(in[a], in[b], in[c]))
    throw GeometryError("the boundary doubles back on itself at " + in.name(b) +
                            ": the polygon is self-intersecting",
                        in.lineOf(b));
  return true;
}

// the ring without repeated vertices and collinear middle ones, along the input and then
// across its wrap; a spike (doubling back) is an error
Ring simplify(const Input& in) {
  Ring r;
  std::deque<std::uint32_t>& ring = r.at;
  for (std::uint32_t i = 0; i < in.size(); ++i) {
    if (!ring.empty() && in[ring.back()] == in[i]) {
      continue;
    }
    ring.push_back(i);
    while (ring.size() >= 3 &&
           collapses(in, ring[ring.size() - 3], ring[ring.size() - 2], ring[ring.size() - 1])) {
      ring.erase(ring.end() - 2);
    }
  }
  for (bool changed = true; changed && ring.size() >= 3;) {
    changed = false;
    if (in[ring.back()] == in[ring.front()]) {
      ring.pop_back();
      changed = true;
    } else if (collapses(in, ring[ring.size() - 2], ring.back(), ring.front())) {
      ring.pop_back();
      changed = true;
    } else if (collapses(in, ring.back(), ring.front(), ring[1])) {
      ring.pop_front();
      changed = true;
    }
  }
  if (ring.size() < 3)
    throw GeometryError("fewer than 3 vertices remain after dropping repeated and collinear ones",
                        in.lastLine());
  return r;
}

// two edges of a ring with turns both ways that cross, where the search is affordable: a
// crossing is the better diagnosis than a reflex vertex
void rejectCrossing(const Input& in, const std::deque<std::uint32_t>& ring) {
  const std::size_t m = ring.size();
  if (m > 4096) return;
  auto at = [&](std::size_t k) { return in[ring[k % m]]; };
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 2; j < m; ++j) {
      if (i == 0 && j == m - 1) continue;  // neighbours through the wrap
      if (segmentsMeet(at(i), at(i + 1), at(j), at(j + 1)))
        throw GeometryError("self-intersecting: the edge from " + in.name(ring[i]) +
                                " crosses the edge from " + in.name(ring[j]),
                            in.lineOf(ring[j]));
    }
}

// whether the ring turns clockwise; throws unless every turn goes the same way
bool clockwiseTurns(const Input& in, const std::deque<std::uint32_t>& ring) {
  const std::size_t m = ring.size();
  auto at = [&](std::size_t k) { return in[ring[k % m]]; };
  std::vector<int> turn(m);
  std::size_t left = 0, right = 0;
  for (std::size_t k = 0; k < m; ++k) {
    turn[k] = orient2d(at(k + m - 1), at(k), at(k + 1));
    (turn[k] > 0 ? left : right) += 1;
  }
  if (left > 0 && right > 0) {
    rejectCrossing(in, ring);
    int majority = left >= right ? 1 : -1;
    std::size_t k = 0;
    while (turn[k] == majority) ++k;
    throw GeometryError("not convex: reflex " + in.name(ring[k]), in.lineOf(ring[k]));
  }
  return right > 0;
}

// a counter-clockwise ring that turns left everywhere is convex and simple only if its edge
// directions turn once around
void checkWinding(const Input& in, const std::deque<std::uint32_t>& ring) {
  const std::size_t m = ring.size();
  auto at = [&](std::size_t k) { return in[ring[k % m]]; };
  std::size_t wraps = 0;
  for (std::size_t k = 0; k < m; ++k) {
    if (!angleBefore(at(k), at(k + 1), at(k + 1), at(k + 2))) {
      if (++wraps == 2)
        throw GeometryError("self-intersecting: the boundary winds around more than once (at " +
                                in.name(ring[(k + 1) % m]) + ")",
                            in.lineOf(ring[(k + 1) % m]));
    }
  }
}

}  // namespace

// === The pipeline

ConvexPolygon::ConvexPolygon(std::span<const Vec2> points, std::span<const std::size_t> lines) {
  const Input in{points, lines};
  checkInput(in);
  rejectCollinear(in);
  Ring ring = simplify(in);
  clockwise_ = clockwiseTurns(in, ring.at);
  if (clockwise_) std::reverse(ring.at.begin(), ring.at.end());
  checkWinding(in, ring.at);

  // keep the ring, each vertex's input index, and the bounding box
  vertices_.reserve(ring.at.size());
  source_.reserve(ring.at.size());
  for (std::uint32_t idx : ring.at) {
    vertices_.push_back(points[idx]);
    source_.push_back(idx);
  }
  dropped_ = points.size() - ring.at.size();
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
