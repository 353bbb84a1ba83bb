// convexloc — deterministic polyhedron and 3D point generators.
#include "convexloc/generate3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "convexloc/error.hpp"
#include "convexloc/predicates.hpp"
#include "detail/names.hpp"
#include "detail/prisms.hpp"

namespace convexloc {
namespace {

constexpr double kPi = std::numbers::pi;

// a point uniform on the unit sphere
Vec3 onSphere(Rng& rng) {
  const double z = rng.uniform(-1, 1), a = rng.uniform(0, 2 * kPi);
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  return {r * std::cos(a), r * std::sin(a), z};
}

// p scaled to unit length
Vec3 normalised(Vec3 p) {
  const double len = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
  return {p.x / len, p.y / len, p.z / len};
}

// reverses each face that is clockwise seen from outside, judged against `inside`
void orientOutward(MeshData& mesh, Vec3 inside) {
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    auto face = mesh.face(f);
    if (orient3d(mesh.vertices[face[0]], mesh.vertices[face[1]], mesh.vertices[face[2]], inside) <
        0)
      std::reverse(mesh.indices.begin() + mesh.faceStart[f],
                   mesh.indices.begin() + mesh.faceStart[f + 1]);
  }
}

// a mesh holding the points and the faces of their exact hull
MeshData platonic(std::vector<Vec3> points) {
  MeshData mesh = smallHull(points);
  mesh.vertices = std::move(points);
  return mesh;
}

// the regular icosahedron's 12 vertices
std::vector<Vec3> icosahedronPoints() {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> p;
  for (double a : {-1.0, 1.0})
    for (double b : {-phi, phi}) {
      p.push_back({0, a, b});
      p.push_back({a, b, 0});
      p.push_back({b, 0, a});
    }
  return p;
}

// The icosahedron subdivided nu times per edge, projected on the sphere of radius r around
// `centre`. Points on an icosahedron edge are computed once, from the edge's smaller end,
// so that both faces share them exactly.
MeshData geodesic(std::size_t nu, double r, Vec3 centre) {
  std::vector<Vec3> ico = icosahedronPoints();
  MeshData base = smallHull(ico);
  MeshData mesh;
  auto place = [&](Vec3 p) {
    Vec3 u = normalised(p);
    return mesh.addVertex({centre.x + r * u.x, centre.y + r * u.y, centre.z + r * u.z});
  };
  for (const Vec3& p : ico) place(p);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t>
      edgeStart;  // first point's index
  auto onEdge = [&](std::uint32_t a, std::uint32_t b, std::size_t k) -> std::uint32_t {
    // the k-th of nu steps from a to b
    if (k == 0) return a;
    if (k == nu) return b;
    const bool flip = b < a;
    const std::uint32_t lo = flip ? b : a, hi = flip ? a : b;
    const std::size_t step = flip ? nu - k : k;
    auto [it, fresh] = edgeStart.try_emplace({lo, hi}, 0);
    if (fresh) {
      it->second = static_cast<std::uint32_t>(mesh.vertices.size());
      for (std::size_t i = 1; i < nu; ++i) {
        const double t = static_cast<double>(i) / static_cast<double>(nu);
        const Vec3 p = ico[lo], q = ico[hi];
        place({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y), p.z + t * (q.z - p.z)});
      }
    }
    return it->second + static_cast<std::uint32_t>(step - 1);
  };
  std::vector<std::uint32_t> grid;
  for (std::size_t f = 0; f < base.faceCount(); ++f) {
    auto face = base.face(f);
    const std::uint32_t A = face[0], B = face[1], C = face[2];
    // grid[(i, j)] for i + j <= nu: the point A + i/nu (B - A) + j/nu (C - A)
    grid.assign((nu + 1) * (nu + 1), 0);
    auto at = [&](std::size_t i, std::size_t j) -> std::uint32_t& {
      return grid[i * (nu + 1) + j];
    };
    for (std::size_t i = 0; i <= nu; ++i)
      for (std::size_t j = 0; i + j <= nu; ++j) {
        if (j == 0)
          at(i, j) = onEdge(A, B, i);
        else if (i == 0)
          at(i, j) = onEdge(A, C, j);
        else if (i + j == nu)
          at(i, j) = onEdge(B, C, j);
        else {
          const double u = static_cast<double>(i) / static_cast<double>(nu);
          const double w = static_cast<double>(j) / static_cast<double>(nu);
          const Vec3 a = ico[A], b = ico[B], c = ico[C];
          at(i, j) = place({a.x + u * (b.x - a.x) + w * (c.x - a.x),
                            a.y + u * (b.y - a.y) + w * (c.y - a.y),
                            a.z + u * (b.z - a.z) + w * (c.z - a.z)});
        }
      }
    for (std::size_t i = 0; i < nu; ++i)
      for (std::size_t j = 0; i + j < nu; ++j) {
        mesh.addFace({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < nu) mesh.addFace({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  orientOutward(mesh, centre);
  return mesh;
}

// the triangles of the exact hull of `points`, as a mesh
MeshData hullMesh(const std::vector<Vec3>& points) {
  MeshData mesh;
  ConvexPolyhedron hull = ConvexPolyhedron::hullOf(points);
  mesh.vertices.assign(hull.vertices().begin(), hull.vertices().end());
  for (const auto& t : hull.triangles()) mesh.addFace({t[0], t[1], t[2]});
  return mesh;
}

// The box [lo, hi] with each face split into a grid of squares (or of triangle pairs),
// counts[a] cells along axis a. Vertices sit on an integer lattice per axis (counts[a] + 1
// values, the last one exactly hi), so neighbouring faces share them.
MeshData gridBox(Vec3 lo, Vec3 hi, const std::size_t (&counts)[3], bool squares) {
  MeshData mesh;
  std::map<std::array<std::size_t, 3>, std::uint32_t> index;
  auto coord = [&](int a, std::size_t i) {
    const double l = a == 0 ? lo.x : a == 1 ? lo.y : lo.z, h = a == 0 ? hi.x : a == 1 ? hi.y : hi.z;
    if (i == counts[a]) return h;
    return l + (h - l) * static_cast<double>(i) / static_cast<double>(counts[a]);
  };
  auto vertex = [&](std::array<std::size_t, 3> g) {
    auto [it, fresh] = index.try_emplace(g, 0);
    if (fresh) it->second = mesh.addVertex({coord(0, g[0]), coord(1, g[1]), coord(2, g[2])});
    return it->second;
  };
  for (int a = 0; a < 3; ++a)
    for (std::size_t side : {std::size_t{0}, counts[a]}) {
      const int u = (a + 1) % 3, w = (a + 2) % 3;
      for (std::size_t i = 0; i < counts[u]; ++i)
        for (std::size_t j = 0; j < counts[w]; ++j) {
          std::array<std::size_t, 3> g{};
          g[a] = side;
          auto corner = [&](std::size_t di, std::size_t dj) {
            g[u] = i + di;
            g[w] = j + dj;
            return vertex(g);
          };
          const std::uint32_t q[4] = {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
          if (squares) {
            mesh.addFace({q[0], q[1], q[2], q[3]});
          } else {
            mesh.addFace({q[0], q[1], q[2]});
            mesh.addFace({q[0], q[2], q[3]});
          }
        }
    }
  orientOutward(mesh, {(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2});
  return mesh;
}

// in the order of PolyhedronKind
constexpr std::string_view kNames[] = {"tetrahedron",    "cube",      "octahedron",  "dodecahedron",
                                       "icosahedron",    "geodesic",  "sphere-hull", "cube-hull",
                                       "ellipsoid-hull", "thin-slab", "offset",      "tiny-faces",
                                       "coplanar",       "cylinder",  "prism"};

}  // namespace

std::string_view toString(PolyhedronKind k) {
  return detail::nameOf(kNames, k);
}

std::optional<PolyhedronKind> parsePolyhedronKind(std::string_view name) {
  return detail::enumNamed<PolyhedronKind>(kNames, name);
}

MeshData smallHull(std::span<const Vec3> points) {
  const std::size_t n = points.size();
  if (n > 64) throw UsageError("smallHull: at most 64 points");
  MeshData mesh;
  if (n < 4) return mesh;
  Vec3 inside{0, 0, 0};
  for (const Vec3& p : points)
    inside = {inside.x + p.x / n, inside.y + p.y / n, inside.z + p.z / n};
  std::vector<std::vector<std::uint32_t>> seen;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      for (std::uint32_t k = j + 1; k < n; ++k) {
        int above = 0, below = 0;
        std::vector<std::uint32_t> on;
        for (std::uint32_t q = 0; q < n; ++q) {
          const int s = orient3d(points[i], points[j], points[k], points[q]);
          if (s > 0)
            ++above;
          else if (s < 0)
            ++below;
          else
            on.push_back(q);
        }
        if ((above && below) || (!above && !below) || on.size() < 3) continue;
        if (std::find(seen.begin(), seen.end(), on) != seen.end()) continue;
        seen.push_back(on);
        // order the face counter-clockwise from outside: each next vertex has every other
        // face vertex on its left seen from outside (inside lies below)
        std::vector<std::uint32_t> ring{on[0]};
        while (ring.size() < on.size()) {
          const std::uint32_t p = ring.back();
          for (std::uint32_t q : on) {
            if (q == p || std::find(ring.begin() + 1, ring.end(), q) != ring.end()) continue;
            if (q == ring.front() && ring.size() < on.size()) continue;
            bool left = true;
            for (std::uint32_t r : on)
              if (r != p && r != q && orient3d(points[p], points[q], points[r], inside) <= 0)
                left = false;
            if (left) {
              ring.push_back(q);
              break;
            }
          }
          if (ring.back() == p) break;  // collinear points on the face: give up on this order
        }
        if (ring.size() == on.size()) mesh.addFace(ring);
      }
  return mesh;
}

MeshData generatePolyhedron(PolyhedronKind kind, std::size_t n, std::uint64_t seed) {
  if (n < 4) throw UsageError("a polyhedron needs at least 4 faces");
  const bool hull = kind == PolyhedronKind::SphereHull || kind == PolyhedronKind::CubeHull ||
                    kind == PolyhedronKind::EllipsoidHull || kind == PolyhedronKind::TinyFaces;
  if (n > (std::size_t{1} << (hull ? 22 : 24)))
    throw UsageError(std::string("at most 2^") + (hull ? "22" : "24") +
                     " faces can be generated for " + std::string(toString(kind)));
  Rng rng(seed);
  const std::size_t nu =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(std::sqrt(n / 20.0))));
  switch (kind) {
    case PolyhedronKind::Tetrahedron:
      return platonic({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}});
    case PolyhedronKind::Cube: {
      std::vector<Vec3> p;
      for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
          for (double z : {-1.0, 1.0}) p.push_back({x, y, z});
      return platonic(p);
    }
    case PolyhedronKind::Octahedron:
      return platonic({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}});
    case PolyhedronKind::Dodecahedron: {
      // the pyritohedron with h = 5/8: every coordinate is exact, every pentagon planar
      const double h = 0.625, a = 1 + h, b = 1 - h * h;
      std::vector<Vec3> p;
      for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
          for (double z : {-1.0, 1.0}) p.push_back({x, y, z});
      for (double s : {-1.0, 1.0})
        for (double t : {-1.0, 1.0}) {
          p.push_back({0, s * a, t * b});
          p.push_back({s * a, t * b, 0});
          p.push_back({t * b, 0, s * a});
        }
      return platonic(p);
    }
    case PolyhedronKind::Icosahedron: return platonic(icosahedronPoints());
    case PolyhedronKind::Geodesic: return geodesic(nu, 1, {0, 0, 0});
    case PolyhedronKind::Offset:
      return geodesic(nu, std::max(1.0, static_cast<double>(nu) / 32), {1e9, 1e9, 1e9});
    case PolyhedronKind::SphereHull:
    case PolyhedronKind::EllipsoidHull: {
      const bool ellipsoid = kind == PolyhedronKind::EllipsoidHull;
      std::vector<Vec3> p(n / 2 + 2);
      for (Vec3& q : p) {
        q = onSphere(rng);
        if (ellipsoid) q = {2 * q.x, q.y, 0.5 * q.z};
      }
      return hullMesh(p);
    }
    case PolyhedronKind::CubeHull: {
      std::vector<Vec3> p(n);
      for (Vec3& q : p) q = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
      return hullMesh(p);
    }
    case PolyhedronKind::TinyFaces: {
      // seven corners of the cube, and n / 2 points on the octant of a tiny sphere tucked
      // into the eighth corner
      const double r = 1e-4, c = 1 - r;
      std::vector<Vec3> p;
      for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
          for (double z : {-1.0, 1.0})
            if (x < 0 || y < 0 || z < 0) p.push_back({x, y, z});
      for (std::size_t i = 0; i < n / 2 + 2; ++i) {
        Vec3 q = onSphere(rng);
        q = {std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)};
        p.push_back({c + r * q.x, c + r * q.y, c + r * q.z});
      }
      return hullMesh(p);
    }
    case PolyhedronKind::ThinSlab: {
      const std::size_t k =
          std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(std::sqrt(n / 4.0))));
      const std::size_t counts[3] = {k, k, 1};
      return gridBox({0, 0, 0}, {1, 1, 1e-9}, counts, false);
    }
    case PolyhedronKind::Coplanar: {
      const std::size_t k =
          std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(std::sqrt(n / 12.0))));
      const std::size_t counts[3] = {k, k, k};
      return gridBox({-1, -1, -1}, {1, 1, 1}, counts, true);
    }
    case PolyhedronKind::Cylinder: return detail::cylinderMesh(std::max<std::size_t>(n / 4 + 1, 3));
    case PolyhedronKind::Prism: return detail::latticePrismMesh(std::max<std::size_t>(n / 4, 8));
  }
  throw UsageError("unknown polyhedron kind");
}

