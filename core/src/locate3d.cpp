// convexloc — the three 3D locators.
#include "convexloc/locate3d.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "convexloc/batch.hpp"
#include "convexloc/error.hpp"
#include "convexloc/predicates.hpp"
#include "convexloc/timing.hpp"
#include "detail/batch_loop.hpp"
#include "detail/radii.hpp"

namespace convexloc {
namespace {

using Triangle = ConvexPolyhedron::Triangle;

constexpr std::uint32_t kNone = 0xffffffffu;

// === Trace sinks: the query code is written once and either records or not

// records nothing; compiles away in locate()
struct NoSink {
  void face(std::uint32_t, int) {}
  void visit(std::uint32_t) {}
  void step(std::uint32_t, std::uint8_t, int) {}
  void cell(int, int, std::uint64_t, std::uint64_t, double, double) {}
  void crowded() {}
  void fallback() {}
  void nonFinite() {}
  void atCentre() {}
  void radius(double, float, float, bool) {}
};

// records every step into a Trace3D
struct TraceSink {
  Trace3D& t;
  void face(std::uint32_t f, int s) { t.faces.push_back({f, s}); }
  void visit(std::uint32_t f) { t.path.push_back(f); }
  void step(std::uint32_t f, std::uint8_t e, int s) { t.steps.push_back({f, e, s}); }
  void cell(int cubeFace, int level, std::uint64_t i, std::uint64_t j, double s, double tt) {
    t.cubeFace = cubeFace;
    t.level = level;
    t.cellI = static_cast<std::uint32_t>(i);
    t.cellJ = static_cast<std::uint32_t>(j);
    t.s = s;
    t.t = tt;
  }
  void crowded() { t.crowded = true; }
  void radius(double d2, float in2, float out2, bool decided) {
    t.distance = std::sqrt(d2);
    t.innerRadius = std::sqrt(static_cast<double>(in2));
    t.outerRadius = std::sqrt(static_cast<double>(out2));
    t.byRadius = decided;
  }
  void fallback() { t.fallback = true; }
  void nonFinite() { t.nonFinite = true; }
  void atCentre() { t.atCentre = true; }
};

// all three coordinates are finite
inline bool finite(Vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// orient3d of p against face t: > 0 on the inner side
inline int planeSign(const std::vector<Vec3>& v, const Triangle& t, Vec3 p) {
  return orient3d(v[t[0]], v[t[1]], v[t[2]], p);
}

// the class of p from the plane of a face its ray from the centre leaves through
inline Location fromExit(int s) {
  return s > 0 ? Location::Inside : (s == 0 ? Location::Boundary : Location::Outside);
}

// tests p against every face, stopping at the first outer side (eq. 2)
template <class Sink>
Location testAll(const std::vector<Vec3>& v, const std::vector<Triangle>& tri, Vec3 p, Sink& sink) {
  bool zero = false;
  const std::uint32_t n = static_cast<std::uint32_t>(tri.size());
  for (std::uint32_t f = 0; f < n; ++f) {
    int s = planeSign(v, tri[f], p);
    sink.face(f, s);
    if (s < 0) return Location::Outside;
    zero |= s == 0;
  }
  return zero ? Location::Boundary : Location::Inside;
}

// Tests p against the listed faces, which include a face its ray from the centre leaves
// through: any outer side is Outside, else any plane through p is Boundary, else Inside.
template <class Sink>
Location testList(const std::vector<Vec3>& v, const std::vector<Triangle>& tri,
                  const std::uint32_t* first, const std::uint32_t* last, Vec3 p, Sink& sink) {
  bool zero = false;
  for (const std::uint32_t* it = first; it != last; ++it) {
    int s = planeSign(v, tri[*it], p);
    sink.face(*it, s);
    if (s < 0) return Location::Outside;
    zero |= s == 0;
  }
  return zero ? Location::Boundary : Location::Inside;
}

// Remembering stochastic walk over face adjacency toward the face whose cone from the
// centre c holds the direction p - c. At a face, the edges are tried from a random one (the
// edge just crossed is skipped); orient3d(c, a, b, p) > 0 means the direction lies beyond
// edge (a, b), and the walk crosses it. A face where no edge says so holds the direction in
// its closed cone: the ray from c through p leaves the polyhedron through it. Returns that
// face, or kNone after `cap` faces. Deterministic: the random source restarts per query.
template <class Sink>
std::uint32_t walkToExit(const std::vector<Vec3>& v, const std::vector<Triangle>& tri,
                         const std::vector<Triangle>& nb, Vec3 c, Vec3 p, std::uint32_t start,
                         std::uint32_t cap, Sink& sink) {
  std::uint32_t face = start, from = kNone;
  std::uint32_t rng = 0x9e3779b9u;
  for (std::uint32_t visited = 0; visited < cap; ++visited) {
    sink.visit(face);
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    const std::uint32_t r = rng % 3;
    std::uint32_t next = kNone;
    for (std::uint32_t j = 0; j < 3 && next == kNone; ++j) {
      const std::uint32_t k = (r + j) % 3;
      if (nb[face][k] == from) continue;
      const Triangle& t = tri[face];
      int s = orient3d(c, v[t[k]], v[t[(k + 1) % 3]], p);
      sink.step(face, static_cast<std::uint8_t>(k), s);
      if (s > 0) next = nb[face][k];
    }
    if (next == kNone) return face;
    from = face;
    face = next;
  }
  return kNone;
}

using detail::bytesOf;

// statistics shared by every method
Stats3D baseStats(std::size_t faces, std::size_t vertices, std::size_t bytes, double buildSeconds) {
  Stats3D s;
  s.faces = faces;
  s.vertices = vertices;
  s.bytes = bytes;
  s.bytesPerFace = faces ? static_cast<double>(bytes) / static_cast<double>(faces) : 0.0;
  s.buildSeconds = buildSeconds;
  return s;
}

}  // namespace

// === halfspace

HalfspaceLocator::HalfspaceLocator(const ConvexPolyhedron& polyhedron) {
  auto t0 = Clock::now();
  v_.assign(polyhedron.vertices().begin(), polyhedron.vertices().end());
  tri_.assign(polyhedron.triangles().begin(), polyhedron.triangles().end());
  buildSeconds_ = secondsSince(t0);
}

Location HalfspaceLocator::locate(Vec3 p) const noexcept {
  NoSink sink;
  if (!finite(p)) return Location::Outside;
  return testAll(v_, tri_, p, sink);
}

void HalfspaceLocator::locate(std::span<const Vec3> points,
                              std::span<Location> out) const noexcept {
  detail::locateEach(*this, points, out);
}

Trace3D HalfspaceLocator::trace(Vec3 p) const {
  Trace3D t;
  t.method = Method3D::Halfspace;
  TraceSink sink{t};
  if (!finite(p)) {
    sink.nonFinite();
    t.result = Location::Outside;
    return t;
  }
  t.result = testAll(v_, tri_, p, sink);
  return t;
}

Stats3D HalfspaceLocator::stats() const {
  return baseStats(tri_.size(), v_.size(), sizeof(*this) + bytesOf(v_) + bytesOf(tri_),
                   buildSeconds_);
}

// === walk

WalkLocator::WalkLocator(const ConvexPolyhedron& polyhedron) {
  auto t0 = Clock::now();
  v_.assign(polyhedron.vertices().begin(), polyhedron.vertices().end());
  tri_.assign(polyhedron.triangles().begin(), polyhedron.triangles().end());
  nb_.assign(polyhedron.neighbours().begin(), polyhedron.neighbours().end());
  centre_ = polyhedron.centre();
  const std::size_t n = tri_.size();
  cap_ =
      static_cast<std::uint32_t>(std::min<double>(64 + 8 * std::sqrt(static_cast<double>(n)), 1e9));
  if (centre_) {
    // jump and walk: about F^(1/3) start faces spread over the list; a query starts from the
    // one whose direction from the centre is closest to its own
    const std::size_t k = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::cbrt(static_cast<double>(n))), 1, 1024);
    const Vec3 c = *centre_;
    for (std::size_t i = 0; i < k; ++i) {
      const std::uint32_t f = static_cast<std::uint32_t>(i * n / k);
      const Triangle& t = tri_[f];
      double d[3] = {0, 0, 0};
      for (std::uint32_t w : t) {
        d[0] += (v_[w].x - c.x) / 3;
        d[1] += (v_[w].y - c.y) / 3;
        d[2] += (v_[w].z - c.z) / 3;
      }
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (!(len > 0) || !std::isfinite(len)) continue;
      starts_.push_back(f);
      startDir_.push_back({static_cast<float>(d[0] / len), static_cast<float>(d[1] / len),
                           static_cast<float>(d[2] / len)});
    }
    if (starts_.empty()) starts_.push_back(0), startDir_.push_back({1, 0, 0});
  }
  buildSeconds_ = secondsSince(t0);
}

