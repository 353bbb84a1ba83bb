// convexloc-viewer — the options' values read from text.
#include "logic/app/option_values.hpp"

#include "convexloc/detail/chars.hpp"

namespace convexloc::viewer {

bool parseDouble(std::string_view s, double& out) {
  double v = 0.0;
  const auto r = convexloc::detail::doubleFromChars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return false;
  out = v;
  return true;
}

bool parsePoint(std::string_view s, Vec2& out) {
  const std::size_t comma = s.find(',');
  if (comma == std::string_view::npos) return false;
  return parseDouble(s.substr(0, comma), out.x) && parseDouble(s.substr(comma + 1), out.y);
}

bool parsePoint3(std::string_view s, Vec3& out) {
  const std::size_t a = s.find(','), b = a == std::string_view::npos ? a : s.find(',', a + 1);
  if (b == std::string_view::npos) return false;
  return parseDouble(s.substr(0, a), out.x) && parseDouble(s.substr(a + 1, b - a - 1), out.y) &&
         parseDouble(s.substr(b + 1), out.z);
}

bool parseCount(std::string_view s, std::size_t& out) {
  if (parseInt<std::size_t>(s, 0, std::size_t{1} << 26, out)) return true;
  double d = 0.0;
  if (!parseDouble(s, d) || d < 0.0 || d > static_cast<double>(std::size_t{1} << 26) ||
      d != std::floor(d))
    return false;
  out = static_cast<std::size_t>(d);
  return true;
}

}  // namespace convexloc::viewer
