// convexloc — strict OFF and OBJ readers, and the writers.
//
// A reader takes one record per line through LineReader (constant memory, the line limit)
// and numbers through parseRow (the point files' decimal rules), so a mesh file and a point
// file agree on what a number and a line are. Counts are checked against kMaxMeshElements
// before anything grows; every index is range-checked here, the geometry by ConvexPolyhedron.
#include "convexloc/mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/text_reader.hpp"
#include "detail/text_scan.hpp"

namespace convexloc {
namespace {

using detail::isBlank;

// a short, printable quote of a token, for messages
std::string quote(std::string_view s) {
  std::string out = "'";
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (i == 24) {
      out += "...";
      break;
    }
    unsigned char u = static_cast<unsigned char>(s[i]);
    out += (u >= 0x20 && u < 0x7f) ? s[i] : '?';
  }
  return out + "'";
}

// the whitespace-separated tokens of a line, up to a '#' comment
class Tokens {
 public:
  explicit Tokens(std::string_view line) : rest_(line) {}
  bool next(std::string_view& token) {
    std::size_t i = 0;
    while (i < rest_.size() && isBlank(rest_[i])) ++i;
    if (i == rest_.size() || rest_[i] == '#') {
      rest_ = {};
      return false;
    }
    std::size_t j = i;
    while (j < rest_.size() && !isBlank(rest_[j]) && rest_[j] != '#') ++j;
    token = rest_.substr(i, j - i);
    rest_.remove_prefix(j);
    return true;
  }
  // every remaining token
  std::size_t count() {
    Tokens copy = *this;
    std::string_view t;
    std::size_t n = 0;
    while (copy.next(t)) ++n;
    return n;
  }

 private:
  std::string_view rest_;
};

// a decimal number, by the point-file rules
double number(std::string_view token, std::size_t line) {
  double v = 0;
  parseRow(token, line, 1, &v);
  return v;
}

// a whole token as a signed integer; false when it is not one
bool integer(std::string_view token, long long& out) {
  if (token.empty()) return false;
  const char* b = token.data();
  if (*b == '+') ++b;
  auto [ptr, ec] = std::from_chars(b, token.data() + token.size(), out);
  return ec == std::errc() && ptr == token.data() + token.size() &&
         b != token.data() + token.size();
}

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

// "x y z": the first three tokens of `t` as a vertex
Vec3 coordinates(Tokens& t, std::size_t line) {
  std::string_view tok;
  double xyz[3];
  for (double& c : xyz) {
    t.next(tok);
    c = number(tok, line);
  }
  return {xyz[0], xyz[1], xyz[2]};
}

// every token left in `t` must be a number
void numbersOnly(Tokens& t, std::size_t line) {
  std::string_view tok;
  while (t.next(tok)) number(tok, line);
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

// === Writing

// Text for a FILE, written out a block of about 64 KiB at a time.
class BlockWriter {
 public:
  explicit BlockWriter(std::FILE* out) : out_(out) {}
  // the text of the block being filled
  std::string& text() noexcept { return text_; }
  // ends a line; writes the block once it is full
  void endLine() {
    text_ += '\n';
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
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
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

}  // namespace

std::optional<MeshFormat> meshFormatOf(std::string_view path) {
  if (path.size() < 4) return std::nullopt;
  std::string ext(path.substr(path.size() - 4));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".obj") return MeshFormat::Obj;
  return std::nullopt;
}

MeshData parseOff(std::FILE* file) {
  LineReader src(file);
  return parseOffFrom(src);
}

MeshData parseOff(std::string_view text) {
  LineReader src(text);
  return parseOffFrom(src);
}

MeshData parseObj(std::FILE* file) {
  LineReader src(file);
  return parseObjFrom(src);
}

MeshData parseObj(std::string_view text) {
  LineReader src(text);
  return parseObjFrom(src);
}

MeshData readMesh(const std::string& path) {
  std::optional<MeshFormat> format = path == "-" ? MeshFormat::Off : meshFormatOf(path);
  if (!format) throw UsageError("unknown mesh format: '" + path + "' (expected .off or .obj)");
  InputFile in(path);
  return *format == MeshFormat::Off ? parseOff(in.get()) : parseObj(in.get());
}

ConvexPolyhedron loadPolyhedron(const std::string& path) {
  return ConvexPolyhedron(readMesh(path));
}

MeshData toMesh(const ConvexPolyhedron& polyhedron) {
  MeshData mesh;
  mesh.vertices.assign(polyhedron.vertices().begin(), polyhedron.vertices().end());
  mesh.indices.reserve(3 * polyhedron.faceCount());
  mesh.faceStart.reserve(polyhedron.faceCount() + 1);
  for (const auto& t : polyhedron.triangles()) mesh.addFace({t[0], t[1], t[2]});
  return mesh;
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
