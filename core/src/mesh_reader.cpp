// convexloc — strict OFF and OBJ readers, writers, and 3D point files.
#include "convexloc/mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <limits>

#include "convexloc/error.hpp"
#include "convexloc/text_reader.hpp"

namespace convexloc {
namespace {

// a blank that separates tokens (not a line end)
bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

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

// the OFF grammar of the header comment, line by line
MeshData parseOffFrom(LineReader& src) {
  MeshData mesh;
  std::string_view line, tok;
  if (!nextContent(src, line)) throw ParseError("empty OFF file: no header", src.line());
  Tokens head(line);
  head.next(tok);
  int extras = 0;  // extra numbers allowed after a vertex's coordinates: -1 = any
  long long probe = 0;
  if (!integer(tok, probe)) {
    std::string_view key = tok;
    if (key.size() < 3 || key.substr(key.size() - 3) != "OFF")
      throw ParseError("not an OFF file: expected the header 'OFF', found " + quote(tok),
                       src.line());
    std::string_view prefix = key.substr(0, key.size() - 3);
    if (prefix.find('4') != std::string_view::npos || prefix.find('n') != std::string_view::npos)
      throw ParseError("only 3D OFF files are supported, not " + quote(tok), src.line());
    for (char c : prefix)
      if (c != 'S' && c != 'T' && c != 'C' && c != 'N')
        throw ParseError("unknown OFF header " + quote(tok), src.line());
    extras = prefix.empty() ? 0 : -1;
    if (!head.next(tok)) {
      if (!nextContent(src, line))
        throw ParseError("the OFF file ends before its counts", src.line());
      head = Tokens(line);
      head.next(tok);
    }
  }
  const std::size_t headerLine = src.line();
  const std::size_t nv = headerCount(tok, "vertex", headerLine);
  if (!head.next(tok))
    throw ParseError("the OFF header needs the vertex and face counts", headerLine);
  const std::size_t nf = headerCount(tok, "face", headerLine);
  if (head.next(tok)) {
    long long edges = 0;
    if (!integer(tok, edges) || edges < 0)
      throw ParseError("the OFF header's edge count is not a non-negative integer: " + quote(tok),
                       headerLine);
    if (head.next(tok))
      throw ParseError("unexpected text after the OFF counts: " + quote(tok), headerLine);
  }

  for (std::size_t i = 0; i < nv; ++i) {
    if (!nextContent(src, line))
      throw ParseError("the file ends after " + std::to_string(i) + " of the " +
                           std::to_string(nv) + " vertices its header announces",
                       src.line());
    Tokens t(line);
    std::size_t count = t.count();
    if (count < 3)
      throw ParseError("a vertex needs 3 coordinates, found " + std::to_string(count), src.line());
    if (extras == 0 && count > 3)
      throw ParseError("a vertex needs 3 coordinates, found " + std::to_string(count) +
                           " (per-vertex data needs a header such as COFF or NOFF)",
                       src.line());
    double xyz[3];
    for (double& c : xyz) {
      t.next(tok);
      c = number(tok, src.line());
    }
    while (t.next(tok)) number(tok, src.line());
    mesh.vertices.push_back({xyz[0], xyz[1], xyz[2]});
    mesh.vertexLines.push_back(src.line());
  }
  std::vector<std::uint32_t> poly;
  for (std::size_t f = 0; f < nf; ++f) {
    if (!nextContent(src, line))
      throw ParseError("the file ends after " + std::to_string(f) + " of the " +
                           std::to_string(nf) + " faces its header announces",
                       src.line());
    Tokens t(line);
    t.next(tok);
    long long k = 0;
    if (!integer(tok, k) || k < 0)
      throw ParseError("a face starts with its vertex count, found " + quote(tok), src.line());
    if (k < 3)
      throw ParseError("a face needs at least 3 vertices, this one has " + std::to_string(k),
                       src.line());
    poly.clear();
    for (long long i = 0; i < k; ++i) {
      if (!t.next(tok))
        throw ParseError(
            "the face announces " + std::to_string(k) + " vertices but lists " + std::to_string(i),
            src.line());
      long long idx = 0;
      if (!integer(tok, idx)) throw ParseError("not a vertex index: " + quote(tok), src.line());
      if (idx < 0 || static_cast<unsigned long long>(idx) >= nv)
        throw ParseError("vertex index " + std::string(tok) + " is out of range: the file has " +
                             std::to_string(nv) + " vertices, numbered from 0",
                         src.line());
      poly.push_back(static_cast<std::uint32_t>(idx));
    }
    // an optional colour: an index, or 3 or 4 components
    std::size_t colour = t.count();
    if (colour != 0 && colour != 1 && colour != 3 && colour != 4) {
      t.next(tok);
      throw ParseError(
          "unexpected text after the face's " + std::to_string(k) + " vertices: " + quote(tok),
          src.line());
    }
    while (t.next(tok)) number(tok, src.line());
    mesh.addFace(poly);
    mesh.faceLines.push_back(src.line());
  }
  if (nextContent(src, line)) {
    Tokens t(line);
    t.next(tok);
    throw ParseError("unexpected text after the last face: " + quote(tok), src.line());
  }
  return mesh;
}

// the OBJ subset of the header comment: v and f statements, the rest ignored
MeshData parseObjFrom(LineReader& src) {
  MeshData mesh;
  std::string_view line, tok;
  std::vector<long long> raw;  // a face's references, resolved to 0-based (may be forward)
  std::size_t maxRef = 0, maxRefLine = 0;
  std::vector<std::uint32_t> poly;
  while (src.next(line)) {
    Tokens t(line);
    if (!t.next(tok)) continue;
    if (!line.empty() && line.back() == '\\')
      throw ParseError("line continuations ('\\') are not supported", src.line());
    if (tok == "v") {
      std::size_t count = t.count();
      if (count != 3 && count != 4 && count != 6 && count != 7)
        throw ParseError("a vertex needs 3 coordinates (then w, or r g b colours), found " +
                             std::to_string(count) + " numbers",
                         src.line());
      double xyz[3];
      for (double& c : xyz) {
        t.next(tok);
        c = number(tok, src.line());
      }
      if (count == 4) {
        t.next(tok);
        if (number(tok, src.line()) != 1.0)
          throw ParseError("a vertex weight w other than 1 is not supported: " + quote(tok),
                           src.line());
      }
      while (t.next(tok)) number(tok, src.line());
      if (mesh.vertices.size() >= kMaxMeshElements)
        throw ParseError("more than " + std::to_string(kMaxMeshElements) + " vertices", src.line());
      mesh.vertices.push_back({xyz[0], xyz[1], xyz[2]});
      mesh.vertexLines.push_back(src.line());
    } else if (tok == "f") {
      raw.clear();
      while (t.next(tok)) {
        std::string_view ref = tok.substr(0, tok.find('/'));
        long long idx = 0;
        if (!integer(ref, idx))
          throw ParseError("not a vertex reference: " + quote(tok), src.line());
        if (idx == 0)
          throw ParseError("vertex reference 0: OBJ numbers vertices from 1", src.line());
        if (idx < 0) {
          long long resolved = static_cast<long long>(mesh.vertices.size()) + idx;
          if (resolved < 0)
            throw ParseError("vertex reference " + std::string(ref) +
                                 " points before the first vertex (only " +
                                 std::to_string(mesh.vertices.size()) + " so far)",
                             src.line());
          idx = resolved;
        } else {
          idx -= 1;
          if (static_cast<unsigned long long>(idx) >= kMaxMeshElements)
            throw ParseError("vertex reference " + std::string(ref) + " is out of range",
                             src.line());
        }
        if (static_cast<std::size_t>(idx) >= maxRef) {
          maxRef = static_cast<std::size_t>(idx) + 1;
          maxRefLine = src.line();
        }
        raw.push_back(idx);
      }
      if (raw.size() < 3)
        throw ParseError(
            "a face needs at least 3 vertices, this one has " + std::to_string(raw.size()),
            src.line());
      if (mesh.faceCount() >= kMaxMeshElements)
        throw ParseError("more than " + std::to_string(kMaxMeshElements) + " faces", src.line());
      poly.assign(raw.begin(), raw.end());
      mesh.addFace(poly);
      mesh.faceLines.push_back(src.line());
    }
    // every other statement is ignored
  }
  if (maxRef > mesh.vertices.size())
    throw ParseError("vertex reference " + std::to_string(maxRef) +
                         " is out of range: the file has " + std::to_string(mesh.vertices.size()) +
                         " vertices",
                     maxRefLine);
  return mesh;
}

// appends the shortest round-trip decimal of v
void appendNumber(std::string& out, double v) {
  char buf[32];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ptr);
}

// writes and clears `text`
void flush(std::FILE* out, std::string& text) {
  if (!text.empty() && std::fwrite(text.data(), 1, text.size(), out) != text.size())
    throw Error(std::string("write error: ") + std::strerror(errno));
  text.clear();
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
  std::string text = "OFF\n" + std::to_string(mesh.vertices.size()) + ' ' +
                     std::to_string(mesh.faceCount()) + " 0\n";
  for (const Vec3& p : mesh.vertices) {
    appendNumber(text, p.x);
    text += ' ';
    appendNumber(text, p.y);
    text += ' ';
    appendNumber(text, p.z);
    text += '\n';
    if (text.size() > (1 << 16)) flush(out, text);
  }
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    auto face = mesh.face(f);
    text += std::to_string(face.size());
    for (std::uint32_t i : face) (text += ' ') += std::to_string(i);
    text += '\n';
    if (text.size() > (1 << 16)) flush(out, text);
  }
  flush(out, text);
}

void writeObj(std::FILE* out, const MeshData& mesh) {
  std::string text;
  for (const Vec3& p : mesh.vertices) {
    text += "v ";
    appendNumber(text, p.x);
    text += ' ';
    appendNumber(text, p.y);
    text += ' ';
    appendNumber(text, p.z);
    text += '\n';
    if (text.size() > (1 << 16)) flush(out, text);
  }
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    text += 'f';
    for (std::uint32_t i : mesh.face(f)) (text += ' ') += std::to_string(i + 1);
    text += '\n';
    if (text.size() > (1 << 16)) flush(out, text);
  }
  flush(out, text);
}

PointList3D readPoints3D(const std::string& path) {
  InputFile in(path);
  RowReader reader(in.get(), 3);
  PointList3D out;
  double row[3];
  while (reader.next(row)) {
    out.points.push_back({row[0], row[1], row[2]});
    out.lines.push_back(reader.line());
  }
  out.lastLine = reader.line();
  return out;
}

}  // namespace convexloc
