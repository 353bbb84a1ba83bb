// convexloc — the PLY body: every element in the order of the header, ASCII one record a
// line, binary in either byte order; vertices and faces kept, everything else read past.
//
// ASCII errors name the line, binary ones the byte offset. A count in the file (an element's,
// a list's) never sizes an allocation beyond what the rest of the file can hold.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/mesh_reader.hpp"
#include "io/byte_source.hpp"
#include "io/mesh_parsers.hpp"
#include "io/mesh_tokens.hpp"
#include "io/ply_format.hpp"

namespace convexloc {
namespace {

using detail::ByteSource;
using detail::PlyElement;
using detail::PlyHeader;
using detail::PlyProperty;
using detail::PlyStorage;
using detail::PlyType;
using detail::plyTypeSize;
using detail::quote;
using detail::Tokens;

// the name of a type, as messages give it
const char* typeName(PlyType t) {
  static constexpr const char* kNames[] = {"char", "uchar", "short", "ushort",
                                           "int",  "uint",  "float", "double"};
  return kNames[static_cast<int>(t)];
}

// whether integer type `t` holds `v`
bool holds(PlyType t, long long v) {
  switch (t) {
    case PlyType::Int8: return v >= -128 && v <= 127;
    case PlyType::UInt8: return v >= 0 && v <= 255;
    case PlyType::Int16: return v >= -32768 && v <= 32767;
    case PlyType::UInt16: return v >= 0 && v <= 65535;
    case PlyType::Int32: return v >= -2147483648LL && v <= 2147483647LL;
    case PlyType::UInt32: return v >= 0 && v <= 4294967295LL;
    default: return false;
  }
}

// a binary integer of type `t` at `p`
long long binaryInteger(PlyType t, const char* p, bool big) {
  using detail::loadScalar;
  switch (t) {
    case PlyType::Int8: return loadScalar<std::int8_t>(p, big);
    case PlyType::UInt8: return loadScalar<std::uint8_t>(p, big);
    case PlyType::Int16: return loadScalar<std::int16_t>(p, big);
    case PlyType::UInt16: return loadScalar<std::uint16_t>(p, big);
    case PlyType::Int32: return loadScalar<std::int32_t>(p, big);
    default: return loadScalar<std::uint32_t>(p, big);
  }
}

// a binary number of type `t` at `p`, as a double (exactly: every PLY type fits)
double binaryReal(PlyType t, const char* p, bool big) {
  if (t == PlyType::Float32) return static_cast<double>(detail::loadScalar<float>(p, big));
  if (t == PlyType::Float64) return detail::loadScalar<double>(p, big);
  return static_cast<double>(binaryInteger(t, p, big));
}

// "vertex 3 of 8", naming a record
std::string recordName(const PlyElement& e, std::uint64_t r) {
  return e.name + " " + std::to_string(r) + " of " + std::to_string(e.count);
}

// whether `line` holds exactly one ASCII record of `e` (numbers where its properties are,
// lists as long as their counts say)
bool fitsRecord(std::string_view line, const PlyElement& e) {
  Tokens t(line, false);
  std::string_view tok;
  auto value = [&](PlyType type) {
    long long v = 0;
    if (!t.next(tok)) return false;
    if (plyInteger(type)) return detail::integer(tok, v);
    try {
      detail::number(tok, 0);
    } catch (const ParseError&) {
      return false;
    }
    return true;
  };
  for (const PlyProperty& p : e.properties) {
    long long n = 0;
    if (!p.list) {
      if (!value(p.type)) return false;
      continue;
    }
    if (!t.next(tok) || !detail::integer(tok, n) || n < 0) return false;
    for (long long m = 0; m < n; ++m)
      if (!value(p.type)) return false;
  }
  return !t.next(tok);
}

// Reads the body after the header into a mesh.
class PlyBody {
 public:
  PlyBody(ByteSource& src, const PlyHeader& header)
      : src_(src),
        h_(header),
        ascii_(header.storage == PlyStorage::Ascii),
        big_(header.storage == PlyStorage::BinaryBigEndian),
        vertexCount_(header.elements[header.vertexElement].count) {}

