// convexloc-viewer — the options' values read from text.
#include "logic/app/option_values.hpp"

#include <algorithm>

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

namespace {

// the optimal string alignment distance: insertions, deletions, changes, adjacent swaps
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t change = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + change});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

}  // namespace

std::string nearestWord(std::string_view word, std::span<const std::string_view> candidates) {
  // a typo changes one letter in four at most, and never more than two
  const std::size_t most = std::min<std::size_t>(2, std::max<std::size_t>(1, word.size() / 4));
  std::string_view best;
  std::size_t bestDistance = most + 1;
  for (std::string_view c : candidates) {
    const std::size_t distance = editDistance(word, c);
    if (distance < bestDistance) {
      best = c;
      bestDistance = distance;
    }
  }
  return std::string(best);
}

std::string badPart(const std::vector<std::string>& values) {
  std::vector<std::string_view> parts;
  std::string all;
  for (std::string_view v : values) {
    if (!all.empty()) all.push_back(' ');
    all.append(v);
    for (std::size_t at = 0;;) {
      const std::size_t cut = std::min(v.find(',', at), v.size());
      parts.push_back(v.substr(at, cut - at));
      if (cut == v.size()) break;
      at = cut + 1;
    }
  }
  double x = 0.0;
  if (parts.size() > 1)
    for (std::string_view part : parts)
      if (!parseDouble(part, x))
        return std::string(1, '\'').append(part).append("' is not a number");
  return std::string("not '").append(all).append("'");
}

}  // namespace convexloc::viewer