template <class Sink>
Location WalkLocator::run(Vec3 p, Sink& sink) const noexcept {
  if (!finite(p)) {
    sink.nonFinite();
    return Location::Outside;
  }
  if (!centre_) {
    sink.fallback();
    return testAll(v_, tri_, p, sink);
  }
  const Vec3 c = *centre_;
  const double dx = p.x - c.x, dy = p.y - c.y, dz = p.z - c.z;
  std::uint32_t start = starts_[0];
  if (std::isfinite(dx) && std::isfinite(dy) && std::isfinite(dz)) {
    // the start choice is a heuristic only; exactness comes from the walk's predicates
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < starts_.size(); ++k) {
      const double dot = dx * startDir_[k][0] + dy * startDir_[k][1] + dz * startDir_[k][2];
      if (dot > best) {
        best = dot;
        start = starts_[k];
      }
    }
  }
  const std::uint32_t exit = walkToExit(v_, tri_, nb_, c, p, start, cap_, sink);
  if (exit == kNone) {
    sink.fallback();
    return testAll(v_, tri_, p, sink);
  }
  const int s = planeSign(v_, tri_[exit], p);
  sink.face(exit, s);
  return fromExit(s);
}

Location WalkLocator::locate(Vec3 p) const noexcept {
  NoSink sink;
  return run(p, sink);
}

void WalkLocator::locate(std::span<const Vec3> points, std::span<Location> out) const noexcept {
  detail::locateEach(*this, points, out);
}

Trace3D WalkLocator::trace(Vec3 p) const {
  Trace3D t;
  t.method = Method3D::Walk;
  t.centre = centre_;
  TraceSink sink{t};
  t.result = run(p, sink);
  return t;
}

Stats3D WalkLocator::stats() const {
  Stats3D s = baseStats(tri_.size(), v_.size(),
                        sizeof(*this) + bytesOf(v_) + bytesOf(tri_) + bytesOf(nb_) +
                            bytesOf(starts_) + bytesOf(startDir_),
                        buildSeconds_);
  s.centred = centre_.has_value();
  return s;
}

// === cubemap
//
// Coordinates. For d = p - c, the major axis a is the first of x, y, z with the largest
// |d_a|; the cube face is 2a (d_a > 0) or 2a + 1 (d_a < 0); with (u, v) = (a + 1, a + 2)
// mod 3, the face coordinates are s = d_u / |d_a| and t = d_v / |d_a| in [-1, 1], computed
// as d_u * (1 / |d_a|): within 2 ulps of the quotient, perhaps 1 + 1 ulp in size (indices are
// clamped to the grid). At level k a face has n_k = G 2^k cells per side; cell (i, j) is
// s in [-1 + i / K_k, -1 + (i + 1) / K_k], t likewise, with K_k = n_k / 2, and the index
// of a coordinate is floor((s + 1) K_k) clamped to n_k - 1. The query computes it once at
// the deepest level D, as floor((s + 1) K_D) with K_D = K_k 2^(D - k); scaling by a power of
// two is exact, so shifting right by D - k gives the index at level k, consistent across
// levels. The computed (s, t) is within a few ulps of the exact direction's, even where the
// computed major axis differs from the exact one (then the exact direction lies just past
// the cube edge, at |s| <= 1 + a few ulps, still in the face's plane).
//
// Build. A face (a, b, c') seen from the centre spans the cone {w : n_i . w >= 0, i = 0..2}
// with n_i = (v_i - c) x (v_(i+1) - v_i) (it is positively oriented from c). On cube face
// (a, sigma), with w = (sigma, s, t), each n_i . w >= 0 is a half-plane in (s, t). Computed
// in floating point, n_i has an error we bound (kNormalError times its permanent); relaxing
// each half-plane by that bound, plus kSlack per unit of its (s, t) gradient, and clipping
// the square [-1 - kReach, 1 + kReach]^2 by them gives a polygon P that contains a disc of
// radius about kSlack around every exact point of the cone's section. A face is listed in
// every cell whose square, grown by kReach = kMargin + kSlack, meets P (rasterised row by
// row, P being convex up to rounding far below kSlack).
//
// Why the query is exact. Let p != c, and let T be a face through which the ray from c
// through p leaves the polyhedron (one exists: c is strictly inside). The exact direction of
// p - c lies in T's cone, at a point w* of the computed cube face's plane that is within a
// few ulps of the computed (s, t), hence inside the computed cell's square grown by
// kMargin. The disc of radius kSlack around w* then lies in P and in the square grown by
// kReach, so T is listed in that cell. The ray meets T at the surface point y. If p is
// strictly inside, it is strictly inside every face plane: all signs positive, Inside. If p
// is on the surface, p = y lies in T's plane (sign 0) and on the inner side of every plane:
// Boundary. If p is outside, p lies beyond y on the ray, and T's plane, which has c strictly
// inside, separates them: T's sign is negative, Outside. A negative sign for any listed face
// is Outside in any case. So "any negative: Outside; else any zero: Boundary; else Inside"
// over the listed faces is exact. A crowded cell is searched by a walk from one of its
// faces, which ends at such a face T; if the walk runs too long the cell's list is tested.

namespace {

constexpr double kEps = 0x1p-53;
// how far, in (s, t) units, a query's computed coordinates may stray: far above their error
constexpr double kMargin = 0x1p-40;
// extra room that keeps rounding in the build's clipping from losing a face
constexpr double kSlack = 0x1p-42;
constexpr double kReach = kMargin + kSlack;
// error of a computed edge-plane normal component, per unit of its permanent
constexpr double kNormalError = 5.25 * kEps;
// absolute slack for products that underflow in the scaled normals
constexpr double kUnderflow = 0x1p-1060;
// relative margin by which all three vertices must miss a cube face to skip it
constexpr double kReject = 0x1p-30;
// the inner-node mark in Node::count
constexpr std::uint32_t kInner = 0xffffffffu;
// the deepest quadtree level, and the most cells per side at any level (2^31)
constexpr int kMaxLevel = 30;
constexpr int kMaxSideBits = 31;
// the largest G accepted
constexpr std::uint32_t kMaxResolution = 8192;
// The default G is at least this: where the faces are few, each cell's radii then bound
// only the part of a face the cell sees, and a thinner shell is left to the face tests (on
// an 80-face geodesic sphere, 2.3% of random points against 5.4% at G = 3); the grid still
// fits the constant part of the memory budget.
constexpr std::uint32_t kSmallestDefault = 16;
// the part of the memory budget that does not grow with the faces
constexpr std::size_t kFixedBudget = 32 * 1024;

// a convex polygon in (s, t) with at most 4 + 3 vertices
struct Poly {
  Vec2 p[8];
  int n = 0;
};

// a face's cone from the centre: edge-plane normals with their error bounds, and the vertex
// directions (all scaled by a power of two)
struct Cone {
  double n[3][3];
  double bound[3];
  double d[3][3];
};

// exact scaling by a power of two: x * 2^shift
struct PowerOfTwo {
  int shift = 0;
  double factor = 1.0;  // 2^shift, when that is a normal double
  explicit PowerOfTwo(int s) : shift(s), factor(s > -1000 && s < 1000 ? std::ldexp(1.0, s) : 0.0) {}
  double operator()(double x) const { return factor != 0.0 ? x * factor : std::ldexp(x, shift); }
};

// the cone of face t seen from c, scaled exactly; false when something is not finite
bool coneOf(const std::vector<Vec3>& v, const Triangle& t, Vec3 c, const PowerOfTwo& scale,
            Cone& k) {
  for (int i = 0; i < 3; ++i) {
    const Vec3 p = v[t[i]];
    k.d[i][0] = scale(p.x - c.x);
    k.d[i][1] = scale(p.y - c.y);
    k.d[i][2] = scale(p.z - c.z);
  }
  bool ok = true;
  for (int i = 0; i < 3; ++i) {
    const Vec3 p = v[t[i]], q = v[t[(i + 1) % 3]];
    const double* d = k.d[i];
    const double e[3] = {scale(q.x - p.x), scale(q.y - p.y), scale(q.z - p.z)};
    double perm = 0;
    for (int a = 0; a < 3; ++a) {
      const int u = (a + 1) % 3, w = (a + 2) % 3;
      const double l = d[u] * e[w], r = d[w] * e[u];
      k.n[i][a] = l - r;
      perm += std::fabs(l) + std::fabs(r);
      ok &= std::isfinite(k.n[i][a]);
    }
    k.bound[i] = kNormalError * perm + kUnderflow;
    ok &= std::isfinite(perm);
  }
  return ok;
}

// keeps the part of P where a + b s + c t >= 0 (Sutherland-Hodgman)
void clip(Poly& P, double a, double b, double c) {
  Poly out;
  for (int i = 0; i < P.n; ++i) {
    const Vec2 p = P.p[i], q = P.p[(i + 1) % P.n];
    const double fp = a + b * p.x + c * p.y, fq = a + b * q.x + c * q.y;
    if (fp >= 0) out.p[out.n++] = p;
    if ((fp >= 0) != (fq >= 0)) {
      const double r = fp / (fp - fq);
      out.p[out.n++] = {p.x + r * (q.x - p.x), p.y + r * (q.y - p.y)};
    }
  }
  P = out;
}

// The polygon P of the face's cone on cube face `face` (see the notes above); false when
// the cone surely misses the face's square.
bool onCubeFace(const Cone& k, int face, Poly& P) {
  const int a = face / 2, u = (a + 1) % 3, w = (a + 2) % 3;
  const double sigma = (face & 1) ? -1.0 : 1.0;
  // quick rejection: all three directions strictly on the outer side of one of the
  // pyramid's bounding planes (or behind it), by a relative margin far above rounding
  for (int rule = 0; rule < 5; ++rule) {
    bool all = true;
    for (int i = 0; i < 3 && all; ++i) {
      const double* d = k.d[i];
      const double da = sigma * d[a];
      const double f = rule == 0   ? da
                       : rule == 1 ? da + d[u]
                       : rule == 2 ? da - d[u]
                       : rule == 3 ? da + d[w]
                                   : da - d[w];
      all = f < -kReject * (std::fabs(d[a]) + std::fabs(d[u]) + std::fabs(d[w]));
    }
    if (all) return false;
  }
  const double L = 1 + kReach;
  P.n = 4;
  P.p[0] = {-L, -L};
  P.p[1] = {L, -L};
  P.p[2] = {L, L};
  P.p[3] = {-L, L};
  for (int i = 0; i < 3; ++i) {
    const double alpha = sigma * k.n[i][a], beta = k.n[i][u], gamma = k.n[i][w];
    const double relax = k.bound[i] + kSlack * (std::fabs(beta) + std::fabs(gamma)) +
                         4 * kEps * (std::fabs(alpha) + std::fabs(beta) + std::fabs(gamma));
    clip(P, alpha + relax, beta, gamma);
    if (P.n == 0) return false;
  }
  return true;
}

// The bounding box, in (s, t) of cube face `face`, of face t's projection when all three
// vertices lie strictly in front of that cube face (then the projection is the triangle of
// the projected vertices), grown by far more than the rounding of their coordinates; as a
// polygon (corners 0 and 2 are the low and high ones). False otherwise.
bool projectedBox(const std::vector<Vec3>& v, const Triangle& t, Vec3 c, int face, Poly& B) {
  const int a = face / 2, u = (a + 1) % 3, w = (a + 2) % 3;
  const double sigma = (face & 1) ? -1.0 : 1.0;
  double lo[2] = {0, 0}, hi[2] = {0, 0}, big = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec3 p = v[t[i]];
    const double d[3] = {p.x - c.x, p.y - c.y, p.z - c.z};
    const double major = sigma * d[a];
    if (!(major > 0)) return false;
    const double st[2] = {d[u] / major, d[w] / major};
    for (int k = 0; k < 2; ++k) {
      lo[k] = i ? std::min(lo[k], st[k]) : st[k];
      hi[k] = i ? std::max(hi[k], st[k]) : st[k];
      big = std::max(big, std::fabs(st[k]));
    }
  }
  if (!(big < 0x1p40)) return false;  // also false for NaN
  const double grow = 0x1p-50 * (1 + big);
  B.n = 4;
  B.p[0] = {lo[0] - grow, lo[1] - grow};
  B.p[1] = {hi[0] + grow, lo[1] - grow};
  B.p[2] = {hi[0] + grow, hi[1] + grow};
  B.p[3] = {lo[0] - grow, hi[1] + grow};
  return true;
}

