// convexloc — the strict OFF reader: header, vertices, faces, nothing after.
//
// One record per line through LineReader (constant memory, the line limit) and numbers
// through parseRow (the point files' decimal rules), so a mesh file and a point file agree
// on what a number and a line are. Counts are checked against kMaxMeshElements before
// anything grows; every index is range-checked here, the geometry by ConvexPolyhedron.
#include "convexloc/mesh_reader.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/text_reader.hpp"
#include "io/mesh_parsers.hpp"
#include "io/mesh_tokens.hpp"

namespace convexloc::detail {
namespace {

// a count from an OFF header ("vertex" or "face" count), checked against the limit
std::size_t headerCount(std::string_view token, std::string_view what, std::size_t line) {
  long long v = 0;
  if (!integer(token, v) || v < 0) {
    // a number too large for 64 bits is still a count, just an absurd one
    bool digits = !token.empty() && std::all_of(token.begin(), token.end(),
                                                [](char c) { return c >= '0' && c <= '9'; });
    if (!digits)
      throw ParseError("the OFF header's " + std::string(what) +
                           " count is not a non-negative integer: " + quote(token),
                       line);
    v = std::numeric_limits<long long>::max();
  }
  if (static_cast<unsigned long long>(v) > kMaxMeshElements)
    throw ParseError("the OFF header announces " + std::string(token) +
                         (what == "vertex" ? " vertices" : " faces") + "; at most " +
                         std::to_string(kMaxMeshElements) + " are supported",
                     line);
  return static_cast<std::size_t>(v);
}

// the next line holding a token; false at the end of the input
bool nextContent(LineReader& src, std::string_view& line) {
  while (src.next(line)) {
    Tokens t(line);
    std::string_view tok;
    if (t.next(tok)) return true;
  }
  return false;
}

// === OFF, in the order of the file: header, vertices, faces, nothing after

// what an OFF header announces
struct OffHeader {
  bool vertexExtras = false;  // numbers may follow a vertex's coordinates (COFF, NOFF, ...)
  std::size_t vertices = 0;
  std::size_t faces = 0;
};

// the keyword of an OFF header ("OFF", "COFF", "STOFF", ...): whether it allows numbers after a
// vertex's coordinates
bool offKeyword(std::string_view tok, std::size_t line) {
  if (tok.size() < 3 || tok.substr(tok.size() - 3) != "OFF")
    throw ParseError("not an OFF file: expected the header 'OFF', found " + quote(tok), line);
  const std::string_view prefix = tok.substr(0, tok.size() - 3);
  if (prefix.find('4') != std::string_view::npos || prefix.find('n') != std::string_view::npos)
    throw ParseError("only 3D OFF files are supported, not " + quote(tok), line);
  for (char c : prefix)
    if (c != 'S' && c != 'T' && c != 'C' && c != 'N')
      throw ParseError("unknown OFF header " + quote(tok), line);
  return !prefix.empty();
}

// "V F [E]": `tok` is the vertex count, `head` holds the rest of its line
void offCounts(std::string_view tok, Tokens& head, std::size_t line, OffHeader& header) {
  header.vertices = headerCount(tok, "vertex", line);
  if (!head.next(tok)) throw ParseError("the OFF header needs the vertex and face counts", line);
  header.faces = headerCount(tok, "face", line);
  if (!head.next(tok)) return;
  long long edges = 0;
  if (!integer(tok, edges) || edges < 0)
    throw ParseError("the OFF header's edge count is not a non-negative integer: " + quote(tok),
                     line);
  if (head.next(tok)) throw ParseError("unexpected text after the OFF counts: " + quote(tok), line);
}

// the header: an optional keyword, then the counts on its line or the next
OffHeader readOffHeader(LineReader& src) {
  std::string_view line, tok;
  if (!nextContent(src, line)) throw ParseError("empty OFF file: no header", src.line());
  Tokens head(line);
  head.next(tok);
  OffHeader header;
  long long count = 0;
  if (!integer(tok, count)) {
    header.vertexExtras = offKeyword(tok, src.line());
    if (!head.next(tok)) {
      if (!nextContent(src, line))
        throw ParseError("the OFF file ends before its counts", src.line());
      head = Tokens(line);
      head.next(tok);
    }
  }
  offCounts(tok, head, src.line(), header);
  return header;
}

// the line of record `done` of the `total` vertices or faces (`what`) the header announces
std::string_view announcedLine(LineReader& src, std::size_t done, std::size_t total,
                               const char* what) {
  std::string_view line;
  if (!nextContent(src, line))
    throw ParseError("the file ends after " + std::to_string(done) + " of the " +
                         std::to_string(total) + " " + what + " its header announces",
                     src.line());
  return line;
}

// a vertex line: "x y z", then more numbers only where the header allows them
Vec3 offVertex(std::string_view text, std::size_t line, bool extras) {
  Tokens t(text);
  const std::size_t count = t.count();
  if (count < 3)
    throw ParseError("a vertex needs 3 coordinates, found " + std::to_string(count), line);
  if (!extras && count > 3)
    throw ParseError("a vertex needs 3 coordinates, found " + std::to_string(count) +
                         " (per-vertex data needs a header such as COFF or NOFF)",
                     line);
  const Vec3 p = coordinates(t, line);
  numbersOnly(t, line);
  return p;
}

// a vertex index of a face, below the `vertices` the header announced
std::uint32_t offIndex(std::string_view tok, std::size_t vertices, std::size_t line) {
  long long idx = 0;
  if (!integer(tok, idx)) throw ParseError("not a vertex index: " + quote(tok), line);
  if (idx < 0 || static_cast<unsigned long long>(idx) >= vertices)
    throw ParseError("vertex index " + std::string(tok) + " is out of range: the file has " +
                         std::to_string(vertices) + " vertices, numbered from 0",
                     line);
  return static_cast<std::uint32_t>(idx);
}

// a face line, "k i1 ... ik [colour]", into `poly`
void offFace(std::string_view text, std::size_t line, std::size_t vertices,
             std::vector<std::uint32_t>& poly) {
  Tokens t(text);
  std::string_view tok;
  t.next(tok);
  long long k = 0;
  if (!integer(tok, k) || k < 0)
    throw ParseError("a face starts with its vertex count, found " + quote(tok), line);
  if (k < 3)
    throw ParseError("a face needs at least 3 vertices, this one has " + std::to_string(k), line);
  poly.clear();
  for (long long i = 0; i < k; ++i) {
    if (!t.next(tok))
      throw ParseError(
          "the face announces " + std::to_string(k) + " vertices but lists " + std::to_string(i),
          line);
    poly.push_back(offIndex(tok, vertices, line));
  }
  // an optional colour: an index, or 3 or 4 components
  const std::size_t colour = t.count();
  if (colour != 0 && colour != 1 && colour != 3 && colour != 4) {
    t.next(tok);
    throw ParseError(
        "unexpected text after the face's " + std::to_string(k) + " vertices: " + quote(tok), line);
  }
  numbersOnly(t, line);
}

}  // namespace

// the OFF grammar of the header comment: header, vertices, faces, then nothing but comments
MeshData parseOffFrom(LineReader& src) {
  const OffHeader header = readOffHeader(src);
  MeshData mesh;
  for (std::size_t i = 0; i < header.vertices; ++i) {
    const std::string_view line = announcedLine(src, i, header.vertices, "vertices");
    mesh.vertices.push_back(offVertex(line, src.line(), header.vertexExtras));
    mesh.vertexLines.push_back(src.line());
  }
  std::vector<std::uint32_t> poly;
  for (std::size_t f = 0; f < header.faces; ++f) {
    const std::string_view line = announcedLine(src, f, header.faces, "faces");
    offFace(line, src.line(), header.vertices, poly);
    mesh.addFace(poly);
    mesh.faceLines.push_back(src.line());
  }
  std::string_view line, tok;
  if (nextContent(src, line)) {
    Tokens(line).next(tok);
    throw ParseError("unexpected text after the last face: " + quote(tok), src.line());
  }
  return mesh;
}

}  // namespace convexloc::detail
