// convexloc — convex hulls of point clouds through Qhull (reentrant API), made exactly
// convex. Qhull's macros stay inside this file.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/predicates.hpp"
#include "detail/polyhedron_build.hpp"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace convexloc {
namespace {

// the most rounds of dropping offending points and running Qhull again
constexpr int kRepairRounds = 64;

// Qhull's state for one run, freed when it goes
class QhullRun {
 public:
  QhullRun() : err_(std::tmpfile()) { qh_zero(&qh_, err_); }
  ~QhullRun() {
    qh_freeqhull(&qh_, !qh_ALL);
    int curlong = 0, totlong = 0;
    qh_memfreeshort(&qh_, &curlong, &totlong);
    if (err_) std::fclose(err_);
  }
  QhullRun(const QhullRun&) = delete;
  QhullRun& operator=(const QhullRun&) = delete;

  // runs "qhull Qt" on the points; throws GeometryError with Qhull's first message line
  void run(std::vector<double>& coords) {
    char options[] = "qhull Qt";
    int code = qh_new_qhull(&qh_, 3, static_cast<int>(coords.size() / 3), coords.data(), False,
                            options, nullptr, err_);
    if (code != 0) throw GeometryError("Qhull failed: " + firstErrorLine());
  }

  // the hull's triangles as indices into the points given to run(), consistently oriented
  void triangles(MeshData& mesh) {
    qhT* qh = &qh_;
    facetT* facet = nullptr;
    FORALLfacets {
      std::uint32_t ids[3];
      int k = 0;
      vertexT *vertex = nullptr, **vertexp = nullptr;
      FOREACHvertex_(facet->vertices) {
        if (k < 3) ids[k] = static_cast<std::uint32_t>(qh_pointid(qh, vertex->point));
        ++k;
      }
      if (k != 3)
        throw GeometryError("Qhull returned a facet with " + std::to_string(k) + " vertices");
      // Qhull's own rule for printing a simplicial 3D facet in a consistent order
      if (facet->toporient ^ qh_ORIENTclock)
        mesh.addFace({ids[0], ids[1], ids[2]});
      else
        mesh.addFace({ids[1], ids[0], ids[2]});
    }
  }

 private:
  // the first line Qhull wrote to its error stream
  std::string firstErrorLine() {
    if (!err_) return "unknown error";
    std::rewind(err_);
    char line[512] = {0};
    if (!std::fgets(line, sizeof line, err_)) return "unknown error";
    std::string s(line);
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    return s;
  }

  qhT qh_;
  std::FILE* err_;
};

}  // namespace

ConvexPolyhedron ConvexPolyhedron::hullOf(std::span<const Vec3> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw GeometryError("point " + std::to_string(i) +
                          " has a coordinate that is not a finite number");
  }
  if (points.size() > kMaxPolyhedronVertices)
    throw UsageError("too many points for a hull: " + std::to_string(points.size()));
  // exact: four points not in one plane, else Qhull's complaint would be less clear
  {
    std::size_t b = 1, c = 0, d = 0;
    while (b < points.size() && points[b] == points[0]) ++b;
    auto line = [&](std::size_t i) { return detail::collinear(points[0], points[b], points[i]); };
    for (c = b + 1; c < points.size() && line(c); ++c) {
    }
    for (d = c + 1; d < points.size() && orient3d(points[0], points[b], points[c], points[d]) == 0;
         ++d) {
    }
    if (points.size() < 4 || d >= points.size())
      throw GeometryError("the hull has zero volume: the " + std::to_string(points.size()) +
                          " points are " + (c >= points.size() ? "collinear" : "coplanar") +
                          (points.size() < 4 ? " (a hull needs at least 4 points)" : ""));
  }

  // Qhull works in doubles and overflows on coordinates near 1e190 (it squares them for its
  // normals); it only decides which points form the hull, which
  // is then checked exactly, so it gets the coordinates scaled by one power of two (exact
  // but for points 2^1000 times smaller than the largest, which may become zero there).
  double largest = 0.0;
  for (Vec3 p : points)
    largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  const int shift = -std::ilogb(largest);  // largest is > 0: the points span a volume

  std::vector<std::uint8_t> dropped(points.size(), 0);
  std::string lastProblem;
  for (int round = 0; round < kRepairRounds; ++round) {
    MeshData mesh;
    std::vector<double> coords;
    coords.reserve(3 * points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (dropped[i]) continue;
      mesh.vertices.push_back(points[i]);
      coords.insert(coords.end(), {std::ldexp(points[i].x, shift), std::ldexp(points[i].y, shift),
                                   std::ldexp(points[i].z, shift)});
    }
    {
      QhullRun qhull;
      qhull.run(coords);
      qhull.triangles(mesh);
    }
    std::vector<std::uint32_t> suspects;
    try {
      return ConvexPolyhedron(mesh, &suspects);
    } catch (const GeometryError& e) {
      if (suspects.empty()) throw;
      lastProblem = e.what();
    }
    // suspects index the kept points: map them back and drop them
    std::vector<std::uint32_t> kept;
    for (std::uint32_t i = 0; i < points.size(); ++i)
      if (!dropped[i]) kept.push_back(i);
    for (std::uint32_t s : suspects) dropped[kept[s]] = 1;
  }
  throw GeometryError("Qhull's hull could not be made exactly convex in " +
                      std::to_string(kRepairRounds) + " rounds; last problem: " + lastProblem);
}

}  // namespace convexloc