// Narrows [first, last] to the cells, at the level with K = (cells per side) / 2, whose
// range of one coordinate grown by kReach meets [lo, hi] (empty when first > last).
inline void cellRange(double lo, double hi, double K, std::int64_t& first, std::int64_t& last) {
  first = std::max(first, static_cast<std::int64_t>(std::ceil((lo - kReach + 1) * K)) - 1);
  last = std::min(last, static_cast<std::int64_t>(std::floor((hi + kReach + 1) * K)));
}

// Calls cell(i, j) for every cell at the level with K = (cells per side) / 2, within the
// index window [i0, i1] x [j0, j1], whose square grown by kReach meets P.
template <class F>
void rasterise(const Poly& P, double K, std::int64_t i0, std::int64_t i1, std::int64_t j0,
               std::int64_t j1, F&& cell) {
  double tmin = P.p[0].y, tmax = P.p[0].y;
  for (int k = 1; k < P.n; ++k) {
    tmin = std::min(tmin, P.p[k].y);
    tmax = std::max(tmax, P.p[k].y);
  }
  std::int64_t jlo = j0, jhi = j1;
  cellRange(tmin, tmax, K, jlo, jhi);
  for (std::int64_t j = jlo; j <= jhi; ++j) {
    const double ta = -1 + static_cast<double>(j) / K - kReach;
    const double tb = -1 + static_cast<double>(j + 1) / K + kReach;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int k = 0; k < P.n; ++k) {
      const Vec2 p = P.p[k], q = P.p[(k + 1) % P.n];
      if (p.y >= ta && p.y <= tb) {
        lo = std::min(lo, p.x);
        hi = std::max(hi, p.x);
      }
      for (double y : {ta, tb})
        if ((p.y < y) != (q.y < y)) {
          const double x = p.x + (y - p.y) / (q.y - p.y) * (q.x - p.x);
          lo = std::min(lo, x);
          hi = std::max(hi, x);
        }
    }
    if (lo > hi) continue;
    std::int64_t ilo = i0, ihi = i1;
    cellRange(lo, hi, K, ilo, ihi);
    for (std::int64_t i = ilo; i <= ihi; ++i) cell(i, j);
  }
}

// the direction (on the cube of half-size 1 around the centre) of point (s, t) of a face
Vec3 cubeDirection(int face, double s, double t) {
  const int a = face / 2;
  double w[3];
  w[a] = (face & 1) ? -1.0 : 1.0;
  w[(a + 1) % 3] = s;
  w[(a + 2) % 3] = t;
  return {w[0], w[1], w[2]};
}

// the deepest level for base resolution g: at most 2^31 cells per side
int depthFor(std::uint32_t g) {
  const int bits = static_cast<int>(std::bit_width(g - 1));
  return std::min(kMaxLevel, kMaxSideBits - bits);
}

}  // namespace

