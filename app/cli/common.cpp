// convexloc CLI — failures, shape loading and buffered output shared by the commands.
#include <sys/stat.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/text_reader.hpp"

namespace convexloc::cli {

void failUsage(const std::string& message) {
  throw Failure(kExitBadUsage, message);
}

void failInput(const std::string& file, std::size_t line, const std::string& problem) {
  throw Failure(kExitBadInput, located(file, line, problem));
}

off_t openForPasses(const std::string& path, std::unique_ptr<InputFile>& in) {
  aboutFile(path, [&] { in = std::make_unique<InputFile>(path); });
  off_t start = -1;
  struct stat st {};
  if (fstat(fileno(in->get()), &st) == 0) {
    if (S_ISDIR(st.st_mode)) failInput(path, 0, "cannot open: it is a directory");
    if (S_ISREG(st.st_mode)) start = ftello(in->get());
  }
  return start;
}

std::string displayName(const std::string& path) {
  return path == "-" ? "<stdin>" : path;
}

void aboutFile(const std::string& file, const std::function<void()>& fn) {
  try {
    fn();
  } catch (const UsageError& e) {
    failUsage(e.what());
  } catch (const Error& e) {
    failInput(file, e.line(), e.what());
  }
}

bool isPolyhedronPath(std::string_view path) {
  auto endsWith = [&](std::string_view suffix) {
    if (path.size() < suffix.size()) return false;
    std::string_view tail = path.substr(path.size() - suffix.size());
    for (std::size_t i = 0; i < tail.size(); ++i) {
      char c = tail[i];
      if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
      if (c != suffix[i]) return false;
    }
    return true;
  };
  return endsWith(".off") || endsWith(".obj") || endsWith(".stl") || endsWith(".ply") ||
         endsWith(".xyz") || endsWith(".pts");
}

namespace {

// a directory opens as a file on some systems; say plainly that it is not one
void rejectDirectory(const std::string& path) {
  std::error_code ec;
  if (path != "-" && std::filesystem::is_directory(path, ec))
    failInput(path, 0, "cannot open: it is a directory");
}

}  // namespace

ConvexPolygon loadPolygon(const std::string& path, std::vector<Vec2>* input, bool hull) {
  rejectDirectory(path);
  PointList list;
  aboutFile(path, [&] { list = readPoints2D(path); });
  if (list.points.empty())
    failInput(path, 0, "no vertices: a polygon file lists one vertex 'x y' per line");
  std::optional<ConvexPolygon> polygon;
  aboutFile(path, [&] {
    if (hull)
      polygon.emplace(convexHull(list.points));
    else
      polygon.emplace(list.points, list.lines);
  });
  if (input) *input = std::move(list.points);
  return std::move(*polygon);
}

ConvexPolyhedron loadPolyhedron(const std::string& path, std::size_t* verticesRead, bool hull) {
  rejectDirectory(path);
  MeshData mesh;
  aboutFile(path, [&] { mesh = readMesh(path); });
  if (verticesRead) *verticesRead = mesh.vertices.size();
  try {
    return hull ? ConvexPolyhedron::hullOf(mesh.vertices) : polyhedronOf(mesh);
  } catch (const Error& e) {
    // every complaint about a mesh read from a file is about the file, a size limit included
    failInput(path, e.line(), e.what());
  }
}

namespace {

// how a method error names the shapes of each dimension
struct ShapeWords {
  const char* one;      // "a polygon"
  const char* oneFile;  // "a polygon", with the extensions where they decide
  const char* others;   // the other dimension's shapes: "polyhedra (.off/.obj/.stl/.ply)"
};

constexpr ShapeWords kPolygonWords{"a polygon", "a polygon", "polyhedra (.off/.obj/.stl/.ply)"};
constexpr ShapeWords kPolyhedronWords{"a polyhedron", "a polyhedron (.off/.obj/.stl/.ply)",
                                      "polygons"};

// the method `parsed` from `name`; `fallback` for no name; otherwise a bad-usage failure that
// says whether the name belongs to the other dimension
template <class Method, std::size_t N>
Method methodOrFail(const std::string& name, std::optional<Method> parsed, bool otherDimension,
                    Method fallback, const Method (&all)[N], const ShapeWords& words) {
  if (name.empty()) return fallback;
  if (parsed) return *parsed;
  const std::string choices = namesOf(all);
  if (otherDimension)
    failUsage("method '" + name + "' is for " + words.others + "; for " + words.oneFile +
              " choose one of " + choices);
  failUsage("unknown method '" + name + "' for " + words.one + "; choose one of " + choices);
}

}  // namespace

Method2D method2DOrFail(const std::string& name) {
  return methodOrFail(name, parseMethod2D(name), parseMethod3D(name).has_value(), Method2D::Polar,
                      kAllMethods2D, kPolygonWords);
}

Method3D method3DOrFail(const std::string& name) {
  return methodOrFail(name, parseMethod3D(name), parseMethod2D(name).has_value(), Method3D::Cubemap,
                      kAllMethods3D, kPolyhedronWords);
}

// === Output

Output::Output() : buf_(std::size_t{1} << 20) {}

void Output::number(double v) {
  constexpr std::size_t kLongest = 32;  // "-1.2345678901234567e-308" and some room
  if (buf_.size() - used_ < kLongest) flushBuffer();
  char* at = buf_.data() + used_;
  auto [end, ec] = std::to_chars(at, at + kLongest, v);
  if (ec != std::errc{}) {
    // cannot happen for a finite double in 32 bytes; keep the output well formed anyway
    end = std::to_chars(at, at + kLongest, v, std::chars_format::scientific, 17).ptr;
  }
  used_ += static_cast<std::size_t>(end - at);
}

void Output::flushBuffer() {
  writeDirect({buf_.data(), used_});
  used_ = 0;
}

void Output::writeDirect(std::string_view text) {
  if (text.empty()) return;
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size())
    throw Failure(kExitBadInput,
                  std::string("convexloc: cannot write the output: ") + std::strerror(errno));
}

void Output::finish() {
  flushBuffer();
  if (std::fflush(stdout) != 0 || std::ferror(stdout))
    throw Failure(kExitBadInput,
                  std::string("convexloc: cannot write the output: ") + std::strerror(errno));
}

}  // namespace convexloc::cli