// === Points

namespace {

// v moved by `steps` ulps (negative: down)
double ulps(double v, int steps) {
  for (; steps > 0; --steps) v = std::nextafter(v, std::numeric_limits<double>::infinity());
  for (; steps < 0; ++steps) v = std::nextafter(v, -std::numeric_limits<double>::infinity());
  return v;
}

// the coordinate k of p
double& coord(Vec3& p, int k) {
  return k == 0 ? p.x : k == 1 ? p.y : p.z;
}

// p exactly on the plane of (a, b, c) if a few ulps along the normal's major axis get
// there; else p unchanged
Vec3 ontoPlane(Vec3 a, Vec3 b, Vec3 c, Vec3 p) {
  const double nx = (b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y);
  const double ny = (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z);
  const double nz = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  const int axis = std::fabs(nx) >= std::fabs(ny) && std::fabs(nx) >= std::fabs(nz) ? 0
                   : std::fabs(ny) >= std::fabs(nz)                                 ? 1
                                                                                    : 2;
  for (int k = 0; k <= 8; ++k)
    for (int sign : {1, -1}) {
      Vec3 q = p;
      coord(q, axis) = ulps(coord(q, axis), sign * k);
      if (orient3d(a, b, c, q) == 0) return q;
    }
  return p;
}

}  // namespace