  MeshData read() {
    for (std::size_t i = 0; i < h_.elements.size(); ++i) {
      const PlyElement& e = h_.elements[i];
      reserveFor(i, e);
      // binary records without properties take no bytes, however many the header announces
      if (!ascii_ && e.properties.empty()) continue;
      for (std::uint64_t r = 0; r < e.count; ++r) {
        if (ascii_)
          asciiRecord(i, e, r);
        else
          binaryRecord(i, e, r);
      }
    }
    finish();
    return std::move(mesh_);
  }

 private:
  // === Both storages

  // room for the vertices or faces of element `i`, as far as the rest of the file can hold
  void reserveFor(std::size_t i, const PlyElement& e) {
    if (i != h_.vertexElement && i != h_.faceElement) return;
    const std::uint64_t left =
        src_.size() ? *src_.size() - std::min(*src_.size(), src_.offset()) : std::uint64_t{1} << 20;
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(e.count, left / 4));
    if (i == h_.vertexElement) mesh_.vertices.reserve(n);
    if (i == h_.faceElement) mesh_.faceStart.reserve(n + 1);
  }

  // the problem, at the current line (ASCII) or at byte `at` (binary)
  [[noreturn]] void fail(std::uint64_t at, const std::string& problem) const {
    if (ascii_) throw ParseError(problem, src_.line());
    detail::failAtByte(at, problem);
  }

  // vertex coordinates must be finite
  void addVertex(const double (&xyz)[3], std::uint64_t at, std::uint64_t r) {
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(xyz[k]))
        fail(at, "vertex " + std::to_string(r) + ": coordinate " + "xyz"[k] + " is " +
                     (std::isnan(xyz[k]) ? "NaN" : "infinite"));
    mesh_.vertices.push_back({xyz[0], xyz[1], xyz[2]});
    if (ascii_) mesh_.vertexLines.push_back(src_.line());
  }

  // a face's vertex count, before its indices are read
  void checkFaceSize(long long n, std::uint64_t at, std::uint64_t r, const std::string& hint) {
    if (n < 3)
      fail(at, "face " + std::to_string(r) + " has " + std::to_string(n) +
                   " vertices; a face needs at least 3" + hint);
    if (static_cast<unsigned long long>(n) > vertexCount_)
      fail(at, "face " + std::to_string(r) + " lists " + std::to_string(n) +
                   " vertices; the file has " + std::to_string(vertexCount_) + hint);
    if (mesh_.indices.size() + static_cast<std::size_t>(n) >
        std::numeric_limits<std::uint32_t>::max())
      fail(at, "more face indices than a mesh can hold");
  }

  // a face's vertex index
  void checkIndex(long long v, std::uint64_t at, std::uint64_t r, const std::string& hint) {
    if (v < 0 || static_cast<unsigned long long>(v) >= vertexCount_)
      fail(at, "face " + std::to_string(r) + ": vertex index " + std::to_string(v) +
                   " is out of range: the file has " + std::to_string(vertexCount_) +
                   " vertices, numbered from 0" + hint);
  }

  // after the last element: nothing but blank lines (ASCII) or nothing at all (binary)
  void finish() {
    if (ascii_) {
      std::string_view line, tok;
      while (src_.nextLine(line)) {
        if (!Tokens(line, false).next(tok)) continue;
        // a line that reads as one more record of the last element blames its count
        const PlyElement& last = h_.elements.back();
        if (fitsRecord(line, last))
          throw ParseError("element '" + last.name + "' announces " + std::to_string(last.count) +
                               " records: line " + std::to_string(src_.line()) +
                               " after them reads as one more: is the count too small?",
                           last.line);
        throw ParseError("unexpected text after the last element: " + quote(tok), src_.line());
      }
      return;
    }
    if (!src_.atEnd())
      detail::failAtByte(src_.offset(),
                         "unexpected bytes after the last element the header announces");
  }

  // === Binary

