// convexloc CLI — `intersect`: how each line of a file meets a polygon (4 numbers per line:
// two points), or each plane a polyhedron (9 numbers: three points); with --clip, the part of
// each segment inside the polygon. Streamed in constant memory.
//
// The rows are read twice. The first pass parses every row and checks that it defines a line
// (two different points) or a plane (three points not on one line), so that a bad row
// anywhere stops the command before it writes anything; the second pass answers. A regular
// file is read again; anything else (standard input, a pipe) is spooled to a temporary file
// as binary doubles during the first pass.
#include <sys/stat.h>
#include <CLI/CLI.hpp>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "commands.hpp"
#include "convexloc/intersect2d.hpp"
#include "convexloc/intersect3d.hpp"
#include "convexloc/text_reader.hpp"

namespace convexloc::cli {
namespace {

// the options of `intersect`
struct IntersectOptions {
  std::string shape;
  std::string lines;
  std::string method;  // empty: dual
  bool clip = false;
  bool hull = false;  // the convex hull of the shape file's points
};

// A LINES file of `Numbers` numbers per row, read in two passes; see the top of this file.
template <int Numbers>
class RowPasses {
 public:
  using Row = std::array<double, Numbers>;

  explicit RowPasses(const std::string& path) : path_(path) {
    start_ = openForPasses(path_, in_);
    if (start_ < 0 && !(spool_ = std::tmpfile()))
      failInput(path_, 0, std::string("cannot create a temporary file: ") + std::strerror(errno));
  }
  ~RowPasses() {
    if (spool_) std::fclose(spool_);
  }
  RowPasses(const RowPasses&) = delete;
  RowPasses& operator=(const RowPasses&) = delete;

  // pass 1: parses every row; `problem(row)` names what is wrong with it, or is empty
  template <class Check>
  void validate(Check&& problem) {
    RowReader reader(in_->get(), Numbers);
    Row row{};
    for (;;) {
      bool more = false;
      aboutFile(path_, [&] { more = reader.next(row.data()); });
      if (!more) break;
      if (const std::string p = problem(row); !p.empty()) failInput(path_, reader.line(), p);
      if (spool_ && std::fwrite(row.data(), sizeof row, 1, spool_) != 1)
        failInput(path_, 0, std::string("cannot spool the rows: ") + std::strerror(errno));
    }
  }

  // pass 2: hands every row to `answer`, in order
  template <class Answer>
  void forEach(Answer&& answer) {
    Row row{};
    if (spool_) {
      std::rewind(spool_);
      while (std::fread(row.data(), sizeof row, 1, spool_) == 1) answer(row);
      if (std::ferror(spool_))
        failInput(path_, 0, std::string("cannot read back the rows: ") + std::strerror(errno));
      return;
    }
    if (fseeko(in_->get(), start_, SEEK_SET) != 0)
      failInput(path_, 0, std::string("cannot read the file again: ") + std::strerror(errno));
    aboutFile(path_, [&] {
      RowReader reader(in_->get(), Numbers);
      while (reader.next(row.data())) answer(row);
    });
  }

