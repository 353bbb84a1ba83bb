// convexloc-viewer — the section polygon.
#include "logic/draw/section_polygon.hpp"

#include <algorithm>
#include <cmath>

namespace convexloc::viewer {
namespace {

// a point of the section in the plane's own coordinates, and where it is in space
struct Cut {
  glm::dvec2 uv;
  glm::dvec3 p;
};

double cross2(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// the convex hull of the cuts, counter-clockwise (Andrew's monotone chain); a turn smaller
// than `flat` (a cut found twice, through a vertex, rounded apart) counts as none
std::vector<glm::dvec3> hullOf(std::vector<Cut> cuts, double flat) {
  std::sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) {
    return a.uv.x < b.uv.x || (a.uv.x == b.uv.x && a.uv.y < b.uv.y);
  });
  std::vector<Cut> h(2 * cuts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    while (k >= 2 && cross2(h[k - 2].uv, h[k - 1].uv, cuts[i].uv) <= flat) --k;
    h[k++] = cuts[i];
  }
  for (std::size_t i = cuts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2(h[k - 2].uv, h[k - 1].uv, cuts[i].uv) <= flat) --k;
    h[k++] = cuts[i];
  }
  std::vector<glm::dvec3> out;
  for (std::size_t i = 0; i + 1 < k; ++i) out.push_back(h[i].p);
  return out;
}

}  // namespace

std::vector<glm::dvec3> sectionPolygon(const ConvexPolyhedron& polyhedron, glm::dvec3 corner,
                                       glm::dvec3 du, glm::dvec3 dv) {
  const glm::dvec3 n = glm::cross(du, dv);
  if (!(glm::length(n) > 0.0)) return {};
  const glm::dvec3 u = glm::normalize(du), w = glm::normalize(glm::cross(n, du));
  const auto vertices = polyhedron.vertices();
  std::vector<double> side(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const glm::dvec3 v{vertices[i].x, vertices[i].y, vertices[i].z};
    side[i] = glm::dot(v - corner, n);
  }
  std::vector<Cut> cuts;
  const auto add = [&](glm::dvec3 p) {
    cuts.push_back({{glm::dot(p - corner, u), glm::dot(p - corner, w)}, p});
  };
  for (const auto& t : polyhedron.triangles())
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      const glm::dvec3 pa{vertices[a].x, vertices[a].y, vertices[a].z};
      const glm::dvec3 pb{vertices[b].x, vertices[b].y, vertices[b].z};
      if (side[a] == 0.0) add(pa);
      if ((side[a] < 0.0 && side[b] > 0.0) || (side[a] > 0.0 && side[b] < 0.0))
        add(pa + (side[a] / (side[a] - side[b])) * (pb - pa));
    }
  if (cuts.size() < 3) return {};
  double extent = 0.0;
  for (const Cut& c : cuts) extent = std::max({extent, std::abs(c.uv.x), std::abs(c.uv.y)});
  std::vector<glm::dvec3> polygon = hullOf(std::move(cuts), 1e-12 * extent * extent);
  if (polygon.size() < 3) return {};
  return polygon;
}

}  // namespace convexloc::viewer
