// convexloc-viewer — the inspector's words.
#include "logic/narration/text.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <initializer_list>

namespace convexloc::viewer {
namespace {

TraceLine::Kind signKind(int s) {
  return s > 0 ? TraceLine::Positive : (s < 0 ? TraceLine::Negative : TraceLine::Zero);
}

// "+1", "0", "-1"
std::string signWord(int s) {
  return s > 0 ? "+1" : (s < 0 ? "-1" : "0");
}

std::string edgeLine(const EdgeTest& e) {
  std::string side = e.sign > 0 ? "inner side" : (e.sign < 0 ? "outer side" : "on its line");
  return "edge " + std::to_string(e.edge) + ": orient2d = " + signWord(e.sign) + "  (" + side + ")";
}

std::string rayLine(const RayTest& r, const char* apex) {
  std::string side =
      r.sign > 0 ? "counter-clockwise of it" : (r.sign < 0 ? "clockwise of it" : "on it");
  return std::string("ray ") + apex + " -> vertex " + std::to_string(r.vertex) + ": " +
         signWord(r.sign) + "  (" + side + ")";
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return out;
}

}  // namespace

std::string exact(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

namespace {

// "(a, b, ...)" with exact()
std::string exactTuple(std::initializer_list<double> values) {
  std::string out = "(";
  for (const double v : values) {
    if (out.size() > 1) out += ", ";
    out += exact(v);
  }
  out += ')';
  return out;
}

}  // namespace

std::string compact(double v, double scale) {
  if (v == 0.0 || std::fabs(v) < 1e-12 * scale) return "0";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

namespace {

// "(a,b,...)" with compact()
std::string compactTuple(std::initializer_list<double> values, double scale) {
  std::string out = "(";
  for (const double v : values) {
    if (out.size() > 1) out += ',';
    out += compact(v, scale);
  }
  out += ')';
  return out;
}

}  // namespace

std::string compact(Vec2 p, double scale) {
  return compactTuple({p.x, p.y}, scale);
}

std::string compact(Vec3 p, double scale) {
  return compactTuple({p.x, p.y, p.z}, scale);
}

std::string exact(Vec2 p) {
  return exactTuple({p.x, p.y});
}

std::string approx(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string numbered(std::string_view prefix, std::uint64_t n) {
  std::string out(prefix);
  out.append(std::to_string(n));
  return out;
}

std::string nsText(double ns) {
  char buf[32];
  if (ns >= 100.0)
    std::snprintf(buf, sizeof buf, "%.0f", ns);
  else if (ns >= 10.0)
    std::snprintf(buf, sizeof buf, "%.1f", ns);
  else
    std::snprintf(buf, sizeof buf, "%.2f", ns);
  return buf;
}

std::string signText(int sign) {
  return sign > 0 ? " +" : (sign < 0 ? " -" : " 0");
}

std::string grouped(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return out;
}

std::string bytesText(std::size_t bytes) {
  const double b = static_cast<double>(bytes);
  if (bytes < 1024) return std::to_string(bytes) + " B";
  if (bytes < 1024 * 1024) return approx(b / 1024.0, 3) + " kB";
  return approx(b / (1024.0 * 1024.0), 3) + " MB";
}

namespace {
// the radius filter's step: where |p - c| falls against the cell's two radii
std::string radiusLine(double distance, double inner, double outer, const char* what) {
  std::string s = "|p - x_T| = " + approx(distance, 6) + "; cell radii " + approx(inner, 6) +
                  " .. " + approx(outer, 6);
  if (distance < inner)
    return s + ": nearer than every " + what + " the cell sees, inside with no test";
  if (distance > outer) return s + ": beyond where its ray leaves, outside with no test";
  return s + ": between them, the tests below decide";
}
}  // namespace

namespace {
// the size of a box, below which 1e-12 of it is noise (the centre's display)
double scaleOf(const Box2& b) {
  return std::hypot(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
}
}  // namespace

std::vector<TraceLine> describeTrace(const Trace2D& t, Vec2 p, const ConvexPolygon& polygon,
                                     std::uint32_t q) {
  std::vector<TraceLine> out;
  auto add = [&](TraceLine::Kind k, std::string s) { out.push_back({k, std::move(s)}); };
  add(TraceLine::Heading, std::string(toString(t.method)) + ": point " + exact(p));
  switch (t.method) {
    case Method2D::Halfplane:
      add(TraceLine::Step, "every edge's line, in order, until an outer side:");
      break;
    case Method2D::Wedge:
      add(TraceLine::Step, "fan from x0 = vertex 0 " + exact(polygon.vertex(0)) + ":");
      break;
    case Method2D::Slab:
    case Method2D::Uniform:
      if (t.outsideBox)
        add(TraceLine::Step, "outside the bounding box: no slab is needed");
      else if (t.cell >= 0)
        add(TraceLine::Step, std::string(t.method == Method2D::Slab ? "binary search of y"
                                                                    : "slab index from y (eq. 4)") +
                                 ": slab " + std::to_string(t.cell));
      break;
    case Method2D::Polar:
      if (t.atCentre)
        add(TraceLine::Step, "the point is the centre x_T itself");
      else if (t.octant >= 0) {
        add(TraceLine::Step, "centre x_T = " + compact(t.apex, scaleOf(polygon.bounds())));
        add(TraceLine::Step,
            "octant " + std::to_string(t.octant) + " (signs of dx, dy and |dx| vs |dy|)");
        // k counts the slabs by the ratio, as the index computes it (eq. 4's polar form)
        if (q > 0 && t.polar.slabs > 0)
          add(TraceLine::Step, "polar slab k = " + std::to_string(t.polar.slab) + " of " +
                                   std::to_string(q) + " in the octant: cell " +
                                   std::to_string(t.cell));
        if (t.outerRadius > 0)
          add(TraceLine::Step, radiusLine(t.distance, t.innerRadius, t.outerRadius, "edge"));
        else if (!t.radiusFilter)
          add(TraceLine::Step, "radius filter off: the cell's edges decide (the paper's query)");
      } else {
        add(TraceLine::Step,
            "no polar cell (no centre strictly inside, or too far): fan from vertex 0");
      }
      break;
  }
  if (t.crowded) add(TraceLine::Step, "the cell lists many edges: bisection over them");
  const char* apex = t.method == Method2D::Polar ? "x_T" : "x0";
  for (const RayTest& r : t.rays) add(signKind(r.sign), rayLine(r, apex));
  for (const EdgeTest& e : t.edges) add(signKind(e.sign), edgeLine(e));
  const std::size_t k = t.rays.size() + t.edges.size();
  add(TraceLine::Result, "result: " + upper(toString(t.result)) + "  (" + std::to_string(k) +
                             (k == 1 ? " predicate)" : " predicates)"));
  return out;
}

std::string exact(Vec3 p) {
  return exactTuple({p.x, p.y, p.z});
}

std::vector<TraceLine> describeTrace3D(const Trace3D& t, Vec3 p, double scale) {
  static const char* kFaces[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  std::vector<TraceLine> out;
  auto add = [&](TraceLine::Kind k, std::string s) { out.push_back({k, std::move(s)}); };
  add(TraceLine::Heading, std::string(toString(t.method)) + ": point " + exact(p));
  if (t.nonFinite) add(TraceLine::Step, "a coordinate is not finite: outside");
  if (t.atCentre) add(TraceLine::Step, "the point is the centre x_T itself");
  if (t.centre && t.method != Method3D::Halfspace)
    add(TraceLine::Step, "centre x_T = " + compact(*t.centre, scale));
  if (t.cubeFace >= 0) {
    add(TraceLine::Step, std::string("direction from x_T: cube face ") + kFaces[t.cubeFace] +
                             " (the largest |coordinate| and its sign)");
    add(TraceLine::Step, "on the face: s = " + approx(t.s, 6) + ", t = " + approx(t.t, 6));
    std::string cell = "cell (" + std::to_string(t.cellI) + ", " + std::to_string(t.cellJ) + ")";
    if (t.level > 0) cell += " at quadtree level " + std::to_string(t.level);
    add(TraceLine::Step, cell);
    if (t.outerRadius > 0)
      add(TraceLine::Step, radiusLine(t.distance, t.innerRadius, t.outerRadius, "face"));
    else if (!t.radiusFilter)
      add(TraceLine::Step, "radius filter off: the cell's faces decide (the paper's query)");
  }
  if (t.crowded) add(TraceLine::Step, "the cell lists many faces: a walk among them");
  if (t.fallback) add(TraceLine::Step, "no cell could be used: every face is tested");
  if (!t.path.empty()) {
    std::string path = "walk across faces:";
    for (std::size_t i = 0; i < t.path.size() && i < 40; ++i) {
      path += ' ';
      path += std::to_string(t.path[i]);
    }
    if (t.path.size() > 40) path += " ...";
    add(TraceLine::Step, path);
  }
  // every edge test of the walk, so that the count below lists what it counts
  for (const WalkTest& w : t.steps)
    add(signKind(w.sign), "face " + std::to_string(w.face) + ", edge " + std::to_string(w.edge) +
                              ": orient3d(x_T, a, b, p) = " + signWord(w.sign) +
                              (w.sign > 0 ? "  (beyond: cross)" : "  (stay)"));
  for (const FaceTest& f : t.faces) {
    const char* side = f.sign > 0 ? "inner side" : (f.sign < 0 ? "outer side" : "on its plane");
    add(f.sign > 0 ? TraceLine::Positive : (f.sign < 0 ? TraceLine::Negative : TraceLine::Zero),
        "face " + std::to_string(f.face) +
            ": orient3d = " + (f.sign > 0 ? "+1" : (f.sign < 0 ? "-1" : "0")) + "  (" + side + ")");
  }
  const std::size_t k = t.faces.size() + t.steps.size();
  add(TraceLine::Result, "result: " + upper(toString(t.result)) + "  (" + std::to_string(k) +
                             (k == 1 ? " predicate)" : " predicates)"));
  return out;
}

}  // namespace convexloc::viewer
