// convexloc — the mesh writers: OFF, OBJ, STL and PLY; in text every coordinate is the
// shortest decimal that reads back to the same double, in binary the exact bits.
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "convexloc/detail/chars.hpp"
#include "convexloc/error.hpp"
#include "convexloc/mesh_reader.hpp"
#include "io/byte_source.hpp"

namespace convexloc {
namespace {

// Text for a FILE, written out a block of about 64 KiB at a time.
class BlockWriter {
 public:
  explicit BlockWriter(std::FILE* out) : out_(out) {}
  // the text of the block being filled
  std::string& text() noexcept { return text_; }
  // ends a line; writes the block once it is full
  void endLine() {
    text_ += '\n';
    spill();
  }
  // writes the block once it is full
  void spill() {
    if (text_.size() > (1 << 16)) flush();
  }
  // writes and empties the block; Error on a write failure
  void flush() {
    if (!text_.empty() && std::fwrite(text_.data(), 1, text_.size(), out_) != text_.size())
      throw Error(std::string("write error: ") + std::strerror(errno));
    text_.clear();
  }

 private:
  std::FILE* out_;
  std::string text_;
};

// appends the shortest round-trip decimal of v
void appendNumber(std::string& out, double v) {
  char buf[32];
  auto [ptr, ec] = detail::doubleToChars(buf, buf + sizeof buf, v);
  out.append(buf, ptr);
}

// one line a vertex: `keyword` (if any), then "x y z"
void writeVertices(BlockWriter& w, const MeshData& mesh, std::string_view keyword) {
  for (const Vec3& p : mesh.vertices) {
    std::string& text = w.text();
    text += keyword;
    appendNumber(text, p.x);
    text += ' ';
    appendNumber(text, p.y);
    text += ' ';
    appendNumber(text, p.z);
    w.endLine();
  }
}

// one line a face: what `head` writes first, then its vertex indices counted from `base`
template <class Head>
void writeFaces(BlockWriter& w, const MeshData& mesh, std::uint32_t base, Head&& head) {
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto face = mesh.face(f);
    std::string& text = w.text();
    head(text, face);
    for (std::uint32_t i : face) (text += ' ') += std::to_string(i + base);
    w.endLine();
  }
}

// the shortest round-trip decimal of v
std::string decimal(double v) {
  std::string s;
  appendNumber(s, v);
  return s;
}

// `v` as a float, which must hold it exactly (`format` names the file format in the error)
float exactFloat(double v, const char* format) {
  if (!(std::fabs(v) <= static_cast<double>(std::numeric_limits<float>::max())))
    throw Error(std::string(format) + " stores coordinates as float32, and " + decimal(v) +
                " is beyond its range: write OFF, OBJ or PLY with double properties instead");
  // through a volatile: GCC 12.2's SLP vectorizer may fold a double-float-double round trip
  // over neighbouring coordinates into nothing
  volatile float rounded = static_cast<float>(v);
  if (static_cast<double>(rounded) != v)
    throw Error(std::string(format) + " stores coordinates as float32, and " + decimal(v) +
                " is not one: write OFF, OBJ or PLY with double properties instead");
  return static_cast<float>(v);
}

// how many triangles a fan triangulation of every face makes
std::size_t fanTriangles(const MeshData& mesh) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    n += std::max<std::size_t>(mesh.face(f).size(), 2) - 2;
  return n;
}

// calls `emit(a, b, c)` for each triangle of each face's fan from its first vertex
template <class Emit>
void forEachTriangle(const MeshData& mesh, Emit&& emit) {
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t k = 2; k < face.size(); ++k) emit(face[0], face[k - 1], face[k]);
  }
}

// the ASCII STL of the triangles
void writeStlText(BlockWriter& w, const MeshData& mesh) {
  w.text() += "solid convexloc\n";
  forEachTriangle(mesh, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::string& text = w.text();
    text += "facet normal 0 0 0\nouter loop\n";
    for (std::uint32_t i : {a, b, c}) {
      const Vec3 p = mesh.vertices[i];
      text += "vertex ";
      appendNumber(text, p.x);
      text += ' ';
      appendNumber(text, p.y);
      text += ' ';
      appendNumber(text, p.z);
      text += '\n';
    }
    text += "endloop\nendfacet";
    w.endLine();
  });
  w.text() += "endsolid convexloc\n";
}