CubemapLocator::CubemapLocator(const ConvexPolyhedron& polyhedron, std::uint32_t resolution) {
  auto t0 = Clock::now();
  if (resolution > kMaxResolution)
    throw UsageError("cubemap: the resolution is at most " + std::to_string(kMaxResolution));
  v_.assign(polyhedron.vertices().begin(), polyhedron.vertices().end());
  tri_.assign(polyhedron.triangles().begin(), polyhedron.triangles().end());
  nb_.assign(polyhedron.neighbours().begin(), polyhedron.neighbours().end());
  const std::size_t nf = tri_.size();
  // By default about 4 faces per base cell up to G = 160 (10^5 faces), so that few cells
  // are crowded and refined and a batch meets few inner nodes; beyond, about 8, which
  // keeps the build of 10^6 faces well under a second.
  const double perCell8 = std::sqrt(static_cast<double>(nf) / 8),
               perCell4 = std::min(std::sqrt(static_cast<double>(nf) / 4), 160.0);
  g_ = resolution ? resolution
                  : static_cast<std::uint32_t>(std::clamp<double>(
                        std::round(std::max(perCell8, perCell4)), kSmallestDefault,
                        kMaxResolution));
  std::optional<Vec3> centre = polyhedron.centre();
  double extent = 0;
  if (centre) {
    c_ = *centre;
    for (const Vec3& p : v_)
      extent =
          std::max({extent, std::fabs(p.x - c_.x), std::fabs(p.y - c_.y), std::fabs(p.z - c_.z)});
  }
  if (!centre || !std::isfinite(extent) || !(extent > 0)) {
    // no centre (a polyhedron thinner than the double grid), or one so vast that its
    // directions overflow: no cells; every query tests all faces
    g_ = 0;
    buildSeconds_ = secondsSince(t0);
    return;
  }
  half_ = extent;
  const PowerOfTwo scale(-std::ilogb(extent));  // extent scaled into [1, 2)

  // the memory budget for the cells: 120 bytes per face in all, plus 32 KiB (so that small
  // polyhedra, the ones a lecturer draws, still get a grid worth showing, and fast radii)
  const std::size_t fixed = sizeof(*this) + bytesOf(v_) + bytesOf(tri_) + bytesOf(nb_);
  const std::size_t total = 120 * nf + kFixedBudget;
  const std::size_t budget = total > fixed ? total - fixed : 0;

  // calls visit(face index, cube face, polygon) for every cube face a face's cone meets
  auto forEachProjection = [&](auto&& visit) {
    Cone k;
    Poly P;
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (!coneOf(v_, tri_[f], c_, scale, k)) return false;
      for (int cf = 0; cf < 6; ++cf)
        if (onCubeFace(k, cf, P)) visit(f, cf, P);
    }
    return true;
  };

  // === the base grid: count, coarsen until it fits, fill
  while (g_ > 1 && 6 * static_cast<std::size_t>(g_) * g_ * sizeof(Node) > budget) g_ /= 2;
  std::vector<std::uint32_t> count;
  for (;;) {
    depth_ = depthFor(g_);
    const std::size_t cells = 6 * static_cast<std::size_t>(g_) * g_;
    count.assign(cells + 1, 0);
    const double K = g_ / 2.0;
    const std::int64_t last = g_ - 1;
    std::size_t entries = 0;
    bool ok = forEachProjection([&](std::uint32_t, int cf, const Poly& P) {
      rasterise(P, K, 0, last, 0, last, [&](std::int64_t i, std::int64_t j) {
        ++count[static_cast<std::size_t>(cf) * g_ * g_ + static_cast<std::size_t>(j) * g_ + i];
        ++entries;
      });
    });
    if (!ok) {
      g_ = 0;
      buildSeconds_ = secondsSince(t0);
      return;  // a direction overflowed: no cells, as above
    }
    if (g_ == 1 || cells * sizeof(Node) + entries * sizeof(std::uint32_t) <= budget) break;
    g_ = std::max<std::uint32_t>(1, g_ / 2);
  }
  const std::size_t baseCells = 6 * static_cast<std::size_t>(g_) * g_;
  nodes_.resize(baseCells);
  {
    std::uint32_t at = 0;
    for (std::size_t c = 0; c < baseCells; ++c) {
      nodes_[c] = {at, count[c]};
      at += count[c];
    }
    entries_.resize(at);
    std::vector<std::uint32_t> cursor(baseCells);
    for (std::size_t c = 0; c < baseCells; ++c) cursor[c] = nodes_[c].first;
    const double K = g_ / 2.0;
    const std::int64_t last = g_ - 1;
    forEachProjection([&](std::uint32_t f, int cf, const Poly& P) {
      rasterise(P, K, 0, last, 0, last, [&](std::int64_t i, std::int64_t j) {
        entries_[cursor[static_cast<std::size_t>(cf) * g_ * g_ + static_cast<std::size_t>(j) * g_ +
                        i]++] = f;
      });
    });
  }
  count = {};
  centred_ = true;
  scale_ = std::ldexp(static_cast<double>(g_), depth_ - 1);

  // === refine crowded cells into quadtrees, breadth first, while the budget allows
  struct Pending {
    std::uint32_t node;
    std::uint32_t i, j;
    std::uint8_t face, level;
  };
  std::vector<Pending> queue;
  for (std::size_t c = 0; c < baseCells; ++c)
    if (nodes_[c].count > kCrowdedCell3D) {
      const std::uint32_t cf = static_cast<std::uint32_t>(c / (static_cast<std::size_t>(g_) * g_));
      const std::uint32_t rest =
          static_cast<std::uint32_t>(c % (static_cast<std::size_t>(g_) * g_));
      queue.push_back(
          {static_cast<std::uint32_t>(c), rest % g_, rest / g_, static_cast<std::uint8_t>(cf), 0});
    }
  std::size_t live = nodes_.size() * sizeof(Node) + entries_.size() * sizeof(std::uint32_t);
  std::size_t liveEntries = entries_.size();
  // rewrites entries_ with the leaves' lists only
  auto compact = [&]() {
    Table<std::uint32_t> kept;
    kept.reserve(liveEntries);
    for (Node& nd : nodes_) {
      if (nd.count == kInner) continue;
      const std::uint32_t first = static_cast<std::uint32_t>(kept.size());
      kept.insert(kept.end(), entries_.begin() + nd.first, entries_.begin() + nd.first + nd.count);
      nd.first = first;
    }
    entries_.swap(kept);
  };
  // appends the 4 children of `node` (cell i, j at `level` - 1) with their lists; queues the
  // crowded ones; returns the index of the first
  auto addChildren = [&](std::uint32_t node, std::int64_t i0, std::int64_t j0, std::uint8_t face,
                         int level, std::vector<std::uint32_t>(&lists)[4]) {
    const std::uint32_t first = static_cast<std::uint32_t>(nodes_.size());
    for (int c = 0; c < 4; ++c) {
      nodes_.push_back({static_cast<std::uint32_t>(entries_.size()),
                        static_cast<std::uint32_t>(lists[c].size())});
      entries_.insert(entries_.end(), lists[c].begin(), lists[c].end());
      if (lists[c].size() > kCrowdedCell3D)
        queue.push_back(
            {first + static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(i0 + (c & 1)),
             static_cast<std::uint32_t>(j0 + (c >> 1)), face, static_cast<std::uint8_t>(level)});
    }
    nodes_[node] = {first, kInner};
    return first;
  };
  std::vector<std::uint32_t> small, large;  // faces placed by their boxes, and the others
  std::vector<std::array<double, 4>> smallBox;
  std::vector<Poly> largePoly;
  std::vector<std::uint32_t> lists[kMaxLevel + 1][4];
  Cone k;
  Poly P, B;
  // the box (s0, s1, t0, t1) as a polygon
  auto boxPoly = [&](const std::array<double, 4>& b) {
    B.n = 4;
    B.p[0] = {b[0], b[2]}, B.p[1] = {b[1], b[2]}, B.p[2] = {b[1], b[3]}, B.p[3] = {b[0], b[3]};
    return B;
  };
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const Pending q = queue[head];
    if (q.level >= depth_) continue;
    const Node parent = nodes_[q.node];
    const double K1 = std::ldexp(g_ / 2.0, q.level + 1);
    // sort the faces: a small face in front of the cube face goes by its box (a superset of
    // its projection, so still conservative); others by their polygon
    small.clear(), large.clear(), smallBox.clear(), largePoly.clear();
    std::array<double, 4> all = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
    for (std::uint32_t e = parent.first; e < parent.first + parent.count; ++e) {
      const std::uint32_t f = entries_[e];
      if (projectedBox(v_, tri_[f], c_, q.face, B) && B.p[2].x - B.p[0].x <= 1 / K1 &&
          B.p[2].y - B.p[0].y <= 1 / K1) {
        small.push_back(f);
        smallBox.push_back({B.p[0].x, B.p[2].x, B.p[0].y, B.p[2].y});
        all = {std::min(all[0], B.p[0].x), std::max(all[1], B.p[2].x), std::min(all[2], B.p[0].y),
               std::max(all[3], B.p[2].y)};
      } else if (coneOf(v_, tri_[f], c_, scale, k) && onCubeFace(k, q.face, P)) {
        large.push_back(f);
        largePoly.push_back(P);
      }
    }
    // a chain: while all the small faces stay in one cell, descend several levels at once;
    // only the large faces are placed in the cells beside the chain
    int deepest = q.level;
    if (small.size() > kCrowdedCell3D) {
      for (int level = q.level + 1; level <= depth_; ++level) {
        const double K = std::ldexp(g_ / 2.0, level);
        const std::int64_t n = static_cast<std::int64_t>(g_) << level;
        std::int64_t i0 = 0, i1 = n - 1, j0 = 0, j1 = n - 1;
        cellRange(all[0], all[1], K, i0, i1);
        cellRange(all[2], all[3], K, j0, j1);
        if (i0 != i1 || j0 != j1) break;
        deepest = level;
      }
    }
    const int levels = deepest >= q.level + 2 ? deepest - q.level : 1;
    std::size_t added = 0;
    std::int64_t ci = q.i, cj = q.j;  // the chain's cell at the level above
    for (int l = 0; l < levels; ++l) {
      const int level = q.level + 1 + l;
      const double K = std::ldexp(g_ / 2.0, level);
      const std::int64_t i0 = 2 * ci, j0 = 2 * cj;
      for (auto& list : lists[l]) list.clear();
      auto placer = [&](std::uint32_t f) {
        return [&, f](std::int64_t i, std::int64_t j) {
          lists[l][(j - j0) * 2 + (i - i0)].push_back(f);
        };
      };
      for (std::size_t m = 0; m < large.size(); ++m)
        rasterise(largePoly[m], K, i0, i0 + 1, j0, j0 + 1, placer(large[m]));
      if (l + 1 == levels) {
        for (std::size_t m = 0; m < small.size(); ++m)
          rasterise(boxPoly(smallBox[m]), K, i0, i0 + 1, j0, j0 + 1, placer(small[m]));
      } else {
        // the chain's cell at this level: the one cell every small box meets
        std::int64_t i1 = i0 + 1, j1 = j0 + 1, ii = i0, jj = j0;
        cellRange(all[0], all[1], K, ii, i1);
        cellRange(all[2], all[3], K, jj, j1);
        ci = ii, cj = jj;
        lists[l][(cj - j0) * 2 + (ci - i0)].clear();  // an inner node: its faces go deeper
      }
      for (auto& list : lists[l]) added += list.size();
    }
    if (levels == 1) {
      // an ordinary split: stop where a child keeps every face while the others share many
      // (a vertex all of them meet, which no split separates; a walk searches it instead)
      std::size_t most = 0;
      for (auto& list : lists[0]) most = std::max(most, list.size());
      if (most == parent.count && added - most > parent.count / 2) continue;
    }
    const std::size_t grown = live + 4 * sizeof(Node) * levels + added * sizeof(std::uint32_t) -
                              parent.count * sizeof(std::uint32_t);
    if (grown > budget || entries_.size() + added > std::numeric_limits<std::uint32_t>::max())
      break;
    // commit, top down; an inner chain cell gets its children at the next level
    std::uint32_t node = q.node;
    ci = q.i, cj = q.j;
    for (int l = 0; l < levels; ++l) {
      const int level = q.level + 1 + l;
      const std::uint32_t first = addChildren(node, 2 * ci, 2 * cj, q.face, level, lists[l]);
      if (l + 1 == levels) break;
      const double K = std::ldexp(g_ / 2.0, level);
      std::int64_t i1 = 2 * ci + 1, j1 = 2 * cj + 1, ii = 2 * ci, jj = 2 * cj;
      cellRange(all[0], all[1], K, ii, i1);
      cellRange(all[2], all[3], K, jj, j1);
      node = first + static_cast<std::uint32_t>((jj - 2 * cj) * 2 + (ii - 2 * ci));
      ci = ii, cj = jj;
    }
    live = grown;
    liveEntries = liveEntries + added - parent.count;
    if (entries_.size() > 2 * liveEntries + (1u << 20)) compact();
  }
  compact();
  nodes_.shrink_to_fit();
  entries_.shrink_to_fit();
  buildRadii();
  buildSeconds_ = secondsSince(t0);
}

