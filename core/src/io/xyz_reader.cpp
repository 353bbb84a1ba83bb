// convexloc — the point-cloud reader (.xyz, .pts): one point "x y z" a line, further numbers
// on the line (intensity, colour, a normal) read past; numbers separated by blanks or commas;
// a first line holding one whole number is a point count (as .pts files start), checked
// against the points that follow. The result is a mesh with vertices only.
#include <algorithm>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/mesh_reader.hpp"
#include "io/mesh_parsers.hpp"
#include "io/mesh_tokens.hpp"

namespace convexloc::detail {
namespace {

// the count a header line announces (ParseError unless a whole number in range)
std::size_t announcedCount(std::string_view token, std::size_t line) {
  long long count = 0;
  if (!integer(token, count) || count < 0)
    throw ParseError("a point count must be a whole number, found " + quote(token), line);
  if (static_cast<unsigned long long>(count) > kMaxMeshElements)
    throw ParseError("the point count " + std::string(token) + " is over the limit of " +
                         std::to_string(kMaxMeshElements),
                     line);
  return static_cast<std::size_t>(count);
}

}  // namespace

MeshData parseXyzFrom(LineReader& src) {
  MeshData mesh;
  std::string_view line;
  std::string spaced;
  std::size_t countLine = 0, announced = 0;
  while (src.next(line)) {
    if (line.find(',') != std::string_view::npos) {
      spaced.assign(line);
      std::replace(spaced.begin(), spaced.end(), ',', ' ');
      line = spaced;
    }
    Tokens t(line);
    const std::size_t n = t.count();
    if (n == 0) continue;
    if (n == 1 && mesh.vertices.empty() && countLine == 0) {
      std::string_view token;
      t.next(token);
      announced = announcedCount(token, src.line());
      countLine = src.line();
      continue;
    }
    if (n < 3)
      throw ParseError("a point needs 3 coordinates x y z, found " + std::to_string(n) +
                           (n == 1 ? " number" : " numbers"),
                       src.line());
    if (mesh.vertices.size() == kMaxMeshElements)
      throw ParseError("more than " + std::to_string(kMaxMeshElements) + " points", src.line());
    mesh.vertices.push_back(coordinates(t, src.line()));
    numbersOnly(t, src.line());
    mesh.vertexLines.push_back(src.line());
  }
  if (countLine != 0 && announced != mesh.vertices.size())
    throw ParseError("the point count on this line says " + std::to_string(announced) +
                         ", but the file holds " + std::to_string(mesh.vertices.size()) + " points",
                     countLine);
  return mesh;
}

}  // namespace convexloc::detail
