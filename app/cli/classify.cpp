// convexloc CLI — `classify`: where each point of a file lies, streamed in constant memory,
// for a polygon (2 numbers per point) or a polyhedron (3 numbers per point).
//
// The points are read twice. The first pass parses every line, so that a bad line anywhere
// stops the command before it writes anything; the second pass classifies and writes. A
// regular file is simply read again; anything else (standard input, a pipe) is spooled to
// a temporary file as binary doubles during the first pass.
#include <sys/stat.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <span>

#include "commands.hpp"
#include "convexloc/error.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/text_reader.hpp"

namespace convexloc::cli {
namespace {

// points handled together: one batch call, one block of the spool
constexpr std::size_t kBlock = 4096;

// the output line of each Location, indexed by its value
constexpr std::array<std::string_view, 3> kAnswer = {"inside\n", "boundary\n", "outside\n"};
static_assert(static_cast<int>(Location::Inside) == 0 &&
              static_cast<int>(Location::Boundary) == 1 &&
              static_cast<int>(Location::Outside) == 2);

// closes a FILE when it goes
struct FileCloser {
  void operator()(std::FILE* f) const noexcept { std::fclose(f); }
};

// the point with `Dims` coordinates
template <int Dims>
struct PointOf;
template <>
struct PointOf<2> {
  using type = Vec2;
  static Vec2 from(const double* row) { return {row[0], row[1]}; }
};
template <>
struct PointOf<3> {
  using type = Vec3;
  static Vec3 from(const double* row) { return {row[0], row[1], row[2]}; }
};

// A POINTS file of `Dims` numbers per line, read in two passes; see the top of this file.
template <int Dims>
class PointPasses {
  using Point = typename PointOf<Dims>::type;

 public:
  explicit PointPasses(const std::string& path) : path_(path) {
    start_ = openForPasses(path_, in_);
    if (start_ < 0) {
      spool_.reset(std::tmpfile());
      if (!spool_)
        failInput(path_, 0,
                  std::string("cannot create a temporary file to hold the points: ") +
                      std::strerror(errno));
    }
  }

  // pass 1: parses every row, spooling them when the input cannot be read twice
  void validate() {
    aboutFile(path_, [&] {
      RowReader reader(in_->get(), Dims);
      std::size_t used = 0;
      double row[Dims];
      while (reader.next(row)) {
        if (!spool_) continue;
        block_[used++] = PointOf<Dims>::from(row);
        if (used == kBlock) spoolBlock(used);
      }
      if (spool_) spoolBlock(used);
    });
  }

  // pass 2: hands the points to `sink` in order, in blocks of at most kBlock
  template <class Sink>
  void forEachBlock(Sink&& sink) {
    if (spool_) {
      std::rewind(spool_.get());
      for (;;) {
        std::size_t got = std::fread(block_.data(), sizeof(Point), kBlock, spool_.get());
        if (got > 0) sink(std::span<const Point>(block_.data(), got));
        if (got < kBlock) break;
      }
      if (std::ferror(spool_.get()))
        failInput(path_, 0,
                  std::string("cannot read back the spooled points: ") + std::strerror(errno));
      return;
    }
    if (fseeko(in_->get(), start_, SEEK_SET) != 0)
      failInput(path_, 0, std::string("cannot read the file again: ") + std::strerror(errno));
    aboutFile(path_, [&] {
      RowReader reader(in_->get(), Dims);
      std::size_t used = 0;
      double row[Dims];
      while (reader.next(row)) {
        block_[used++] = PointOf<Dims>::from(row);
        if (used == kBlock) {
          sink(std::span<const Point>(block_.data(), used));
          used = 0;
        }
      }
      if (used > 0) sink(std::span<const Point>(block_.data(), used));
    });
  }

 private:
  // appends block_[0..used) to the spool and empties the block
  void spoolBlock(std::size_t& used) {
    if (used > 0 && std::fwrite(block_.data(), sizeof(Point), used, spool_.get()) != used)
      failInput(
          path_, 0,
          std::string("cannot spool the points to a temporary file: ") + std::strerror(errno));
    used = 0;
  }

  std::string path_;
  std::unique_ptr<InputFile> in_;
  std::unique_ptr<std::FILE, FileCloser> spool_;
  off_t start_ = -1;  // where the points start in a regular file; -1 when spooled
  std::array<Point, kBlock> block_{};
};

// Checks every point of `path`, then writes the answer of `locator` for each, in order.
template <int Dims, class Locator>
void classifyPoints(const Locator& locator, const std::string& path) {
  auto passes = std::make_unique<PointPasses<Dims>>(path);
  passes->validate();

  Output out;
  std::array<Location, kBlock> answers{};
  passes->forEachBlock([&](std::span<const typename PointOf<Dims>::type> points) {
    std::span<Location> result(answers.data(), points.size());
    locator.locate(points, result);
    for (Location l : result) out.put(kAnswer[static_cast<std::size_t>(l)]);
  });
  out.finish();
}

// SHAPE and POINTS cannot share standard input
void rejectBothStdin(const ClassifyOptions& o) {
  if (o.shape == "-" && o.points == "-")
    failUsage("SHAPE and POINTS cannot both be standard input ('-')");
}

}  // namespace

void classify2D(const ClassifyOptions& o) {
  const Method2D method = method2DOrFail(o.method);
  rejectBothStdin(o);
  const ConvexPolygon polygon = loadPolygon(o.shape, nullptr, o.hull);
  std::unique_ptr<Locator2D> locator;
  aboutFile(o.shape, [&] { locator = std::make_unique<Locator2D>(polygon, method, o.resolution); });
  classifyPoints<2>(*locator, o.points);
}

void classify3D(const ClassifyOptions& o) {
  const Method3D method = method3DOrFail(o.method);
  rejectBothStdin(o);
  std::unique_ptr<Locator3D> locator;
  {
    // the locator keeps its own copy: the polyhedron goes before the points are read
    const ConvexPolyhedron polyhedron = loadPolyhedron(o.shape, nullptr, o.hull);
    aboutFile(o.shape,
              [&] { locator = std::make_unique<Locator3D>(polyhedron, method, o.resolution); });
  }
  classifyPoints<3>(*locator, o.points);
}

}  // namespace convexloc::cli