namespace {

// A lower bound on the squared distance from c to the plane of face (a, b, d), for c strictly
// on its inner side (0 when it cannot be bounded). In long double (64-bit significand, an
// exponent range no product of doubles leaves): the triple product's rounding error is at
// most 8 units of its permanent, the normal's length is bounded above component by
// component; what rounding remains, the radius slack covers.
double planeDistance2Below(Vec3 a, Vec3 b, Vec3 d, Vec3 c) {
  using L = long double;
  constexpr L eps = std::numeric_limits<L>::epsilon();  // 2^-63: twice the unit roundoff
  const L ux = L(b.x) - a.x, uy = L(b.y) - a.y, uz = L(b.z) - a.z;
  const L vx = L(d.x) - a.x, vy = L(d.y) - a.y, vz = L(d.z) - a.z;
  const L wx = L(c.x) - a.x, wy = L(c.y) - a.y, wz = L(c.z) - a.z;
  const L nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const L px = std::fabs(uy * vz) + std::fabs(uz * vy),
          py = std::fabs(uz * vx) + std::fabs(ux * vz),
          pz = std::fabs(ux * vy) + std::fabs(uy * vx);
  // orient3d(a, b, d, c) > 0 on the inner side is the triple product (b-a)x(d-a).(c-a) < 0
  const L det = -(nx * wx + ny * wy + nz * wz);
  const L permanent = px * std::fabs(wx) + py * std::fabs(wy) + pz * std::fabs(wz);
  const L num = det - 8 * eps * permanent;
  if (!(num > 0)) return 0.0;
  const L mx = std::fabs(nx) + 4 * eps * px, my = std::fabs(ny) + 4 * eps * py,
          mz = std::fabs(nz) + 4 * eps * pz;
  const L len2 = mx * mx + my * my + mz * mz;
  if (!(len2 > 0)) return 0.0;
  return static_cast<double>(num / len2 * num);
}

// the squared distance of p from c in long double, rounded to double
double distance2Long(Vec3 p, Vec3 c) {
  using L = long double;
  const L dx = L(p.x) - c.x, dy = L(p.y) - c.y, dz = L(p.z) - c.z;
  return static_cast<double>(dx * dx + dy * dy + dz * dz);
}

// Tighter bounds for one cell and one face listed in it. The rays from c whose directions
// the query maps to the cell form a pyramid: the cone over the cell's square on its cube
// face, widened far beyond the query's rounding. Where all four corner rays meet the face's
// plane ahead of c, the plane's part inside the pyramid is the quadrilateral Q of the four
// hits, and every exit point through this face of a point mapped to the cell lies in Q. Over
// Q the distance from c is largest at a corner, and smallest at the foot of the
// perpendicular from c if Q holds it, else on one of Q's sides. All in long double; the ends
// are bounded with the products' error bounds (the edge normal to 4 units of its
// permanent, the triple product to 8), and a face whose normal or corner rays are too badly
// conditioned for that keeps its whole-face bounds. Lowers out2 and raises in2 only where
// the tighter bound is sure.
struct CellPyramid {
  long double d[4][3];  // the corner directions, widened, counter-clockwise around the cell
  long double len[4];   // their lengths
  int a, u, w;          // the cube face's major and minor axes
  long double sigma;
  long double s0, s1, t0, t1;  // the widened square
};

// Returns the bound on the squared distance to the face's plane along every ray of the
// pyramid (infinity where some corner ray misses the plane or the face is ill-conditioned).
double pieceBounds3D(const CellPyramid& cp, Vec3 va, Vec3 vb, Vec3 vd, Vec3 c, double& in2,
                     double& out2) {
  using L = long double;
  constexpr L eps = std::numeric_limits<L>::epsilon();
  const L u[3] = {L(vb.x) - va.x, L(vb.y) - va.y, L(vb.z) - va.z};
  const L v[3] = {L(vd.x) - va.x, L(vd.y) - va.y, L(vd.z) - va.z};
  const L w[3] = {L(c.x) - va.x, L(c.y) - va.y, L(c.z) - va.z};
  const L n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const L pn[3] = {std::fabs(u[1] * v[2]) + std::fabs(u[2] * v[1]),
                   std::fabs(u[2] * v[0]) + std::fabs(u[0] * v[2]),
                   std::fabs(u[0] * v[1]) + std::fabs(u[1] * v[0])};
  // n's components are within 4 eps of their permanents; its length at least nNorm
  const L nErr[3] = {4 * eps * pn[0], 4 * eps * pn[1], 4 * eps * pn[2]};
  const L nNorm = std::fabs(n[0]) + std::fabs(n[1]) + std::fabs(n[2]);
  constexpr double kNone2 = HUGE_VAL;
  if (!(nErr[0] + nErr[1] + nErr[2] <= 0x1p-40L * nNorm)) return kNone2;  // a nearly flat triangle
  // the outward plane offset N = n . (a - c) > 0, within 8 eps of its permanent
  const L N = -(n[0] * w[0] + n[1] * w[1] + n[2] * w[2]);
  const L NErr = 8 * eps * (pn[0] * std::fabs(w[0]) + pn[1] * std::fabs(w[1]) + pn[2] * std::fabs(w[2]));
  if (!(N - NErr > 0)) return kNone2;
  const L nLen = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  L hit[4][3], farthest = 0;
  for (int k = 0; k < 4; ++k) {
    const L* d = cp.d[k];
    const L D = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
    const L DErr = (nErr[0] + 2 * eps * std::fabs(n[0])) * std::fabs(d[0]) +
                   (nErr[1] + 2 * eps * std::fabs(n[1])) * std::fabs(d[1]) +
                   (nErr[2] + 2 * eps * std::fabs(n[2])) * std::fabs(d[2]);
    // the corner ray must meet the plane ahead, not nearly along it
    if (!(D - DErr > 0x1p-20L * nLen * cp.len[k])) return kNone2;
    const L lambdaHi = (N + NErr) / (D - DErr);
    farthest = std::max(farthest, lambdaHi * cp.len[k]);
    const L lambda = N / D;
    for (int i = 0; i < 3; ++i) hit[k][i] = lambda * d[i];
  }
  // rounding in the hits and in what follows stays below 2^-40 of the farthest
  const L slack = 0x1p-36L * farthest;
  farthest += slack;
  const double plane2 = static_cast<double>(farthest * farthest);
  out2 = std::min(out2, plane2);
  // the foot of the perpendicular lies along n from c: is its direction in the pyramid?
  // (tested with room far beyond n's error, so that "not in it" is sure)
  const L major = cp.sigma * n[cp.a];
  constexpr L kRoom = 0x1p-20L;
  if (major > 0) {
    const L fs = n[cp.u] / major, ft = n[cp.w] / major;
    if (fs >= cp.s0 - kRoom && fs <= cp.s1 + kRoom && ft >= cp.t0 - kRoom && ft <= cp.t1 + kRoom)
      return plane2;  // Q may hold the foot: the plane's distance stands
  }
  L nearest = std::numeric_limits<L>::infinity();
  for (int k = 0; k < 4; ++k) {
    const L* A = hit[k];
    const L* B = hit[(k + 1) % 4];
    const L e[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]};
    const L e2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    L t = e2 > 0 ? -(A[0] * e[0] + A[1] * e[1] + A[2] * e[2]) / e2 : 0;
    t = std::clamp(t, L(0), L(1));
    const L x = A[0] + t * e[0], y = A[1] + t * e[1], z = A[2] + t * e[2];
    nearest = std::min(nearest, std::sqrt(x * x + y * y + z * z));
  }
  nearest -= slack;
  if (nearest > 0) in2 = std::max(in2, static_cast<double>(nearest * nearest));
  return plane2;
}

}  // namespace

template <class Visit>
void CubemapLocator::forEachLeaf(Visit&& visit) const {
  struct Item {
    std::uint32_t node, i, j;
    int level;
  };
  std::vector<Item> stack;
  const std::size_t perFace = static_cast<std::size_t>(g_) * g_;
  for (std::size_t c = 0; c < 6 * perFace; ++c) {
    const int cf = static_cast<int>(c / perFace);
    const std::uint32_t rest = static_cast<std::uint32_t>(c % perFace);
    stack.push_back({static_cast<std::uint32_t>(c), rest % g_, rest / g_, 0});
    while (!stack.empty()) {
      const Item it = stack.back();
      stack.pop_back();
      const Node nd = nodes_[it.node];
      if (nd.count == kInner) {
        for (std::uint32_t k = 4; k-- > 0;)
          stack.push_back({nd.first + k, 2 * it.i + (k & 1), 2 * it.j + (k >> 1), it.level + 1});
        continue;
      }
      visit(it.node, cf, it.level, it.i, it.j);
    }
  }
}