// the binary STL of the triangles
void writeStlBinary(BlockWriter& w, const MeshData& mesh) {
  const std::size_t count = fanTriangles(mesh);
  if (count > std::numeric_limits<std::uint32_t>::max())
    throw Error("too many triangles for a binary STL");
  std::string header = "binary STL written by convexloc";
  header.resize(80, ' ');
  w.text() += header;
  detail::storeScalar(w.text(), static_cast<std::uint32_t>(count), false);
  forEachTriangle(mesh, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::string& out = w.text();
    out.append(12, '\0');  // the normal, which readers recompute from the winding
    for (std::uint32_t i : {a, b, c})
      for (double v : {mesh.vertices[i].x, mesh.vertices[i].y, mesh.vertices[i].z})
        detail::storeScalar(out, exactFloat(v, "binary STL"), false);
    out.append(2, '\0');
    w.spill();
  });
}

// the PLY header for `mesh`
std::string plyHeader(const MeshData& mesh, PlyEncoding encoding, bool float32, bool wideCount) {
  static constexpr const char* kFormats[] = {"ascii", "binary_little_endian", "binary_big_endian"};
  const char* type = float32 ? "float" : "double";
  std::string h = std::string("ply\nformat ") + kFormats[static_cast<int>(encoding)] +
                  " 1.0\ncomment written by convexloc\nelement vertex " +
                  std::to_string(mesh.vertices.size()) + "\n";
  for (const char* axis : {"x", "y", "z"}) h += std::string("property ") + type + " " + axis + "\n";
  h += "element face " + std::to_string(mesh.faceCount()) + "\nproperty list " +
       (wideCount ? "uint" : "uchar") + " int vertex_indices\nend_header\n";
  return h;
}

// the binary PLY records of `mesh`
void writePlyBinary(BlockWriter& w, const MeshData& mesh, bool big, bool float32, bool wideCount) {
  for (const Vec3& p : mesh.vertices) {
    for (double v : {p.x, p.y, p.z}) {
      if (float32)
        detail::storeScalar(w.text(), exactFloat(v, "PLY with float properties"), big);
      else
        detail::storeScalar(w.text(), v, big);
    }
    w.spill();
  }
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto face = mesh.face(f);
    if (wideCount)
      detail::storeScalar(w.text(), static_cast<std::uint32_t>(face.size()), big);
    else
      detail::storeScalar(w.text(), static_cast<std::uint8_t>(face.size()), big);
    for (std::uint32_t i : face) detail::storeScalar(w.text(), static_cast<std::int32_t>(i), big);
    w.spill();
  }
}

}  // namespace

void writeStl(std::FILE* out, const MeshData& mesh, bool ascii) {
  BlockWriter w(out);
  if (ascii)
    writeStlText(w, mesh);
  else
    writeStlBinary(w, mesh);
  w.flush();
}

void writePly(std::FILE* out, const MeshData& mesh, PlyEncoding encoding, bool float32) {
  std::size_t widest = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) widest = std::max(widest, mesh.face(f).size());
  const bool wideCount = widest > 255;
  BlockWriter w(out);
  w.text() = plyHeader(mesh, encoding, float32, wideCount);
  if (encoding != PlyEncoding::Ascii) {
    writePlyBinary(w, mesh, encoding == PlyEncoding::BinaryBigEndian, float32, wideCount);
  } else {
    if (float32)
      for (const Vec3& p : mesh.vertices)
        for (double v : {p.x, p.y, p.z}) exactFloat(v, "PLY with float properties");
    writeVertices(w, mesh, "");
    writeFaces(w, mesh, 0,
               [](std::string& text, auto face) { text += std::to_string(face.size()); });
  }
  w.flush();
}

void writeOff(std::FILE* out, const MeshData& mesh) {
  BlockWriter w(out);
  w.text() = "OFF\n" + std::to_string(mesh.vertices.size()) + ' ' +
             std::to_string(mesh.faceCount()) + " 0\n";
  writeVertices(w, mesh, "");
  writeFaces(w, mesh, 0, [](std::string& text, auto face) { text += std::to_string(face.size()); });
  w.flush();
}

void writeObj(std::FILE* out, const MeshData& mesh) {
  BlockWriter w(out);
  writeVertices(w, mesh, "v ");
  writeFaces(w, mesh, 1, [](std::string& text, auto) { text += 'f'; });
  w.flush();
}

}  // namespace convexloc