  // the next `n` bytes of record `r` of `e`; the file ending first is an error
  std::string_view bytes(std::size_t n, const PlyElement& e, std::uint64_t r) {
    const std::uint64_t at = src_.offset();
    const std::string_view b = src_.take(n);
    if (b.size() < n)
      detail::failAtByte(at + b.size(), "the file ends inside " + recordName(e, r) +
                                            " (element declared on header line " +
                                            std::to_string(e.line) + ")");
    return b;
  }

  // " (the other byte order reads N, which would fit: is the format line right?)", or ""
  std::string orderHint(PlyType t, const char* p, long long lo, long long hi) const {
    const long long other = binaryInteger(t, p, !big_);
    if (plyTypeSize(t) == 1 || other < lo || other > hi) return "";
    return " (read in the other byte order it would be " + std::to_string(other) +
           ": is the header's format right?)";
  }

  // the index list of face `r`, into a new face
  void binaryFace(const PlyProperty& p, const PlyElement& e, std::uint64_t r, std::uint64_t at) {
    const char* c = bytes(plyTypeSize(p.countType), e, r).data();
    const long long n = binaryInteger(p.countType, c, big_);
    const auto limit = static_cast<long long>(std::min<std::uint64_t>(vertexCount_, 1u << 30));
    checkFaceSize(n, at, r, orderHint(p.countType, c, 3, limit));
    for (long long k = 0; k < n; ++k) {
      const char* b = bytes(plyTypeSize(p.type), e, r).data();
      const long long v = binaryInteger(p.type, b, big_);
      checkIndex(v, at, r, orderHint(p.type, b, 0, limit - 1));
      mesh_.indices.push_back(static_cast<std::uint32_t>(v));
    }
    mesh_.faceStart.push_back(static_cast<std::uint32_t>(mesh_.indices.size()));
  }

  // a list property read past
  void binarySkipList(const PlyProperty& p, const PlyElement& e, std::uint64_t r,
                      std::uint64_t at) {
    const long long n =
        binaryInteger(p.countType, bytes(plyTypeSize(p.countType), e, r).data(), big_);
    if (n < 0) fail(at, recordName(e, r) + ": list '" + p.name + "' has a negative count");
    const std::uint64_t want = static_cast<std::uint64_t>(n) * plyTypeSize(p.type);
    const std::uint64_t from = src_.offset();
    if (src_.skip(want) < want)
      detail::failAtByte(src_.offset(), "the file ends inside list '" + p.name + "' of " +
                                            recordName(e, r) + " (it starts at byte " +
                                            std::to_string(from) + ")");
  }