void CubemapLocator::buildRadii() {
  const std::size_t nf = tri_.size();
  std::vector<double> in2(nf), out2(nf);
  std::vector<double> vertex2(v_.size());
  for (std::size_t i = 0; i < v_.size(); ++i) vertex2[i] = distance2Long(v_[i], c_);
  for (std::size_t f = 0; f < nf; ++f) {
    const Triangle& t = tri_[f];
    in2[f] = planeDistance2Below(v_[t[0]], v_[t[1]], v_[t[2]], c_);
    out2[f] = std::max({vertex2[t[0]], vertex2[t[1]], vertex2[t[2]]});
  }
  // A leaf's bounds from its faces' whole-face bounds; where those leave a shell wider than
  // 1/1024 of the radius (faces large against the cell, as on a coarse polyhedron), each
  // face's part inside the cell's pyramid tightens them. Elsewhere the shell is already
  // thin and the tightening would only cost build time.
  auto leaf = [&](std::uint32_t node, int cf, int level, std::uint64_t i, std::uint64_t j) {
    Node& nd = nodes_[node];
    double lo = nd.count ? HUGE_VAL : 0.0, hi = nd.count ? 0.0 : HUGE_VAL;
    for (std::uint32_t e = nd.first; e < nd.first + nd.count; ++e) {
      lo = std::min(lo, in2[entries_[e]]);
      hi = std::max(hi, out2[entries_[e]]);
    }
    if (nd.count && !(hi <= lo * (1 + 0x1p-10))) {
      using L = long double;
      CellPyramid cp;
      cp.a = cf / 2, cp.u = (cp.a + 1) % 3, cp.w = (cp.a + 2) % 3;
      cp.sigma = (cf & 1) ? -1 : 1;
      // the cell's square, widened far beyond the query's error in (s, t) (below 2^-50)
      const L K = std::ldexp(static_cast<L>(g_) / 2, level), widen = 0x1p-30L;
      cp.s0 = L(i) / K - 1 - widen, cp.s1 = L(i + 1) / K - 1 + widen;
      cp.t0 = L(j) / K - 1 - widen, cp.t1 = L(j + 1) / K - 1 + widen;
      const L corner[4][2] = {{cp.s0, cp.t0}, {cp.s1, cp.t0}, {cp.s1, cp.t1}, {cp.s0, cp.t1}};
      for (int k = 0; k < 4; ++k) {
        cp.d[k][cp.a] = cp.sigma;
        cp.d[k][cp.u] = corner[k][0];
        cp.d[k][cp.w] = corner[k][1];
        cp.len[k] = std::sqrt(1 + corner[k][0] * corner[k][0] + corner[k][1] * corner[k][1]);
      }
      // A ray leaves a convex polyhedron at the nearest of the face planes it meets ahead,
      // so a face whose plane every ray of the pyramid meets ahead bounds every exit point
      // of the cell by itself: the smallest such bound serves as well as the largest.
      double tightLo = HUGE_VAL, tightHi = 0.0, anyPlane = HUGE_VAL;
      for (std::uint32_t e = nd.first; e < nd.first + nd.count; ++e) {
        const std::uint32_t f = entries_[e];
        double fIn2 = in2[f], fOut2 = out2[f];
        const Triangle& t = tri_[f];
        anyPlane = std::min(anyPlane, pieceBounds3D(cp, v_[t[0]], v_[t[1]], v_[t[2]], c_, fIn2, fOut2));
        tightLo = std::min(tightLo, fIn2);
        tightHi = std::max(tightHi, fOut2);
      }
      lo = std::max(lo, tightLo);
      hi = std::min({hi, tightHi, anyPlane});
    }
    nd.in2 = detail::innerBound(lo);
    nd.out2 = detail::outerBound(hi);
  };
  for (Node& nd : nodes_)
    if (nd.count == kInner) nd.in2 = nd.out2 = std::numeric_limits<float>::quiet_NaN();
  forEachLeaf(leaf);
}


std::optional<Vec3> CubemapLocator::centre() const noexcept {
  if (!centred_) return std::nullopt;
  return c_;
}

inline int CubemapLocator::aim(Vec3 p, Aim& a) const noexcept {
  if (!centred_) return -1;
  const double d[3] = {p.x - c_.x, p.y - c_.y, p.z - c_.z};
  const double ax = std::fabs(d[0]), ay = std::fabs(d[1]), az = std::fabs(d[2]);
  // one test for the usual point; a sum that overflows (or is NaN) looks closer: p not
  // finite, or the direction overflows
  if (!(ax + ay + az <= std::numeric_limits<double>::max()) &&
      !(ax <= std::numeric_limits<double>::max() && ay <= std::numeric_limits<double>::max() &&
        az <= std::numeric_limits<double>::max()))
    return -1;
  // the dominant axis (x before y before z on ties), without a branch: random directions
  // would mispredict one
  constexpr int kU[3] = {1, 2, 0}, kV[3] = {2, 0, 1};
  const int xWins = static_cast<int>(ax >= ay) & static_cast<int>(ax >= az);
  const int axis = (1 - xWins) * (1 + static_cast<int>(!(ay >= az)));  // arithmetic, no jump
  const double major = d[axis], du = d[kU[axis]], dv = d[kV[axis]];
  if (major == 0) return 0;  // d = 0: p is the centre
  a.face = 2 * axis + (major < 0 ? 1 : 0);
  // one division and two products, within 2 ulps of the quotients; below 2^-1023 the
  // reciprocal overflows, and the quotients are taken as they are
  const double m = std::fabs(major), inv = 1.0 / m;
  if (inv <= std::numeric_limits<double>::max()) {
    a.s = du * inv;
    a.t = dv * inv;
  } else {
    a.s = du / m;
    a.t = dv / m;
  }
  a.d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const std::uint64_t last = (static_cast<std::uint64_t>(g_) << depth_) - 1;
  // (s + 1) * scale_ lies in [0, 2^31]: the signed conversion is exact and needs no branch
  a.X = std::min(static_cast<std::uint64_t>(static_cast<std::int64_t>((a.s + 1) * scale_)), last);
  a.Y = std::min(static_cast<std::uint64_t>(static_cast<std::int64_t>((a.t + 1) * scale_)), last);
  a.node = static_cast<std::uint32_t>(
      (static_cast<std::uint64_t>(a.face) * g_ + (a.Y >> depth_)) * g_ + (a.X >> depth_));
  return 1;
}

inline std::uint32_t CubemapLocator::leafAt(std::uint64_t X, std::uint64_t Y, std::uint32_t node,
                                            int& level) const noexcept {
  while (nodes_[node].count == kInner) {
    ++level;
    const int shift = depth_ - level;
    node = nodes_[node].first +
           static_cast<std::uint32_t>(((Y >> shift) & 1) * 2 + ((X >> shift) & 1));
  }
  return node;
}

std::span<const std::uint32_t> CubemapLocator::cellFaces(Vec3 p) const noexcept {
  Aim a;
  if (aim(p, a) <= 0) return {};
  int level = 0;
  const Node& leaf = nodes_[leafAt(a.X, a.Y, a.node, level)];
  return {entries_.data() + leaf.first, leaf.count};
}

template <class Sink>
Location CubemapLocator::run(Vec3 p, Sink& sink) const noexcept {
  Aim a;
  const int aimed = aim(p, a);
  if (aimed == 0) {
    sink.atCentre();  // strictly inside
    return Location::Inside;
  }
  if (aimed < 0) {
    if (!finite(p)) {
      sink.nonFinite();
      return Location::Outside;
    }
    sink.fallback();  // no centre, or the direction overflows
    return testAll(v_, tri_, p, sink);
  }
  int level = 0;
  const std::uint32_t node = leafAt(a.X, a.Y, a.node, level);
  sink.cell(a.face, level, a.X >> (depth_ - level), a.Y >> (depth_ - level), a.s, a.t);
  return fromLeaf(p, a.d2, nodes_[node], sink);
}

template <class Sink>
Location CubemapLocator::fromLeaf(Vec3 p, double d2, const Node& leaf, Sink& sink) const noexcept {
  const bool decided = detail::radiiDecide(d2, leaf.in2, leaf.out2);
  sink.radius(d2, leaf.in2, leaf.out2, decided);
  if (decided) return detail::insideOrOutside(d2 > static_cast<double>(leaf.out2));
  if constexpr (std::is_same_v<Sink, NoSink>) {
    // Untraced, a leaf that is not crowded: every face's filter, then the answer without a
    // branch on it (inside and outside come at random). A face surely beyond p's side
    // decides Outside, all faces surely on the inner side Inside; the exact tests below
    // only where neither holds.
    if (leaf.count - 1 < kCrowdedCell3D) {
      const std::uint32_t* e = entries_.data() + leaf.first;
      bool beyond = false, allSure = true;
      for (std::uint32_t k = 0; k < leaf.count; ++k) {
        const Triangle& t = tri_[e[k]];
        const auto s = detail::orient3dTerms(v_[t[0]], v_[t[1]], v_[t[2]], p);
        const bool sure = detail::orient3dSure(s);
        beyond |= sure & (s.det < 0);
        allSure &= sure;
      }
      if (beyond | allSure) return detail::insideOrOutside(beyond);
    }
  }
  const std::uint32_t* first = entries_.data() + leaf.first;
  if (leaf.count == 0) {
    sink.fallback();  // cannot happen (every direction leaves through some face); be safe
    return testAll(v_, tri_, p, sink);
  }
  if (leaf.count <= kCrowdedCell3D) return testList(v_, tri_, first, first + leaf.count, p, sink);
  sink.crowded();
  const std::uint32_t exit = walkToExit(v_, tri_, nb_, c_, p, *first, 16 + leaf.count / 4, sink);
  if (exit != kNone) {
    const int sign = planeSign(v_, tri_[exit], p);
    sink.face(exit, sign);
    return fromExit(sign);
  }
  return testList(v_, tri_, first, first + leaf.count, p, sink);
}

