// The C++ locators' answers, for the Python tests to compare the module with.
//
// Usage: python_reference SHAPE POINTS METHOD RESOLUTION ANSWERS
//   SHAPE      a polygon file (.txt) or a polyhedron (.off, .obj), read by core's readers
//   POINTS     raw native float64, 2 (polygon) or 3 (polyhedron) per point
//   METHOD     a method name of the shape's dimension
//   ANSWERS    written: one byte per point, the Location code from locate(p), point by point
// Each point goes through the single-point locate, so the module's batch path is compared
// with core's scalar path.
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/text_reader.hpp"

namespace {

using namespace convexloc;

// the whole file as bytes
std::vector<char> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// every point of the raw file, located one at a time
template <class Locator, class Point>
std::vector<char> answers(const Locator& locator, const std::vector<char>& raw) {
  std::vector<Point> points(raw.size() / sizeof(Point));
  if (!points.empty()) std::memcpy(points.data(), raw.data(), points.size() * sizeof(Point));
  std::vector<char> out;
  for (const Point& p : points) out.push_back(static_cast<char>(locator.locate(p)));
  return out;
}

// the answers for the shape at `shape` with the named method
std::vector<char> run(const std::string& shape, const std::vector<char>& raw,
                      const std::string& method, std::uint32_t resolution) {
  if (meshFormatOf(shape)) {
    const Locator3D locator(loadPolyhedron(shape), parseMethod3D(method).value(), resolution);
    return answers<Locator3D, Vec3>(locator, raw);
  }
  const PointList list = readPoints2D(shape);
  const Locator2D locator(ConvexPolygon(list.points, list.lines), parseMethod2D(method).value(),
                          resolution);
  return answers<Locator2D, Vec2>(locator, raw);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: python_reference SHAPE POINTS METHOD RESOLUTION ANSWERS\n");
    return 2;
  }
  try {
    const auto out =
        run(argv[1], readBytes(argv[2]), argv[3], static_cast<std::uint32_t>(std::stoul(argv[4])));
    std::ofstream(argv[5], std::ios::binary)
        .write(out.data(), static_cast<std::streamsize>(out.size()));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "python_reference: %s\n", e.what());
    return 1;
  }
  return 0;
}
