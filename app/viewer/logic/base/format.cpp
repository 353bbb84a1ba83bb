// convexloc-viewer — numbers as the viewer writes them.
#include "logic/base/format.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <vector>

namespace convexloc::viewer {

namespace {

// the numbers of "(a, b)" or "(a, b, c)" starting at text[open] == '(', and the index after
// its ')'; false when it is not such a list
bool readTuple(std::string_view text, std::size_t open, std::vector<double>& values,
               std::size_t& after) {
  const std::size_t close = text.find(')', open);
  if (close == std::string_view::npos) return false;
  const std::string inner(text.substr(open + 1, close - open - 1));
  values.clear();
  const char* p = inner.c_str();
  const char* const end = p + inner.size();
  while (p < end) {
    char* stop = nullptr;
    const double v = std::strtod(p, &stop);
    if (stop == p) return false;
    values.push_back(v);
    p = stop;
    while (p < end && *p == ' ') ++p;
    if (p < end && *p != ',') return false;
    if (p < end) ++p;
  }
  after = close + 1;
  return values.size() == 2 || values.size() == 3;
}

}  // namespace

std::optional<double> parseNumber(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  if (text.empty() || text.size() > 400) return std::nullopt;
  const std::string copy(text);
  // strtod takes "inf", "nan" and hexadecimal too: only decimal digits, signs, '.', 'e'
  for (char c : copy)
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E'))
      return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size() || !std::isfinite(v)) return std::nullopt;
  if (errno == ERANGE && std::fabs(v) > 1.0) return std::nullopt;  // overflow, not underflow
  return v;
}

std::string shortestCoordinates(std::string_view message) {
  std::string out;
  std::vector<double> values;
  std::size_t at = 0;
  while (at < message.size()) {
    const std::size_t open = message.find('(', at);
    std::size_t after = 0;
    if (open == std::string_view::npos || !readTuple(message, open, values, after)) {
      const std::size_t stop = open == std::string_view::npos ? message.size() : open + 1;
      out.append(message.substr(at, stop - at));
      at = stop;
      continue;
    }
    out.append(message.substr(at, open - at));
    out.append(values.size() == 2 ? exactText(Vec2{values[0], values[1]})
                                  : exactText(Vec3{values[0], values[1], values[2]}));
    at = after;
  }
  return out;
}

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