Location CubemapLocator::locate(Vec3 p) const noexcept {
  // Most points: aimed at a base cell that is a leaf and decided by its radii (an inner
  // node's NaN radii decide nothing). All in line, no call: a caller's loop of independent
  // points then keeps several cells' memory reads in flight at once.
  Aim a;
  if (aim(p, a) > 0) {
    const Node& nd = nodes_[a.node];
    if (detail::radiiDecide(a.d2, nd.in2, nd.out2))
      return detail::insideOrOutside(a.d2 > static_cast<double>(nd.out2));
  }
  NoSink sink;
  return run(p, sink);
}

namespace {

// the batch's state for one block of points, structure of arrays
constexpr std::size_t kAimBlock = 32;
struct AimBlock {
  std::uint32_t X[kAimBlock], Y[kAimBlock], node[kAimBlock];
  double d2[kAimBlock];
  int level[kAimBlock];  // node's quadtree level
};

// what the vector aim needs of the locator
struct AimParams {
  Vec3 c;
  double scale, last;
  std::uint32_t g;
  int depth;
};

#if defined(__x86_64__)
// The radii stage for 4 points: gathers each base node's two radii (bytes 8..15 of its
// 16), decides as detail::radiiDecide does (the same roundings, no FMA) and writes the
// verdict; lanes without a node, on an inner node (NaN radii) or between the radii are
// appended to `open`.
__attribute__((target("avx2"), always_inline)) inline void decide4(
    __m128i node, __m256d d2, const long long* radii, Location* o, std::size_t j,
    std::uint32_t* open, std::size_t& left) noexcept {
  const __m128i missing = _mm_cmpeq_epi32(node, _mm_set1_epi32(-1));
  // four 8-byte loads (node 0 for lanes without one): on the CPUs measured they beat a
  // gather instruction, whose latency the next stage waits on
  alignas(16) std::uint32_t at[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(at), _mm_andnot_si128(missing, node));
  const __m256i pairs = _mm256_setr_epi64x(radii[2 * std::size_t{at[0]}], radii[2 * std::size_t{at[1]}],
                                           radii[2 * std::size_t{at[2]}], radii[2 * std::size_t{at[3]}]);
  const __m256 both = _mm256_castsi256_ps(
      _mm256_permutevar8x32_epi32(pairs, _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7)));
  const __m256d in2 = _mm256_cvtps_pd(_mm256_castps256_ps128(both));
  const __m256d out2 = _mm256_cvtps_pd(_mm256_extractf128_ps(both, 1));
  const __m256d product = _mm256_mul_pd(_mm256_sub_pd(d2, in2), _mm256_sub_pd(d2, out2));
  const __m256d decided = _mm256_cmp_pd(product, _mm256_setzero_pd(), _CMP_GT_OQ);
  // Outside (2) beyond the outer radius, else Inside (0), as 4 bytes
  const __m128i verdict = _mm256_cvttpd_epi32(
      _mm256_and_pd(_mm256_cmp_pd(d2, out2, _CMP_GT_OQ), _mm256_set1_pd(2.0)));
  const __m128i bytes = _mm_packus_epi16(_mm_packus_epi32(verdict, verdict), verdict);
  const int four = _mm_cvtsi128_si32(bytes);
  std::memcpy(o + j, &four, 4);
  unsigned undecided = static_cast<unsigned>(_mm256_movemask_pd(decided)) ^ 0xfu;
  undecided |= static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(missing)));
  while (undecided) {
    open[left++] = static_cast<std::uint32_t>(j + static_cast<std::size_t>(__builtin_ctz(undecided)));
    undecided &= undecided - 1;
  }
}

// the radii stage over a block the aim has filled, 4 points at a time; returns how many
// points it did (a multiple of 4), the open count in `left`
__attribute__((target("avx2"))) std::size_t decideAvx2(const AimBlock& b, std::size_t m,
                                                       const void* nodes, Location* o,
                                                       std::uint32_t* open,
                                                       std::size_t& left) noexcept {
  const long long* radii = static_cast<const long long*>(nodes) + 1;
  std::size_t j = 0;
  for (; j + 4 <= m; j += 4)
    decide4(_mm_loadu_si128(reinterpret_cast<const __m128i*>(b.node + j)), _mm256_loadu_pd(b.d2 + j),
            radii, o, j, open, left);
  return j;
}

// CubemapLocator::aim for 4 points at a time, in AVX2 (no FMA: every operation rounds as
// the scalar code does, so X, Y, the base cell and d2 are the scalar ones). Lanes the
// scalar code would not aim (not finite, too far, the centre, a reciprocal that overflows)
// get node kNone and go the scalar way. Returns how many points it did (a multiple of 4).
// The radii stage runs after it over the whole block, not 4 points at a time as each 4 are
// aimed: two short loops of independent iterations keep more points in flight than one
// long one (measured 20% faster, on tables in cache too).
__attribute__((target("avx2"))) std::size_t aimAvx2(const Vec3* p, std::size_t m,
                                                    const AimParams& a, AimBlock& b) noexcept {
  const __m256d cx = _mm256_set1_pd(a.c.x), cy = _mm256_set1_pd(a.c.y), cz = _mm256_set1_pd(a.c.z);
  const __m256d sign = _mm256_set1_pd(-0.0),
                big = _mm256_set1_pd(std::numeric_limits<double>::max());
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0), two = _mm256_set1_pd(2.0);
  const __m256d scale = _mm256_set1_pd(a.scale), last = _mm256_set1_pd(a.last);
  const __m128i g = _mm_set1_epi32(static_cast<int>(a.g)), shift = _mm_cvtsi32_si128(a.depth);
  std::size_t j = 0;
  for (; j + 4 <= m; j += 4) {
    // 4 points as 3 loads (x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3), regrouped by coordinate
    const double* q = &p[j].x;
    static_assert(sizeof(Vec3) == 3 * sizeof(double));
    const __m256d v0 = _mm256_loadu_pd(q), v1 = _mm256_loadu_pd(q + 4), v2 = _mm256_loadu_pd(q + 8);
    const __m256d xs = _mm256_permute4x64_pd(
        _mm256_blend_pd(_mm256_blend_pd(v0, v1, 0b0100), v2, 0b0010), _MM_SHUFFLE(1, 2, 3, 0));
    const __m256d ys = _mm256_permute4x64_pd(
        _mm256_blend_pd(_mm256_blend_pd(v0, v1, 0b1001), v2, 0b0100), _MM_SHUFFLE(2, 3, 0, 1));
    const __m256d zs = _mm256_permute4x64_pd(
        _mm256_blend_pd(_mm256_blend_pd(v0, v1, 0b0010), v2, 0b1001), _MM_SHUFFLE(3, 0, 1, 2));
    const __m256d dx = _mm256_sub_pd(xs, cx), dy = _mm256_sub_pd(ys, cy),
                  dz = _mm256_sub_pd(zs, cz);
    const __m256d ax = _mm256_andnot_pd(sign, dx), ay = _mm256_andnot_pd(sign, dy),
                  az = _mm256_andnot_pd(sign, dz);
    const __m256d finite = _mm256_cmp_pd(_mm256_add_pd(_mm256_add_pd(ax, ay), az), big, _CMP_LE_OQ);
    const __m256d xw =
        _mm256_and_pd(_mm256_cmp_pd(ax, ay, _CMP_GE_OQ), _mm256_cmp_pd(ax, az, _CMP_GE_OQ));
    const __m256d yw = _mm256_andnot_pd(xw, _mm256_cmp_pd(ay, az, _CMP_GE_OQ));
    const __m256d major = _mm256_blendv_pd(_mm256_blendv_pd(dz, dy, yw), dx, xw);
    const __m256d du = _mm256_blendv_pd(_mm256_blendv_pd(dx, dz, yw), dy, xw);
    const __m256d dv = _mm256_blendv_pd(_mm256_blendv_pd(dy, dx, yw), dz, xw);
    const __m256d inv = _mm256_div_pd(one, _mm256_andnot_pd(sign, major));
    const __m256d good = _mm256_and_pd(finite, _mm256_cmp_pd(inv, big, _CMP_LE_OQ));
    const __m256d s = _mm256_mul_pd(du, inv), t = _mm256_mul_pd(dv, inv);
    const __m256d d2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                                     _mm256_mul_pd(dz, dz));
    // (s + 1) * scale clamped to the last index, then truncated: as the scalar min after
    // truncation, for values >= 0 (and for the tiny negatives of s = -1 - 1 ulp alike)
    const __m256d fx =
        _mm256_and_pd(good, _mm256_min_pd(_mm256_mul_pd(_mm256_add_pd(s, one), scale), last));
    const __m256d fy =
        _mm256_and_pd(good, _mm256_min_pd(_mm256_mul_pd(_mm256_add_pd(t, one), scale), last));
    const __m128i X = _mm256_cvttpd_epi32(fx), Y = _mm256_cvttpd_epi32(fy);
    const __m256d axis = _mm256_blendv_pd(_mm256_blendv_pd(two, one, yw), zero, xw);
    const __m256d negative = _mm256_and_pd(_mm256_cmp_pd(major, zero, _CMP_LT_OQ), one);
    const __m128i face = _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_add_pd(axis, axis), negative));
    const __m128i row = _mm_add_epi32(_mm_mullo_epi32(face, g), _mm_srl_epi32(Y, shift));
    __m128i node = _mm_add_epi32(_mm_mullo_epi32(row, g), _mm_srl_epi32(X, shift));
    // lanes not aimed: kNone (all bits set)
    const __m128i bad = _mm256_cvtpd_epi32(_mm256_andnot_pd(good, one));  // 1 where not good
    node = _mm_or_si128(node, _mm_sub_epi32(_mm_setzero_si128(), bad));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(b.X + j), X);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(b.Y + j), Y);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(b.node + j), node);
    _mm256_storeu_pd(b.d2 + j, d2);
  }
  return j;
}

