// convexloc — the STL reader, binary and ASCII, corners welded by exact equality.
//
// Binary errors name the byte offset of the record at fault; ASCII errors name the line.
// Which of the two a file is is decided by its first 84 bytes (see mesh_reader.hpp): an ASCII
// file's bytes read as a binary count would exceed kMaxMeshElements, so no binary file the
// reader accepts is ever taken for ASCII.
#include <bit>
#include <cmath>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/mesh_reader.hpp"
#include "detail/bit_cast.hpp"
#include "io/byte_source.hpp"
#include "io/mesh_parsers.hpp"
#include "io/mesh_tokens.hpp"

namespace convexloc {
namespace {

using detail::ByteSource;
using detail::failAtByte;
using detail::quote;
using detail::Tokens;

constexpr std::size_t kHeaderBytes = 84;  // 80 free bytes and the uint32 facet count
constexpr std::size_t kFacetBytes = 50;   // normal, 3 vertices (float32 each), uint16

// === Welding: one vertex for every set of exactly equal corners

// the bits of a coordinate, -0 read as +0 (they are equal)
std::uint64_t coordinateBits(double v) noexcept {
  return detail::bit_cast<std::uint64_t>(v + 0.0);
}

// a hash of a corner's coordinates
std::uint64_t cornerHash(Vec3 p) noexcept {
  std::uint64_t h = coordinateBits(p.x) * 0x9E3779B97F4A7C15ull;
  h = (h ^ (h >> 29) ^ coordinateBits(p.y)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 31) ^ coordinateBits(p.z)) * 0x94D049BB133111EBull;
  return h ^ (h >> 32);
}

// Gives each distinct corner the index of its first appearance in the mesh: an open-addressing
// table of vertex indices (plus one; 0 is empty), at most half full, probed linearly.
class Welder {
 public:
  explicit Welder(MeshData& mesh) : mesh_(mesh), slots_(64, 0) {}
  // room for about `facets` facets
  void reserve(std::size_t facets) {
    mesh_.vertices.reserve(facets / 2 + 4);
    mesh_.indices.reserve(3 * facets);
    mesh_.faceStart.reserve(facets + 1);
    std::size_t want = 64;
    while (want < facets + 8) want *= 2;  // about 2 slots a vertex: a closed mesh has F / 2
    if (want > slots_.size()) rehash(want);
  }
  // the vertex at `p`, added if new (with its `line`, when the file has lines); false when
  // the mesh would hold more than kMaxMeshElements vertices
  bool vertex(Vec3 p, std::size_t line, std::uint32_t& index) {
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = cornerHash(p) & mask;; i = (i + 1) & mask) {
      const std::uint32_t slot = slots_[i];
      if (slot == 0) break;
      const Vec3 q = mesh_.vertices[slot - 1];
      if (q.x == p.x && q.y == p.y && q.z == p.z) {
        index = slot - 1;
        return true;
      }
    }
    if (mesh_.vertices.size() >= kMaxMeshElements) return false;
    index = static_cast<std::uint32_t>(mesh_.vertices.size());
    mesh_.vertices.push_back(p);
    if (line != 0) mesh_.vertexLines.push_back(line);
    place(index);
    if (2 * mesh_.vertices.size() > slots_.size()) rehash(2 * slots_.size());
    return true;
  }

 private:
  // puts vertex `v` in the first empty slot of its probe sequence
  void place(std::uint32_t v) {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = cornerHash(mesh_.vertices[v]) & mask;
    while (slots_[i] != 0) i = (i + 1) & mask;
    slots_[i] = v + 1;
  }
  // a table of `size` slots (a power of 2) holding every vertex so far
  void rehash(std::size_t size) {
    slots_.assign(size, 0);
    for (std::uint32_t v = 0; v < mesh_.vertices.size(); ++v) place(v);
  }

  MeshData& mesh_;
  std::vector<std::uint32_t> slots_;
};

std::string tooManyVertices() {
  return "more than " + std::to_string(kMaxMeshElements) + " distinct vertices";
}

// === Binary

// a coordinate of a binary facet: the float32 at `p`, exactly; non-finite is an error
double binaryCoordinate(const char* p, std::uint64_t offset, std::size_t facet, int corner) {
  const float v = detail::loadScalar<float>(p, false);
  if (!std::isfinite(v))
    failAtByte(offset, "facet " + std::to_string(facet) + ", vertex " + std::to_string(corner) +
                           ": a coordinate is " + (std::isnan(v) ? "NaN" : "infinite"));
  return static_cast<double>(v);
}

// the facet count of the header, checked against the limit and the file's size
std::uint32_t binaryCount(ByteSource& src) {
  const std::string_view head = src.take(kHeaderBytes);
  if (head.size() < kHeaderBytes)
    failAtByte(head.size(), "the file ends inside the 84-byte header of a binary STL");
  const auto count = detail::loadScalar<std::uint32_t>(head.data() + 80, false);
  if (count > kMaxMeshElements)
    failAtByte(80, "the header announces " + std::to_string(count) + " facets; at most " +
                       std::to_string(kMaxMeshElements) + " are supported");
  const std::uint64_t expected = kHeaderBytes + std::uint64_t{kFacetBytes} * count;
  if (src.size() && *src.size() != expected) {
    const std::uint64_t size = *src.size();
    std::string holds;
    if ((size - kHeaderBytes) % kFacetBytes == 0)
      holds = " (room for " + std::to_string((size - kHeaderBytes) / kFacetBytes) + " facets)";
    failAtByte(80, "the header announces " + std::to_string(count) +
                       " facets, which take 84 + 50 * " + std::to_string(count) + " = " +
                       std::to_string(expected) + " bytes, but the file has " +
                       std::to_string(size) + " bytes" + holds);
  }
  return count;
}

