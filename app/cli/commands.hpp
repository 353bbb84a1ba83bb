// convexloc CLI — the subcommands, their options, and how they fail.
//
// main.cpp parses the command line into the option structs below and calls one command.
// A command returns normally on success and throws Failure otherwise; main turns that
// into the exit code and the message on stderr. Nothing a command writes to stdout may
// precede a Failure caused by bad input: commands validate everything first.
#pragma once

#include <sys/types.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/text_reader.hpp"

namespace CLI {
class App;
}

namespace convexloc::cli {

// === Exit codes

inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitBadUsage = 2;

// A reason to stop, with the exit code and the complete message for stderr.
class Failure : public std::runtime_error {
 public:
  Failure(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const noexcept { return code_; }
  bool isUsage() const noexcept { return code_ == kExitBadUsage; }

 private:
  int code_;
};

// a bad-usage failure (exit 2); main adds the usage text
[[noreturn]] void failUsage(const std::string& message);

// a bad-input failure about `file` (exit 1): "FILE:LINE: problem", or "FILE: problem" for line 0
[[noreturn]] void failInput(const std::string& file, std::size_t line, const std::string& problem);

// how a file is named in messages: its path, or "<stdin>" for "-"
std::string displayName(const std::string& path);

// Runs `fn`, turning a convexloc::Error into a Failure that names `file` (and its line),
// and a convexloc::UsageError into a bad-usage Failure.
void aboutFile(const std::string& file, const std::function<void()>& fn);

// Opens `path` ("-": standard input) into `in` for reading in passes, refusing a directory.
// Returns where its text starts when it is a regular file (it can be read again from
// there), else -1 (a pipe: the caller spools it).
off_t openForPasses(const std::string& path, std::unique_ptr<InputFile>& in);

// "a, b, c": the names of every value of `all`, as toString writes them
template <class T, std::size_t N>
std::string namesOf(const T (&all)[N]) {
  std::string names;
  for (const T& value : all) names += (names.empty() ? "" : ", ") + std::string(toString(value));
  return names;
}

// === Shapes

// true for a path naming a polyhedron (.off, .obj, .stl or .ply, any case)
bool isPolyhedronPath(std::string_view path);

// The polygon in a vertex file ("-" for stdin), validated, or with `hull` the convex hull of
// its points in any order; Failure naming the file otherwise. `input`, when given, receives
// the vertices as read, before normalisation.
ConvexPolygon loadPolygon(const std::string& path, std::vector<Vec2>* input = nullptr,
                          bool hull = false);

// The polyhedron in an OFF, OBJ, STL or PLY file, validated, or with `hull` the convex hull
// of every vertex the file lists (its faces ignored: a point cloud works); Failure naming the
// file otherwise (a mesh too large to hold is bad input too). `verticesRead`, when given,
// receives how many vertices the file listed.
ConvexPolyhedron loadPolyhedron(const std::string& path, std::size_t* verticesRead = nullptr,
                                bool hull = false);

// The method with that name for a polygon (2D) or a polyhedron (3D); empty names the default
// (polar, cubemap). Otherwise a bad-usage failure listing the choices for that kind of shape.
Method2D method2DOrFail(const std::string& name);
Method3D method3DOrFail(const std::string& name);

// what --hull does, for every command that takes it
inline constexpr const char* kHullHelp =
    "Take the convex hull of the SHAPE file's points instead of the shape as given: the points "
    "in any order, a mesh's faces ignored, a point cloud without faces (a scan's PLY) accepted";

// === Options, one struct per subcommand

// `classify SHAPE POINTS`: where each point lies
struct ClassifyOptions {
  std::string shape;
  std::string points;
  std::string method;            // empty: polar for a polygon, cubemap for a polyhedron
  std::uint32_t resolution = 0;  // 0: chosen from the shape
  bool hull = false;             // the convex hull of the shape file's points
};

// `info SHAPE`: the shape and the subdivisions of its methods
struct InfoOptions {
  std::string shape;
  std::string method;  // empty: every method, in a table
  std::uint32_t resolution = 0;
  bool intersect = false;  // report the line (plane) methods too, building the 3D dual
  bool hull = false;       // the convex hull of the shape file's points
};

// `generate polygon`: a convex polygon of a kind
struct GeneratePolygonOptions {
  std::string kind;
  std::size_t n = 16;
  std::uint64_t seed = 1;
};

// `generate polyhedron`: a convex polyhedron of a kind, as OFF or OBJ
struct GeneratePolyhedronOptions {
  std::string kind;
  std::size_t n = 100;
  std::uint64_t seed = 1;
  std::string format = "off";
};

// `generate points`: query points around a shape
struct GeneratePointsOptions {
  std::string shape;
  std::size_t count = 1000;
  std::uint64_t seed = 1;
  bool nearBoundary = false;
};

// === Commands, one per dimension where the dimension matters
//
// A SHAPE ending in .off, .obj, .stl or .ply is a polyhedron (3D), anything else a polygon
// (2D); both halves of a command share one file and one contract.

void classify2D(const ClassifyOptions& o);  // classify.cpp
void classify3D(const ClassifyOptions& o);
void info2D(const InfoOptions& o);  // info.cpp
void info3D(const InfoOptions& o);
void generatePolygon(const GeneratePolygonOptions& o);  // generate.cpp
void generatePolyhedron(const GeneratePolyhedronOptions& o);
void generatePoints2D(const GeneratePointsOptions& o);
void generatePoints3D(const GeneratePointsOptions& o);

// === Commands that register their own subcommand

// a subcommand, and what runs when the command line names it
struct Command {
  CLI::App* sub = nullptr;
  std::function<void()> action;
};
// `intersect SHAPE LINES [--method] [--clip]` (intersect.cpp)
Command addIntersect(CLI::App& app);

// === Output

// Writes to stdout through a large buffer; a failed write is a Failure.
class Output {
 public:
  Output();
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;
  // appends raw text
  void put(std::string_view text) {
    if (text.size() > buf_.size() - used_) flushBuffer();
    if (text.size() > buf_.size()) {
      writeDirect(text);
      return;
    }
    text.copy(buf_.data() + used_, text.size());
    used_ += text.size();
  }
  // appends a double in the shortest form that reads back to the same double
  void number(double v);
  // appends "x y\n"
  void point(Vec2 p) {
    number(p.x);
    put(" ");
    number(p.y);
    put("\n");
  }
  // appends "x y z\n"
  void point(Vec3 p) {
    number(p.x);
    put(" ");
    number(p.y);
    put(" ");
    number(p.z);
    put("\n");
  }
  // writes everything buffered and flushes stdout; Failure when the write failed
  void finish();

 private:
  void flushBuffer();
  void writeDirect(std::string_view text);
  std::vector<char> buf_;
  std::size_t used_ = 0;
};

// printf into a std::string
template <class... Args>
std::string format(const char* fmt, Args... args) {
  char buf[256];
  int n = std::snprintf(buf, sizeof buf, fmt, args...);
  return std::string(buf, static_cast<std::size_t>(std::clamp(n, 0, 255)));
}

// a duration in the unit that suits it ("12.3 us", "4.56 ms", "1.23 s")
std::string duration(double seconds);  // info.cpp

}  // namespace convexloc::cli
