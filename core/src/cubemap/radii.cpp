// convexloc — the cube map's radii: for each leaf, the two squared distances from the centre
// that decide most points before any face test (the argument: detail/radii.hpp); then, from
// the same list of faces, its slab (cubemap/slabs.cpp).
//
// A leaf's bounds start from its faces' whole-face bounds: the distance to the face's plane
// (below every point of the face) and to its farthest vertex. Where those leave a shell wider
// than 1/1024 of the radius (faces large against the cell, as on a coarse polyhedron), each
// face's part inside the cell's pyramid tightens them; elsewhere the shell is already thin.
// Everything is computed in long double and bounded with the products' error bounds, so a
// bound is only tightened where the tighter value is sure.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "cubemap/build.hpp"
#include "cubemap/index.hpp"
#include "detail/radii.hpp"

namespace convexloc {
namespace cubemap {
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
// pyramid (infinity where some corner ray misses the plane or the face is ill-conditioned);
// raises in2 only when `inner` asks for it.
double pieceBounds(const CellPyramid& cp, Vec3 va, Vec3 vb, Vec3 vd, Vec3 c, double& in2,
                   double& out2, bool inner = true) {
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
  const L NErr =
      8 * eps * (pn[0] * std::fabs(w[0]) + pn[1] * std::fabs(w[1]) + pn[2] * std::fabs(w[2]));
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
  if (!inner) return plane2;  // in2 not asked for
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

// the pyramid of cell (i, j) at `level` of cube face `cf`, for base resolution g
CellPyramid pyramidOf(std::uint32_t g, int cf, int level, std::uint64_t i, std::uint64_t j) {
  using L = long double;
  CellPyramid cp;
  cp.a = cf / 2, cp.u = (cp.a + 1) % 3, cp.w = (cp.a + 2) % 3;
  cp.sigma = (cf & 1) ? -1 : 1;
  // the cell's square, widened far beyond the query's error in (s, t) (below 2^-50)
  const L K = std::ldexp(static_cast<L>(g) / 2, level), widen = 0x1p-30L;
  cp.s0 = L(i) / K - 1 - widen, cp.s1 = L(i + 1) / K - 1 + widen;
  cp.t0 = L(j) / K - 1 - widen, cp.t1 = L(j + 1) / K - 1 + widen;
  const L corner[4][2] = {{cp.s0, cp.t0}, {cp.s1, cp.t0}, {cp.s1, cp.t1}, {cp.s0, cp.t1}};
  for (int k = 0; k < 4; ++k) {
    cp.d[k][cp.a] = cp.sigma;
    cp.d[k][cp.u] = corner[k][0];
    cp.d[k][cp.w] = corner[k][1];
    cp.len[k] = std::sqrt(1 + corner[k][0] * corner[k][0] + corner[k][1] * corner[k][1]);
  }
  return cp;
}

// each plane face's whole-face bounds: in2 below the squared distance to its plane, out2
// that to its farthest corner (side by side: a leaf reads both)
struct FaceBounds {
  struct Bounds {
    double in2, out2;
  };
  std::vector<Bounds> of;
  FaceBounds(const detail::SurfaceCopy& surface, const ConvexPolyhedron& polyhedron, Vec3 c) {
    const std::size_t nf = surface.faces.size();
    const std::vector<Vec3>& v = surface.vertices;
    of.resize(nf);
    std::vector<double> vertex2(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) vertex2[i] = distance2Long(v[i], c);
    for (std::size_t f = 0; f < nf; ++f) {
      const ConvexPolyhedron::Triangle& t = surface.faces[f];
      of[f].in2 = planeDistance2Below(v[t[0]], v[t[1]], v[t[2]], c);
      of[f].out2 = 0.0;
      for (std::uint32_t w : polyhedron.planeLoop(f)) of[f].out2 = std::max(of[f].out2, vertex2[w]);
    }
  }
};

// Tightens [lo, hi] with each listed face's part inside the pyramid. A ray leaves a convex
// polyhedron at the nearest of the face planes it meets ahead, so a face whose plane every
// ray of the pyramid meets ahead bounds every exit point of the cell by itself: the smallest
// such bound serves as well as the largest. A leaf listing more than `sample` faces (the thin
// faces of a zone) keeps its whole-face lower bound and takes the upper one from a spread
// sample of its faces.
void tightenInPyramid(const CellPyramid& cp, const detail::SurfaceCopy& surface, Vec3 c,
                      const FaceBounds& whole, const std::uint32_t* first, std::uint32_t count,
                      std::uint32_t sample, double& lo, double& hi) {
  const std::vector<Vec3>& v = surface.vertices;
  const bool all = count <= sample;
  const std::uint32_t step = all ? 1 : (count + sample - 1) / sample;
  double tightLo = HUGE_VAL, tightHi = 0.0, anyPlane = HUGE_VAL;
  for (std::uint32_t k = 0; k < count; k += step) {
    const std::uint32_t f = first[k];
    double fIn2 = whole.of[f].in2, fOut2 = whole.of[f].out2;
    const ConvexPolyhedron::Triangle& t = surface.faces[f];
    anyPlane = std::min(anyPlane, pieceBounds(cp, v[t[0]], v[t[1]], v[t[2]], c, fIn2, fOut2, all));
    tightLo = std::min(tightLo, fIn2);
    tightHi = std::max(tightHi, fOut2);
  }
  if (all) {
    lo = std::max(lo, tightLo);
    hi = std::min(hi, tightHi);
  }
  hi = std::min(hi, anyPlane);
}

}  // namespace
}  // namespace cubemap

void CubemapBuilder::setLeafRadii() {
  // the faces a leaf's pyramid tightens its radii with: all of them up to 32
  constexpr std::uint32_t kSample = 32;
  CubemapLocator& L = locator_;
  const cubemap::FaceBounds whole(L.surface_, polyhedron_, L.centre_);
  std::vector<std::uint32_t> faces;  // a zone or sector leaf's, expanded
  auto leaf = [&](std::uint32_t node, int cf, int level, std::uint64_t i, std::uint64_t j) {
    Node& nd = L.nodes_[node];
    const bool zone = cubemap::isZoneLeaf(nd.count) || cubemap::isSectorLeaf(nd.count);
    if (cubemap::isSectorLeaf(nd.count))
      fanLeafFaces(nd, faces);
    else if (zone)
      faces = L.leafFaces(nd);
    const std::uint32_t* first = zone ? faces.data() : L.entries_.data() + nd.first;
    const auto count = zone ? static_cast<std::uint32_t>(faces.size()) : nd.count;
    double lo = count ? HUGE_VAL : 0.0, hi = count ? 0.0 : HUGE_VAL;
    for (const std::uint32_t* e = first; e != first + count; ++e) {
      lo = std::min(lo, whole.of[*e].in2);
      hi = std::max(hi, whole.of[*e].out2);
    }
    if (count && !(hi <= lo * (1 + 0x1p-10)))
      cubemap::tightenInPyramid(cubemap::pyramidOf(L.resolution_, cf, level, i, j), L.surface_,
                                L.centre_, whole, first, count, kSample, lo, hi);
    nd.in2 = detail::innerBound(lo);
    nd.out2 = detail::outerBound(hi);
    setLeafSlab(node, cf, level, i, j, {first, count});
  };
  L.slabs_.assign(L.nodes_.size(), CubemapLocator::Slab{});
  for (Node& nd : L.nodes_)
    if (nd.count == cubemap::kInner) nd.in2 = nd.out2 = std::numeric_limits<float>::quiet_NaN();
  L.forEachLeaf(leaf);
}

}  // namespace convexloc