MeshData parseBinary(ByteSource& src) {
  const std::uint32_t count = binaryCount(src);
  MeshData mesh;
  Welder weld(mesh);
  // the size is known to match the count, or the reading stops where the bytes do
  if (src.size()) weld.reserve(count);
  for (std::size_t f = 0; f < count; ++f) {
    const std::uint64_t at = src.offset();
    const std::string_view rec = src.take(kFacetBytes);
    if (rec.size() < kFacetBytes)
      failAtByte(at + rec.size(), "the file ends inside facet " + std::to_string(f) + " of " +
                                      std::to_string(count) + " (its 50 bytes start at byte " +
                                      std::to_string(at) + ")");
    std::uint32_t corners[3];
    for (int k = 0; k < 3; ++k) {
      const std::size_t base = 12 + 12 * static_cast<std::size_t>(k);
      Vec3 p;
      p.x = binaryCoordinate(rec.data() + base, at + base, f, k);
      p.y = binaryCoordinate(rec.data() + base + 4, at + base + 4, f, k);
      p.z = binaryCoordinate(rec.data() + base + 8, at + base + 8, f, k);
      if (!weld.vertex(p, 0, corners[k])) failAtByte(at, tooManyVertices());
    }
    mesh.addFace({corners[0], corners[1], corners[2]});
  }
  if (!src.atEnd())
    failAtByte(src.offset(),
               "unexpected bytes after the last of the " + std::to_string(count) + " facets");
  return mesh;
}

// === ASCII, one statement a line

// An ASCII STL being read: the lines, the mesh, the welder.
struct AsciiStl {
  explicit AsciiStl(ByteSource& source) : src(source) {}
  ByteSource& src;
  MeshData mesh;
  Welder weld{mesh};
  std::string_view keyword;  // the first token of the statement read last
  Tokens rest{{}};           // the tokens after it

  // the next statement; false at the end of the input
  bool next() {
    std::string_view line;
    while (src.nextLine(line)) {
      rest = Tokens(line, false);
      if (rest.next(keyword)) return true;
    }
    return false;
  }

  // the next statement, which must be `word` (what: how the message names it)
  void expect(std::string_view word, const std::string& what) {
    if (!next()) throw ParseError("the file ends where " + what + " should follow", src.line());
    if (keyword != word)
      throw ParseError("expected " + what + ", found " + quote(keyword), src.line());
  }

  // nothing may follow the statement's own tokens
  void endOfStatement() {
    std::string_view tok;
    if (rest.next(tok))
      throw ParseError("unexpected text after " + quote(keyword) + ": " + quote(tok), src.line());
  }

  // "facet normal i j k" ... "endfacet", after the "facet"
  void facet() {
    const std::size_t line = src.line();
    std::string_view tok;
    // the normal is ignored (see the header), but it must be there
    if (!rest.next(tok) || tok != "normal" || rest.count() != 3)
      throw ParseError("expected 'facet normal i j k'", line);
    expect("outer", "'outer loop'");
    if (!rest.next(tok) || tok != "loop") throw ParseError("expected 'outer loop'", src.line());
    endOfStatement();
    std::uint32_t corners[3];
    for (int k = 0; k < 3; ++k) {
      expect("vertex", "'vertex x y z' (vertex " + std::to_string(k) + " of the facet)");
      if (rest.count() != 3)
        throw ParseError("a vertex needs 3 coordinates, found " + std::to_string(rest.count()),
                         src.line());
      if (!weld.vertex(detail::coordinates(rest, src.line()), src.line(), corners[k]))
        throw ParseError(tooManyVertices(), src.line());
    }
    expect("endloop", "'endloop'");
    endOfStatement();
    expect("endfacet", "'endfacet'");
    endOfStatement();
    if (mesh.faceCount() >= kMaxMeshElements)
      throw ParseError("more than " + std::to_string(kMaxMeshElements) + " facets", line);
    mesh.addFace({corners[0], corners[1], corners[2]});
    mesh.faceLines.push_back(line);
  }

  // "solid [name]", facets, "endsolid [name]", as often as the file repeats them
  MeshData read() {
    while (next()) {
      if (keyword != "solid")
        throw ParseError("expected 'solid', found " + quote(keyword), src.line());
      for (;;) {
        if (!next())
          throw ParseError(
              "the file ends before 'endsolid' (or it is a binary STL cut short "
              "inside its 84-byte header)",
              src.line());
        if (keyword == "endsolid") break;
        if (keyword != "facet")
          throw ParseError("expected 'facet' or 'endsolid', found " + quote(keyword), src.line());
        facet();
      }
    }
    return std::move(mesh);
  }
};

// whether `c` is a byte of text: printable, a line end or blank, or part of UTF-8
bool textByte(unsigned char c) {
  return (c >= 0x09 && c <= 0x0d) || c >= 0x20;
}

// a blank or a line end
bool spaceByte(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// the rule of mesh_reader.hpp: "solid" first and the first 84 bytes all text
bool isAsciiStl(ByteSource& src) {
  const std::string_view head = src.peek(kHeaderBytes);
  for (char c : head)
    if (!textByte(static_cast<unsigned char>(c))) return false;
  std::size_t i = 0;
  while (i < head.size() && spaceByte(head[i])) ++i;
  return head.substr(i, 5) == "solid" && (i + 5 == head.size() || spaceByte(head[i + 5]));
}

}  // namespace

MeshData detail::parseStlFrom(ByteSource& src) {
  if (isAsciiStl(src)) return AsciiStl(src).read();
  return parseBinary(src);
}

}  // namespace convexloc
