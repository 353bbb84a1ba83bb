// convexloc CLI — failures, shape loading and buffered output shared by the commands.
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "convexloc/error.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/text_reader.hpp"

namespace convexloc::cli {

void failUsage(const std::string& message) {
  throw Failure(kExitBadUsage, message);
}

void failInput(const std::string& file, std::size_t line, const std::string& problem) {
  std::string where = displayName(file);
  if (line > 0) where += ':' + std::to_string(line);
  throw Failure(kExitBadInput, where + ": " + problem);
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
  return endsWith(".off") || endsWith(".obj");
}

namespace {

// a directory opens as a file on some systems; say plainly that it is not one
void rejectDirectory(const std::string& path) {
  std::error_code ec;
  if (path != "-" && std::filesystem::is_directory(path, ec))
    failInput(path, 0, "cannot open: it is a directory");
}

}  // namespace

ConvexPolygon loadPolygon(const std::string& path, std::vector<Vec2>* input) {
  rejectDirectory(path);
  PointList list;
  aboutFile(path, [&] { list = readPoints2D(path); });
  if (list.points.empty())
    failInput(path, 0, "no vertices: a polygon file lists one vertex 'x y' per line");
  std::optional<ConvexPolygon> polygon;
  aboutFile(path, [&] { polygon.emplace(list.points, list.lines); });
  if (input) *input = std::move(list.points);
  return std::move(*polygon);
}

ConvexPolyhedron loadPolyhedron(const std::string& path, std::size_t* verticesRead) {
  rejectDirectory(path);
  MeshData mesh;
  aboutFile(path, [&] { mesh = readMesh(path); });
  if (verticesRead) *verticesRead = mesh.vertices.size();
  try {
    return ConvexPolyhedron(mesh);
  } catch (const Error& e) {
    // every complaint about a mesh read from a file is about the file, a size limit included
    failInput(path, e.line(), e.what());
  }
}

namespace {

// "a, b, c": the names of every method of one dimension
template <class Method, std::size_t N>
std::string methodNames(const Method (&all)[N]) {
  std::string names;
  for (Method m : all) names += (names.empty() ? "" : ", ") + std::string(toString(m));
  return names;
}

}  // namespace

Method2D method2DOrFail(const std::string& name) {
  if (name.empty()) return Method2D::Polar;
  if (auto m = parseMethod2D(name)) return *m;
  const std::string choices = methodNames(kAllMethods2D);
  if (parseMethod3D(name))
    failUsage("method '" + name + "' is for polyhedra (.off/.obj); for a polygon choose one of " +
              choices);
  failUsage("unknown method '" + name + "' for a polygon; choose one of " + choices);
}

Method3D method3DOrFail(const std::string& name) {
  if (name.empty()) return Method3D::Cubemap;
  if (auto m = parseMethod3D(name)) return *m;
  const std::string choices = methodNames(kAllMethods3D);
  if (parseMethod2D(name))
    failUsage("method '" + name + "' is for polygons; for a polyhedron (.off/.obj) choose one of " +
              choices);
  failUsage("unknown method '" + name + "' for a polyhedron; choose one of " + choices);
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
