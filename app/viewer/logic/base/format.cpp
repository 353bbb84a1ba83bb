// convexloc-viewer — numbers as the viewer writes them.
#include "logic/base/format.hpp"

#include <cmath>
#include <cstdio>
#include <initializer_list>

namespace convexloc::viewer {

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

std::string sortedY(std::size_t rank) {
  return "y(" + std::to_string(rank) + ")";
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

}  // namespace convexloc::viewer
