// convexloc — the OBJ reader: v and f statements, every other one ignored.
//
// One statement per line through LineReader, numbers through parseRow; a face may refer to
// a vertex defined later, so the largest reference is checked once the file is read.
#include "convexloc/mesh_reader.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/text_reader.hpp"
#include "io/mesh_parsers.hpp"
#include "io/mesh_tokens.hpp"

namespace convexloc::detail {
namespace {

// === OBJ: v and f statements, every other one ignored

// a "v x y z [w | r g b [a]]" statement, after its "v"
Vec3 objVertex(Tokens& t, std::size_t line) {
  const std::size_t count = t.count();
  if (count != 3 && count != 4 && count != 6 && count != 7)
    throw ParseError("a vertex needs 3 coordinates (then w, or r g b colours), found " +
                         std::to_string(count) + " numbers",
                     line);
  const Vec3 p = coordinates(t, line);
  if (count == 4) {
    std::string_view tok;
    t.next(tok);
    if (number(tok, line) != 1.0)
      throw ParseError("a vertex weight w other than 1 is not supported: " + quote(tok), line);
  }
  numbersOnly(t, line);
  return p;
}

// A face's vertex reference ("i", "i/t", "i//n", "i/t/n"), 0-based; negative counts back
// from the last of the `defined` vertices so far, positive may point past them (checked at
// the end of the file).
long long objReference(std::string_view tok, std::size_t defined, std::size_t line) {
  const std::string_view ref = tok.substr(0, tok.find('/'));
  long long idx = 0;
  if (!integer(ref, idx)) throw ParseError("not a vertex reference: " + quote(tok), line);
  if (idx == 0) throw ParseError("vertex reference 0: OBJ numbers vertices from 1", line);
  if (idx < 0) {
    const long long resolved = static_cast<long long>(defined) + idx;
    if (resolved < 0)
      throw ParseError("vertex reference " + std::string(ref) +
                           " points before the first vertex (only " + std::to_string(defined) +
                           " so far)",
                       line);
    return resolved;
  }
  if (static_cast<unsigned long long>(idx - 1) >= kMaxMeshElements)
    throw ParseError("vertex reference " + std::string(ref) + " is out of range", line);
  return idx - 1;
}

// An OBJ file being read: the mesh so far, and the largest vertex reference with its line,
// checked once every vertex is known.
struct ObjReading {
  MeshData mesh;
  std::size_t maxRef = 0, maxRefLine = 0;
  std::vector<std::uint32_t> poly;  // the face being read

  // an "f a b c ..." statement, after its "f"
  void face(Tokens& t, std::size_t line) {
    poly.clear();
    std::string_view tok;
    while (t.next(tok)) {
      const long long idx = objReference(tok, mesh.vertices.size(), line);
      if (static_cast<std::size_t>(idx) >= maxRef) {
        maxRef = static_cast<std::size_t>(idx) + 1;
        maxRefLine = line;
      }
      poly.push_back(static_cast<std::uint32_t>(idx));
    }
    if (poly.size() < 3)
      throw ParseError(
          "a face needs at least 3 vertices, this one has " + std::to_string(poly.size()), line);
    if (mesh.faceCount() >= kMaxMeshElements)
      throw ParseError("more than " + std::to_string(kMaxMeshElements) + " faces", line);
    mesh.addFace(poly);
    mesh.faceLines.push_back(line);
  }

  // a "v ..." statement, after its "v"
  void vertex(Tokens& t, std::size_t line) {
    const Vec3 p = objVertex(t, line);
    if (mesh.vertices.size() >= kMaxMeshElements)
      throw ParseError("more than " + std::to_string(kMaxMeshElements) + " vertices", line);
    mesh.vertices.push_back(p);
    mesh.vertexLines.push_back(line);
  }
};

}  // namespace

// the OBJ subset of the header comment: v and f statements, the rest ignored
MeshData parseObjFrom(LineReader& src) {
  ObjReading obj;
  std::string_view line, tok;
  while (src.next(line)) {
    Tokens t(line);
    if (!t.next(tok)) continue;
    if (!line.empty() && line.back() == '\\')
      throw ParseError("line continuations ('\\') are not supported", src.line());
    if (tok == "v")
      obj.vertex(t, src.line());
    else if (tok == "f")
      obj.face(t, src.line());
  }
  if (obj.maxRef > obj.mesh.vertices.size())
    throw ParseError("vertex reference " + std::to_string(obj.maxRef) +
                         " is out of range: the file has " +
                         std::to_string(obj.mesh.vertices.size()) + " vertices",
                     obj.maxRefLine);
  return std::move(obj.mesh);
}

}  // namespace convexloc::detail