std::vector<Vec3> generatePoints3D(const ConvexPolyhedron& polyhedron, std::size_t count,
                                   std::uint64_t seed, bool nearBoundary) {
  Rng rng(seed);
  const Box3 b = polyhedron.bounds();
  const Vec3 w{0.1 * (b.hi.x - b.lo.x), 0.1 * (b.hi.y - b.lo.y), 0.1 * (b.hi.z - b.lo.z)};
  std::vector<Vec3> out;
  out.reserve(count);
  auto v = polyhedron.vertices();
  auto tri = polyhedron.triangles();
  while (out.size() < count) {
    if (!nearBoundary) {
      out.push_back({rng.uniform(b.lo.x - w.x, b.hi.x + w.x),
                     rng.uniform(b.lo.y - w.y, b.hi.y + w.y),
                     rng.uniform(b.lo.z - w.z, b.hi.z + w.z)});
      continue;
    }
    const auto& t = tri[rng.below(tri.size())];
    const Vec3 A = v[t[0]], B = v[t[1]], C = v[t[2]];
    switch (rng.below(6)) {
      case 0: out.push_back(v[rng.below(v.size())]); break;  // a vertex
      case 1: {                                              // one ulp off a vertex
        Vec3 p = A;
        for (int k = 0; k < 3; ++k)
          coord(p, k) = ulps(coord(p, k), static_cast<int>(rng.below(3)) - 1);
        out.push_back(p);
        break;
      }
      case 2: {  // on an edge; exactly where the rounded point happens to lie on it
        const double s = rng.uniform();
        Vec3 p{A.x + s * (B.x - A.x), A.y + s * (B.y - A.y), A.z + s * (B.z - A.z)};
        out.push_back(ontoPlane(A, B, C, p));
        break;
      }
      case 3:
      case 4: {  // on a face, exactly where a few ulps reach it; case 4 then one ulp off
        const bool off = out.size() % 2 == 1;
        double s = rng.uniform(), r = rng.uniform();
        if (s + r > 1) s = 1 - s, r = 1 - r;
        Vec3 p{A.x + s * (B.x - A.x) + r * (C.x - A.x), A.y + s * (B.y - A.y) + r * (C.y - A.y),
               A.z + s * (B.z - A.z) + r * (C.z - A.z)};
        p = ontoPlane(A, B, C, p);
        if (off) {
          int k = static_cast<int>(rng.below(3));
          coord(p, k) = ulps(coord(p, k), rng.below(2) ? 1 : -1);
        }
        out.push_back(p);
        break;
      }
      default: {  // a hair inside or outside, relative to the box
        const double h = (rng.uniform() - 0.5) * 1e-9;
        const Vec3 m{(A.x + B.x + C.x) / 3, (A.y + B.y + C.y) / 3, (A.z + B.z + C.z) / 3};
        out.push_back({m.x + h * (b.hi.x - b.lo.x) * rng.uniform(-1, 1),
                       m.y + h * (b.hi.y - b.lo.y) * rng.uniform(-1, 1),
                       m.z + h * (b.hi.z - b.lo.z) * rng.uniform(-1, 1)});
        break;
      }
    }
  }
  return out;
}

}  // namespace convexloc
