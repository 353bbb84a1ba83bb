// convexloc-viewer — Why O(1)'s record files: written line by line, read back with
// FILE:LINE errors.
#include "logic/teach/scaling_record.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "convexloc/detail/chars.hpp"
#include "convexloc/error.hpp"

namespace convexloc::viewer {
namespace {

constexpr const char* kHeader = "convexloc-why 1";

// a double that reads back as itself
std::string exact(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// one sample's line: "2d polar 512 1 1.25 23.5 4096"
template <class Method>
void sampleLines(const char* dim, const std::vector<SeriesOf<Method>>& series, std::string& out) {
  for (const auto& s : series)
    for (const ScalingSample& x : s.samples)
      out += std::string(dim) + " " + std::string(toString(s.method)) + " " + std::to_string(x.n) +
             " " + exact(x.predicates) + " " + exact(x.cellEdges) + " " + exact(x.nsPerQuery) +
             " " + std::to_string(x.bytes) + "\n";
}

// a finite double, whole
bool readDouble(const std::string& s, double& out) {
  const auto r = detail::doubleFromChars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}

// a whole number, whole
bool readCount(const std::string& s, std::size_t& out) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// The reader: one line at a time into the result; the problem of a bad line.
struct RecordReader {
  ScalingResult& r;
  ScalingConfig& c;
  bool headerSeen = false;

  // a sample's words after "2d" / "3d": METHOD N PREDICATES CELL_EDGES NS BYTES
  template <class Method>
  std::string sample(const std::vector<std::string>& w, std::vector<SeriesOf<Method>>& series,
                     std::span<const Method> methods) {
    if (w.size() != 7) return "a sample needs METHOD N PREDICATES CELL_EDGES NS_PER_QUERY BYTES";
    const auto m =
        std::find_if(methods.begin(), methods.end(), [&](Method x) { return toString(x) == w[1]; });
    if (m == methods.end()) return "unknown method '" + w[1] + "' for " + w[0];
    ScalingSample s;
    if (!readCount(w[2], s.n) || !readDouble(w[3], s.predicates) ||
        !readDouble(w[4], s.cellEdges) || !readDouble(w[5], s.nsPerQuery) ||
        !readCount(w[6], s.bytes))
      return "a sample's N and BYTES are whole numbers, the others numbers";
    series[static_cast<std::size_t>(m - methods.begin())].samples.push_back(s);
    return {};
  }

  std::string config(const std::vector<std::string>& w) {
    std::size_t seed = 0;
    if (w.size() != 7 || !readCount(w[1], c.tracedPoints) || !readCount(w[2], c.timedPoints) ||
        !readDouble(w[3], c.minSeconds) || !readCount(w[4], c.linearLimit) ||
        !readCount(w[5], c.linearLimit3d) || !readCount(w[6], seed))
      return "config needs TRACED TIMED MIN_SECONDS LINEAR_LIMIT LINEAR_LIMIT_3D SEED";
    c.seed = seed;
    return {};
  }

  std::string memory(const std::vector<std::string>& w) {
    MemorySample m;
    if (w.size() != 6 || !readDouble(w[1], m.gap) || !readDouble(w[2], m.paperSlabs) ||
        !readDouble(w[3], m.paperBytes) || !readCount(w[4], m.uniformBytes) ||
        !readCount(w[5], m.polarBytes))
      return "memory needs GAP PAPER_SLABS PAPER_BYTES UNIFORM_BYTES POLAR_BYTES";
    r.memory.push_back(m);
    return {};
  }

  std::string line(const std::vector<std::string>& w) {
    if (!headerSeen) {
      headerSeen = w.size() == 2 && w[0] + " " + w[1] == kHeader;
      return headerSeen ? "" : std::string("not a Why O(1) record: it starts '") + kHeader + "'";
    }
    if (w[0] == "config") return config(w);
    if (w[0] == "2d") return sample<Method2D>(w, r.series, kAllMethods2D);
    if (w[0] == "3d") return sample<Method3D>(w, r.series3d, kAllMethods3D);
    if (w[0] == "memory") return memory(w);
    return "unknown record '" + w[0] + "' (config, 2d, 3d or memory)";
  }
};

// the sizes the samples were measured at, ascending, once each
template <class Method>
std::vector<std::size_t> sizesOf(const std::vector<SeriesOf<Method>>& series) {
  std::vector<std::size_t> sizes;
  for (const auto& s : series)
    for (const ScalingSample& x : s.samples) sizes.push_back(x.n);
  std::sort(sizes.begin(), sizes.end());
  sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
  return sizes;
}

}  // namespace

std::string scalingRecord(const ScalingResult& r, const ScalingConfig& c) {
  std::string out = std::string(kHeader) + "\n";
  out += "# config TRACED TIMED MIN_SECONDS LINEAR_LIMIT LINEAR_LIMIT_3D SEED\n";
  out += "config " + std::to_string(c.tracedPoints) + " " + std::to_string(c.timedPoints) + " " +
         exact(c.minSeconds) + " " + std::to_string(c.linearLimit) + " " +
         std::to_string(c.linearLimit3d) + " " + std::to_string(c.seed) + "\n";
  out += "# 2d|3d METHOD N PREDICATES CELL_EDGES NS_PER_QUERY BYTES\n";
  sampleLines("2d", r.series, out);
  sampleLines("3d", r.series3d, out);
  out += "# memory GAP PAPER_SLABS PAPER_BYTES UNIFORM_BYTES POLAR_BYTES\n";
  for (const MemorySample& m : r.memory)
    out += "memory " + exact(m.gap) + " " + exact(m.paperSlabs) + " " + exact(m.paperBytes) + " " +
           std::to_string(m.uniformBytes) + " " + std::to_string(m.polarBytes) + "\n";
  return out;
}

bool parseScalingRecord(const std::string& text, const std::string& source, ScalingResult& r,
                        ScalingConfig& c, std::string& error) {
  r = {};
  c = {};
  for (const Method2D m : kAllMethods2D) r.series.push_back({m, {}});
  for (const Method3D m : kAllMethods3D) r.series3d.push_back({m, {}});
  RecordReader reader{r, c};
  std::istringstream in(text);
  std::size_t number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty() || w[0].front() == '#') continue;
    if (const std::string problem = reader.line(w); !problem.empty()) {
      error = located(source, number, problem);
      return false;
    }
  }
  c.sizes = sizesOf(r.series);
  c.faces = sizesOf(r.series3d);
  if (c.faces.empty()) r.series3d.clear();
  if (!reader.headerSeen || c.sizes.empty()) {
    error = located(source, 0, "no 2d samples: not a Why O(1) record");
    return false;
  }
  return true;
}

bool readScalingRecord(const std::string& path, ScalingResult& r, ScalingConfig& c,
                       std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = path + ": cannot be read";
    return false;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parseScalingRecord(text.str(), path, r, c, error);
}

bool writeScalingRecord(const std::string& path, const ScalingResult& r, const ScalingConfig& c,
                        std::string& error) {
  std::ofstream out(path, std::ios::binary);
  out << scalingRecord(r, c);
  out.close();
  if (!out) {
    error = path + ": cannot be written";
    return false;
  }
  return true;
}

bool showScalingRecord(const std::string& path, ScalingWorker& worker, std::string& error) {
  ScalingResult r;
  ScalingConfig c;
  if (!readScalingRecord(path, r, c, error)) return false;
  worker.show(std::move(c), std::move(r));
  return true;
}

}  // namespace convexloc::viewer