 private:
  std::string path_;
  std::unique_ptr<InputFile> in_;
  std::FILE* spool_ = nullptr;
  off_t start_ = -1;  // where the rows start in a regular file; -1 when spooled
};

// appends "x1 y1 x2 y2\n"
void putSegment(Output& out, const Segment2D& s) {
  for (double v : {s.a.x, s.a.y, s.b.x}) {
    out.number(v);
    out.put(" ");
  }
  out.number(s.b.y);
  out.put("\n");
}

void intersect2D(const IntersectOptions& o) {
  const std::optional<LineMethod> method =
      o.method.empty() ? LineMethod::Dual : parseLineMethod(o.method);
  if (!method)
    failUsage("unknown method '" + o.method +
              "' for a polygon: vertices O(N), bisection O(log N) or dual O(1)");
  if (o.shape == "-" && o.lines == "-")
    failUsage("SHAPE and LINES cannot both be standard input ('-')");
  std::unique_ptr<LineIntersector> intersector;
  {
    const ConvexPolygon polygon = loadPolygon(o.shape, nullptr, o.hull);
    aboutFile(o.shape, [&] { intersector = std::make_unique<LineIntersector>(polygon, *method); });
  }
  RowPasses<4> rows(o.lines);
  rows.validate([](const RowPasses<4>::Row& r) {
    return r[0] == r[2] && r[1] == r[3] ? std::string("the two points of the line are equal")
                                        : std::string();
  });
  Output out;
  rows.forEach([&](const RowPasses<4>::Row& r) {
    const Vec2 p1{r[0], r[1]}, p2{r[2], r[3]};
    if (!o.clip) {
      out.put(toString(intersector->classify(p1, p2)));
      out.put("\n");
    } else if (const std::optional<Segment2D> s = intersector->clip(p1, p2)) {
      putSegment(out, *s);
    } else {
      out.put("outside\n");
    }
  });
  out.finish();
}

void intersect3D(const IntersectOptions& o) {
  const std::optional<PlaneMethod> method =
      o.method.empty() ? PlaneMethod::Dual : parsePlaneMethod(o.method);
  if (!method)
    failUsage("unknown method '" + o.method + "' for a polyhedron: vertices O(V) or dual O(1)");
  if (o.clip) failUsage("--clip takes a polygon: a polyhedron clips no segments here");
  if (o.lines == "-" && o.shape == "-")
    failUsage("SHAPE and LINES cannot both be standard input ('-')");
  std::unique_ptr<PlaneIntersector> intersector;
  {
    const ConvexPolyhedron polyhedron = loadPolyhedron(o.shape, nullptr, o.hull);
    aboutFile(o.shape,
              [&] { intersector = std::make_unique<PlaneIntersector>(polyhedron, *method); });
  }
  RowPasses<9> rows(o.lines);
  rows.validate([](const RowPasses<9>::Row& r) {
    return collinear({r[0], r[1], r[2]}, {r[3], r[4], r[5]}, {r[6], r[7], r[8]})
               ? std::string("the three points of the plane lie on one line")
               : std::string();
  });
  Output out;
  rows.forEach([&](const RowPasses<9>::Row& r) {
    out.put(toString(
        intersector->classify({r[0], r[1], r[2]}, {r[3], r[4], r[5]}, {r[6], r[7], r[8]})));
    out.put("\n");
  });
  out.finish();
}

}  // namespace

Command addIntersect(CLI::App& app) {
  auto o = std::make_shared<IntersectOptions>();
  CLI::App* sub = app.add_subcommand(
      "intersect",
      "Print misses, touches or crosses for each line against a polygon (each plane against a "
      "polyhedron), one line per input line, in order; with --clip, each segment's part inside");
  sub->add_option("SHAPE", o->shape,
                  "Polygon file, one vertex 'x y' per line, or a polyhedron (.off/.obj/.stl/.ply)")
      ->required();
  sub->add_option("LINES", o->lines,
                  "One line 'x1 y1 x2 y2' (two different points) per line for a polygon, one plane "
                  "'x1 y1 z1 x2 y2 z2 x3 y3 z3' (three points not on one line) for a polyhedron; "
                  "'-' reads standard input")
      ->required();
  sub->add_option("-m,--method", o->method,
                  "polygon: vertices O(N), bisection O(log N) or dual O(1) (default dual); "
                  "polyhedron: vertices O(V) or dual O(1) (default dual)");
  sub->add_flag("--clip", o->clip,
                "Polygon only: each line is a segment; print its part inside 'x1 y1 x2 y2', in "
                "its own direction (a point twice when it only touches), or 'outside'");
  sub->add_flag("--hull", o->hull, kHullHelp);
  return {sub, [o] { isPolyhedronPath(o->shape) ? intersect3D(*o) : intersect2D(*o); }};
}

}  // namespace convexloc::cli
