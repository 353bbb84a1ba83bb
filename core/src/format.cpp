// convexloc — numbers and sizes as text.
#include "convexloc/format.hpp"

#include <charconv>
#include <cstdio>
#include <initializer_list>
#include <iterator>

#include "convexloc/detail/chars.hpp"

namespace convexloc {
namespace {

// "(a, b, ...)" with exactText
std::string exactTuple(std::initializer_list<double> values) {
  std::string out = "(";
  for (const double v : values) {
    if (out.size() > 1) out += ", ";
    out += exactText(v);
  }
  out += ')';
  return out;
}

}  // namespace

std::string exactText(double v) {
  char buf[64];  // "-1.2345678901234567e-308" with room to spare: to_chars cannot fail
  const auto r = detail::doubleToChars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string exactText(Vec2 p) {
  return exactTuple({p.x, p.y});
}

std::string exactText(Vec3 p) {
  return exactTuple({p.x, p.y, p.z});
}

std::string binarySize(double bytes) {
  constexpr const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  std::size_t u = 0;
  while (bytes >= 1024.0 && u + 1 < std::size(kUnits)) {
    bytes /= 1024.0;
    ++u;
  }
  char buf[48];
  if (u == 0)
    std::snprintf(buf, sizeof buf, "%.0f B", bytes);
  else
    std::snprintf(buf, sizeof buf, "%.3g %s", bytes, kUnits[u]);
  return buf;
}

}  // namespace convexloc