  // one record of element `i`
  void binaryRecord(std::size_t i, const PlyElement& e, std::uint64_t r) {
    const std::uint64_t at = src_.offset();
    const bool vertex = i == h_.vertexElement, face = i == h_.faceElement;
    double xyz[3] = {0, 0, 0};
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const PlyProperty& p = e.properties[k];
      if (face && k == h_.indexList) {
        binaryFace(p, e, r, at);
      } else if (p.list) {
        binarySkipList(p, e, r, at);
      } else {
        const char* b = bytes(plyTypeSize(p.type), e, r).data();
        for (int c = 0; c < 3; ++c)
          if (vertex && k == h_.xyz[c]) xyz[c] = binaryReal(p.type, b, big_);
      }
    }
    if (vertex) addVertex(xyz, at, r);
  }

  // === ASCII

  // the next token of the record, as an integer of type `t`
  long long asciiInteger(Tokens& t, PlyType type, const PlyElement& e, std::uint64_t r) {
    std::string_view tok;
    if (!t.next(tok)) fail(0, recordName(e, r) + " has fewer values than its properties");
    long long v = 0;
    if (!detail::integer(tok, v) || !holds(type, v))
      fail(0, "expected a value of type " + std::string(typeName(type)) + ", found " + quote(tok));
    return v;
  }

  // the next token of the record, as a number of type `t`
  double asciiReal(Tokens& t, PlyType type, const PlyElement& e, std::uint64_t r) {
    if (detail::plyInteger(type)) return static_cast<double>(asciiInteger(t, type, e, r));
    std::string_view tok;
    if (!t.next(tok)) fail(0, recordName(e, r) + " has fewer values than its properties");
    return detail::number(tok, src_.line());
  }

  // One record of element `i`, one line. A line that fails as a record of `e` but reads as
  // one of a neighbouring element blames the count in the header, on its line.
  void asciiRecord(std::size_t i, const PlyElement& e, std::uint64_t r) {
    std::string_view line;
    if (!src_.nextLine(line))
      throw ParseError("the file ends before " + recordName(e, r) +
                           " (element declared on header line " + std::to_string(e.line) + ")",
                       src_.line());
    try {
      asciiValues(i, e, r, line);
    } catch (const ParseError& failed) {
      if (fitsRecord(line, e)) throw;  // the record has the right shape: its values are wrong
      blameCount(i, r, line, failed.what());
      throw;
    }
  }

  // A record of element `i` whose line has the wrong shape for it, and the shape of a record
  // of the element after it (a count too large) or, for the first record, of the element
  // before it (that one's count too small): ParseError on the header line of the count.
  void blameCount(std::size_t i, std::uint64_t r, std::string_view line, const char* problem) {
    const PlyElement& e = h_.elements[i];
    const std::string at = "line " + std::to_string(src_.line()) + " ('" +
                           std::string(line.substr(0, 40)) + "') fails as " + recordName(e, r) +
                           " (" + problem + ")";
    if (i + 1 < h_.elements.size() && fitsRecord(line, h_.elements[i + 1]))
      throw ParseError("element '" + e.name + "' announces " + std::to_string(e.count) +
                           " records: " + at + " and reads as a '" + h_.elements[i + 1].name +
                           "' record: is the count too large?",
                       e.line);
    if (r == 0 && i > 0 && fitsRecord(line, h_.elements[i - 1]))
      throw ParseError("element '" + h_.elements[i - 1].name + "' announces " +
                           std::to_string(h_.elements[i - 1].count) + " records: " + at +
                           " and reads as one more '" + h_.elements[i - 1].name +
                           "': is the count too small?",
                       h_.elements[i - 1].line);
  }

  // the values of one record of element `i` from its line
  void asciiValues(std::size_t i, const PlyElement& e, std::uint64_t r, std::string_view line) {
    Tokens t(line, false);
    const bool vertex = i == h_.vertexElement, face = i == h_.faceElement;
    double xyz[3] = {0, 0, 0};
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const PlyProperty& p = e.properties[k];
      if (!p.list) {
        const double v = asciiReal(t, p.type, e, r);
        for (int c = 0; c < 3; ++c)
          if (vertex && k == h_.xyz[c]) xyz[c] = v;
        continue;
      }
      const long long n = asciiInteger(t, p.countType, e, r);
      const bool indices = face && k == h_.indexList;
      if (indices) checkFaceSize(n, 0, r, "");
      if (n < 0) fail(0, recordName(e, r) + ": list '" + p.name + "' has a negative count");
      for (long long m = 0; m < n; ++m) {
        if (!indices) {
          asciiReal(t, p.type, e, r);
          continue;
        }
        const long long v = asciiInteger(t, p.type, e, r);
        checkIndex(v, 0, r, "");
        mesh_.indices.push_back(static_cast<std::uint32_t>(v));
      }
      if (indices) {
        mesh_.faceStart.push_back(static_cast<std::uint32_t>(mesh_.indices.size()));
        mesh_.faceLines.push_back(src_.line());
      }
    }
    std::string_view extra;
    if (t.next(extra))
      fail(0, "unexpected text after the values of " + recordName(e, r) + ": " + quote(extra));
    if (vertex) addVertex(xyz, 0, r);
  }

  ByteSource& src_;
  const PlyHeader& h_;
  bool ascii_, big_;
  std::uint64_t vertexCount_;
  MeshData mesh_;
};

}  // namespace

MeshData detail::parsePlyFrom(ByteSource& src) {
  const PlyHeader header = detail::readPlyHeader(src);
  return PlyBody(src, header).read();
}

}  // namespace convexloc