#else
std::size_t aimAvx2(const Vec3*, std::size_t, const AimParams&, AimBlock&) noexcept { return 0; }
std::size_t decideAvx2(const AimBlock&, std::size_t, const void*, Location*, std::uint32_t*,
                       std::size_t&) noexcept {
  return 0;
}
#endif

}  // namespace

void CubemapLocator::locate(std::span<const Vec3> points, std::span<Location> out) const noexcept {
  if (!centred_) {
    detail::locateEach(*this, points, out);
    return;
  }
  // Blocks of points in stages: aim each (4 at a time in AVX2 where the CPU has it) and
  // prefetch its base cell, then find each leaf and let its radii decide, prefetching the
  // lists of the points they leave open, then the face tests; the cache misses of a large
  // table overlap instead of following one another.
  const std::size_t n = std::min(points.size(), out.size());
  const bool vector = vectorBatches();
  const AimParams params{
      c_, scale_, static_cast<double>((static_cast<std::uint64_t>(g_) << depth_) - 1), g_, depth_};
  // a node table that stays in the L2 cache needs no prefetch stage
  constexpr std::size_t kCachedTable = 512 * 1024;
  const bool prefetch = nodes_.size() * sizeof(Node) > kCachedTable;
  AimBlock b;
  std::uint32_t pending[kAimBlock];
  static_assert(sizeof(Node) == 16 && offsetof(Node, in2) == 8 && offsetof(Node, out2) == 12);
  for (std::size_t i0 = 0; i0 < n; i0 += kAimBlock) {
    const std::size_t m = std::min(kAimBlock, n - i0);
    const Vec3* p = points.data() + i0;
    Location* o = out.data() + i0;
    // the points two blocks ahead: with the table's misses in flight, the hardware's stream
    // prefetch alone fell behind
    if (i0 + 3 * kAimBlock <= n)
      for (std::size_t byte = 0; byte < kAimBlock * sizeof(Vec3); byte += 64)
        __builtin_prefetch(reinterpret_cast<const char*>(p + 2 * kAimBlock) + byte);
    // aim (4 at a time in AVX2 where the CPU has it), then the base nodes' radii decide most
    // points, without a branch on the answer; the open ones (no node, an inner node,
    // between the radii) go on
    std::size_t left = 0, aimed = 0, decided = 0;
    if (vector) aimed = aimAvx2(p, m, params, b);
    for (std::size_t j = aimed; j < m; ++j) {
      Aim a;
      const bool ok = aim(p[j], a) > 0;
      b.X[j] = static_cast<std::uint32_t>(a.X);
      b.Y[j] = static_cast<std::uint32_t>(a.Y);
      b.node[j] = ok ? a.node : kNone;
      b.d2[j] = a.d2;
    }
    if (prefetch)
      for (std::size_t j = 0; j < m; ++j)
        __builtin_prefetch(nodes_.data() + (b.node[j] == kNone ? 0 : b.node[j]));
    if (vector) decided = decideAvx2(b, m, nodes_.data(), o, pending, left);
    for (std::size_t j = decided; j < m; ++j) {
      const bool missing = b.node[j] == kNone;
      const Node& nd = nodes_[missing ? 0 : b.node[j]];
      o[j] = detail::insideOrOutside(b.d2[j] > static_cast<double>(nd.out2));
      pending[left] = static_cast<std::uint32_t>(j);
      left += missing | !detail::radiiDecide(b.d2[j], nd.in2, nd.out2);
    }
    // a refined base cell: step down one level and prefetch that child (a quadtree's second
    // miss would otherwise follow the first)
    for (std::size_t k = 0; k < left; ++k) {
      const std::size_t j = pending[k];
      b.level[j] = 0;
      if (b.node[j] == kNone) continue;
      const Node& nd = nodes_[b.node[j]];
      if (nd.count != kInner) {
        __builtin_prefetch(entries_.data() + nd.first);
        continue;
      }
      const int shift = depth_ - 1;
      b.node[j] = nd.first + ((b.Y[j] >> shift) & 1) * 2 + ((b.X[j] >> shift) & 1);
      b.level[j] = 1;
      __builtin_prefetch(nodes_.data() + b.node[j]);
    }
    for (std::size_t k = 0; k < left; ++k) {
      const std::size_t j = pending[k];
      NoSink sink;
      if (b.node[j] == kNone) {
        o[j] = run(p[j], sink);
        continue;
      }
      int level = b.level[j];
      o[j] = fromLeaf(p[j], b.d2[j], nodes_[leafAt(b.X[j], b.Y[j], b.node[j], level)], sink);
    }
  }
}

Trace3D CubemapLocator::trace(Vec3 p) const {
  Trace3D t;
  t.method = Method3D::Cubemap;
  t.centre = centre();
  TraceSink sink{t};
  t.result = run(p, sink);
  return t;
}

Stats3D CubemapLocator::stats() const {
  Stats3D s = baseStats(tri_.size(), v_.size(),
                        sizeof(*this) + bytesOf(v_) + bytesOf(tri_) + bytesOf(nb_) +
                            bytesOf(nodes_) + bytesOf(entries_),
                        buildSeconds_);
  s.centred = centred_;
  s.resolution = centred_ ? g_ : 0;
  s.nodes = nodes_.size();
  s.histogram.assign(kCrowdedCell3D + 2, 0);
  if (!centred_) return s;
  for (const Node& nd : nodes_) {
    if (nd.count == kInner) continue;
    ++s.cells;
    s.entries += nd.count;
    s.maxPerCell = std::max<std::size_t>(s.maxPerCell, nd.count);
    if (nd.count > kCrowdedCell3D) ++s.crowdedCells;
    ++s.histogram[std::min<std::size_t>(nd.count, s.histogram.size() - 1)];
  }
  s.meanPerCell = s.cells ? static_cast<double>(s.entries) / static_cast<double>(s.cells) : 0.0;
  // the deepest level
  forEachLeaf([&](std::uint32_t, int, int level, std::uint32_t, std::uint32_t) {
    s.maxLevel = std::max(s.maxLevel, level);
  });
  return s;
}

std::vector<Cell3D> CubemapLocator::cells() const {
  std::vector<Cell3D> out;
  if (!centred_) return out;
  forEachLeaf([&](std::uint32_t node, int cf, int level, std::uint32_t i, std::uint32_t j) {
    const Node nd = nodes_[node];
    Cell3D cell;
    cell.index = static_cast<std::uint32_t>(out.size());
    cell.cubeFace = cf;
    cell.level = level;
    cell.i = i;
    cell.j = j;
    const double K = std::ldexp(g_ / 2.0, level);
    cell.s0 = -1 + i / K;
    cell.s1 = -1 + (i + 1) / K;
    cell.t0 = -1 + j / K;
    cell.t1 = -1 + (j + 1) / K;
    cell.apex = c_;
    const double st[4][2] = {
        {cell.s0, cell.t0}, {cell.s1, cell.t0}, {cell.s1, cell.t1}, {cell.s0, cell.t1}};
    for (int q = 0; q < 4; ++q) {
      const Vec3 d = cubeDirection(cf, st[q][0], st[q][1]);
      cell.corners[q] = {c_.x + half_ * d.x, c_.y + half_ * d.y, c_.z + half_ * d.z};
    }
    cell.faces.assign(entries_.begin() + nd.first, entries_.begin() + nd.first + nd.count);
    out.push_back(std::move(cell));
  });
  return out;
}

// === Locator3D

namespace {
std::variant<HalfspaceLocator, WalkLocator, CubemapLocator> build(
    const ConvexPolyhedron& polyhedron, Method3D method, std::uint32_t resolution) {
  switch (method) {
    case Method3D::Halfspace: return HalfspaceLocator(polyhedron);
    case Method3D::Walk: return WalkLocator(polyhedron);
    case Method3D::Cubemap: break;
  }
  return CubemapLocator(polyhedron, resolution);
}
}  // namespace

Locator3D::Locator3D(const ConvexPolyhedron& polyhedron, Method3D method, std::uint32_t resolution)
    : impl_(build(polyhedron, method, resolution)) {}

Location Locator3D::locate(Vec3 p) const noexcept {
  return std::visit([&](const auto& l) { return l.locate(p); }, impl_);
}
void Locator3D::locate(std::span<const Vec3> points, std::span<Location> out) const noexcept {
  std::visit([&](const auto& l) { l.locate(points, out); }, impl_);
}
Trace3D Locator3D::trace(Vec3 p) const {
  return std::visit([&](const auto& l) { return l.trace(p); }, impl_);
}
Stats3D Locator3D::stats() const {
  return std::visit([&](const auto& l) { return l.stats(); }, impl_);
}
std::vector<Cell3D> Locator3D::cells() const {
  return std::visit([&](const auto& l) { return l.cells(); }, impl_);
}

}  // namespace convexloc
