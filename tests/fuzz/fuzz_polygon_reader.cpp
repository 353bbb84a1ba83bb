// Fuzz target: a polygon file as `convexloc` reads it: readPoints2D on the bytes (through a
// path, as the tool opens it), then ConvexPolygon. Either a ParseError or GeometryError
// naming a line of the file, or a polygon that is exactly what normalisation promises and
// that every method locates exactly at its vertices, edge midpoints and their neighbours.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "check2d.hpp"
#include "convexloc/error.hpp"
#include "convexloc/text_reader.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace fuzz;

// The bytes as an anonymous in-memory file, named by a path readPoints2D can open.
class MemPath {
 public:
  MemPath(const std::uint8_t* data, std::size_t size) {
    fd_ = memfd_create("convexloc-fuzz", 0);
    if (fd_ < 0) fail("memfd_create failed");
    for (std::size_t done = 0; done < size;) {
      ssize_t n = ::write(fd_, data + done, size - done);
      if (n <= 0) fail("cannot write the input to the memfd");
      done += static_cast<std::size_t>(n);
    }
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  ~MemPath() { ::close(fd_); }
  MemPath(const MemPath&) = delete;
  MemPath& operator=(const MemPath&) = delete;
  const std::string& path() const noexcept { return path_; }

 private:
  int fd_ = -1;
  std::string path_;
};

// lines in the text: a last line without '\n' counts
std::size_t lineCount(const std::uint8_t* data, std::size_t size) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < size; ++i) n += data[i] == '\n';
  return n + (size > 0 && data[size - 1] != '\n');
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  MemPath file(data, size);
  const std::size_t lines = lineCount(data, size);
  convexloc::PointList list;
  try {
    list = convexloc::readPoints2D(file.path());
  } catch (const convexloc::ParseError& e) {
    if (e.line() == 0 || e.line() > lines)
      fail("ParseError names line " + std::to_string(e.line()) + " of a " + std::to_string(lines) +
           "-line file: " + e.what());
    return 0;
  }
  if (list.lastLine != lines)
    fail("readPoints2D counted " + std::to_string(list.lastLine) + " lines, the file has " +
         std::to_string(lines));
  try {
    ConvexPolygon poly(list.points, list.lines);
    checkPolygon(poly, list.points);
    if (poly.size() <= 64) {
      std::vector<Vec2> queries;
      addHardPoints(queries, poly.vertices());
      checkMethods(poly, queries, 0);
    }
  } catch (const convexloc::GeometryError& e) {
    if (e.line() > lines)
      fail("GeometryError names line " + std::to_string(e.line()) + " of a " +
           std::to_string(lines) + "-line file: " + e.what());
    if (!list.points.empty() && e.line() == 0)
      fail(std::string("GeometryError without a line for a file of points: ") + e.what());
  }
  return 0;
}
