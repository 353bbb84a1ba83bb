// convexloc — the PLY header: "ply", the format line, comments, elements and their
// properties, "end_header"; then what the mesh needs from them, checked once.
#include <string>
#include <string_view>

#include "convexloc/error.hpp"
#include "convexloc/mesh_reader.hpp"
#include "io/mesh_tokens.hpp"
#include "io/ply_format.hpp"

namespace convexloc::detail {

std::size_t PlyElement::fixedBytes() const noexcept {
  std::size_t bytes = 0;
  for (const PlyProperty& p : properties) {
    if (p.list) return 0;
    bytes += plyTypeSize(p.type);
  }
  return bytes;
}

namespace {

// the most properties, over all elements, a header may declare (it is held in memory)
constexpr std::size_t kMaxHeaderProperties = 4096;

// a type by its PLY name (both the old and the sized names); false for another word
bool typeNamed(std::string_view word, PlyType& type) {
  struct Named {
    std::string_view a, b;
    PlyType type;
  };
  static constexpr Named kNames[] = {
      {"char", "int8", PlyType::Int8},        {"uchar", "uint8", PlyType::UInt8},
      {"short", "int16", PlyType::Int16},     {"ushort", "uint16", PlyType::UInt16},
      {"int", "int32", PlyType::Int32},       {"uint", "uint32", PlyType::UInt32},
      {"float", "float32", PlyType::Float32}, {"double", "float64", PlyType::Float64}};
  for (const Named& n : kNames)
    if (word == n.a || word == n.b) {
      type = n.type;
      return true;
    }
  return false;
}

// the type named by the next token of `t`
PlyType typeToken(Tokens& t, std::size_t line) {
  std::string_view word;
  PlyType type{};
  if (!t.next(word)) throw ParseError("a property needs a type and a name", line);
  if (!typeNamed(word, type))
    throw ParseError("unknown PLY type " + quote(word) +
                         " (expected char, uchar, short, ushort, int, uint, float, double or "
                         "int8 .. float64)",
                     line);
  return type;
}

// an element's or a property's name: printable ASCII only, since messages quote it
void checkName(std::string_view name, const char* what, std::size_t line) {
  for (char c : name)
    if (c < 0x21 || c > 0x7e)
      throw ParseError(std::string("a") + what + " name must be printable ASCII: " + quote(name),
                       line);
}

// A header being read, one line at a time.
struct HeaderReading {
  ByteSource& src;
  PlyHeader header;
  bool formatSeen = false;
  std::size_t properties = 0;

  // "format ascii|binary_little_endian|binary_big_endian 1.0"
  void format(Tokens& t) {
    std::string_view kind, version, extra;
    if (formatSeen) throw ParseError("a second 'format' line", src.line());
    if (!t.next(kind) || !t.next(version) || t.next(extra))
      throw ParseError("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'",
                       src.line());
    if (kind == "ascii")
      header.storage = PlyStorage::Ascii;
    else if (kind == "binary_little_endian")
      header.storage = PlyStorage::BinaryLittleEndian;
    else if (kind == "binary_big_endian")
      header.storage = PlyStorage::BinaryBigEndian;
    else
      throw ParseError("unknown PLY format " + quote(kind), src.line());
    if (version != "1.0") throw ParseError("unsupported PLY version " + quote(version), src.line());
    formatSeen = true;
  }

  // "element NAME COUNT"
  void element(Tokens& t) {
    std::string_view name, count, extra;
    if (!t.next(name) || !t.next(count) || t.next(extra))
      throw ParseError("expected 'element NAME COUNT'", src.line());
    checkName(name, "n element", src.line());
    long long n = 0;
    if (!integer(count, n) || n < 0)
      throw ParseError("the element count is not a non-negative integer: " + quote(count),
                       src.line());
    if ((name == "vertex" || name == "face") &&
        static_cast<unsigned long long>(n) > kMaxMeshElements)
      throw ParseError("the header announces " + std::string(count) + " " + std::string(name) +
                           " records; at most " + std::to_string(kMaxMeshElements) +
                           " are supported",
                       src.line());
    for (const PlyElement& e : header.elements)
      if (e.name == name) throw ParseError("a second element " + quote(name), src.line());
    header.elements.push_back({std::string(name), static_cast<std::uint64_t>(n), {}, src.line()});
  }

  // "property TYPE NAME" or "property list COUNT_TYPE TYPE NAME"
  void property(Tokens& t) {
    if (header.elements.empty()) throw ParseError("a property before any element", src.line());
    if (++properties > kMaxHeaderProperties)
      throw ParseError("more than " + std::to_string(kMaxHeaderProperties) + " properties",
                       src.line());
    PlyProperty p;
    p.line = src.line();
    Tokens probe = t;
    std::string_view word, extra;
    if (probe.next(word) && word == "list") {
      t.next(word);
      p.list = true;
      p.countType = typeToken(t, p.line);
      if (!plyInteger(p.countType))
        throw ParseError("a list's count type must be an integer type", p.line);
    }
    p.type = typeToken(t, p.line);
    if (!t.next(word) || t.next(extra))
      throw ParseError("expected 'property [list COUNT_TYPE] TYPE NAME'", p.line);
    checkName(word, " property", p.line);
    p.name = std::string(word);
    PlyElement& e = header.elements.back();
    for (const PlyProperty& q : e.properties)
      if (q.name == p.name)
        throw ParseError("a second property " + quote(word) + " in element " + quote(e.name),
                         p.line);
    e.properties.push_back(std::move(p));
  }

  // one header line; false at "end_header"
  bool line(std::string_view text) {
    Tokens t(text, false);
    std::string_view word;
    if (!t.next(word)) throw ParseError("a blank line in the PLY header", src.line());
    if (word == "end_header") {
      if (t.next(word)) throw ParseError("unexpected text after 'end_header'", src.line());
      return false;
    }
    if (word == "comment" || word == "obj_info") return true;
    if (!formatSeen && word != "format")
      throw ParseError("expected the 'format' line, found " + quote(word), src.line());
    if (word == "format")
      format(t);
    else if (word == "element")
      element(t);
    else if (word == "property")
      property(t);
    else
      throw ParseError("unknown PLY header line " + quote(word), src.line());
    return true;
  }
};

// the index of property `name` of `e`, checked to be a scalar; SIZE_MAX when absent
std::size_t scalarNamed(const PlyElement& e, std::string_view name) {
  for (std::size_t i = 0; i < e.properties.size(); ++i)
    if (e.properties[i].name == name) {
      if (e.properties[i].list)
        throw ParseError("vertex property " + quote(name) + " must be a number, not a list",
                         e.properties[i].line);
      return i;
    }
  return SIZE_MAX;
}

// the vertex element and its x, y, z
void findVertices(PlyHeader& h, std::size_t endLine) {
  for (std::size_t i = 0; i < h.elements.size(); ++i)
    if (h.elements[i].name == "vertex") {
      const PlyElement& e = h.elements[i];
      h.vertexElement = i;
      const char* names[3] = {"x", "y", "z"};
      for (int k = 0; k < 3; ++k) {
        h.xyz[k] = scalarNamed(e, names[k]);
        if (h.xyz[k] == SIZE_MAX)
          throw ParseError("element 'vertex' has no property '" + std::string(names[k]) + "'",
                           e.line);
      }
      return;
    }
  throw ParseError("the header declares no 'vertex' element", endLine);
}

// the face element and its index list, when there is one
void findFaces(PlyHeader& h) {
  for (std::size_t i = 0; i < h.elements.size(); ++i) {
    const PlyElement& e = h.elements[i];
    if (e.name == "tristrips" && e.count > 0)
      throw ParseError("triangle strips ('tristrips') are not supported; use 'face'", e.line);
    if (e.name != "face") continue;
    std::size_t found = SIZE_MAX;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const PlyProperty& p = e.properties[k];
      if (p.name != "vertex_indices" && p.name != "vertex_index") continue;
      if (found != SIZE_MAX)
        throw ParseError("element 'face' has both 'vertex_indices' and 'vertex_index'", p.line);
      if (!p.list || !plyInteger(p.type))
        throw ParseError("'" + p.name + "' must be a list of an integer type", p.line);
      found = k;
    }
    if (found == SIZE_MAX && e.count > 0)
      throw ParseError("element 'face' has no list property 'vertex_indices'", e.line);
    if (found != SIZE_MAX) {
      h.faceElement = i;
      h.indexList = found;
    }
  }
}

}  // namespace

PlyHeader readPlyHeader(ByteSource& src) {
  std::string_view text, word;
  Tokens first(src.nextLine(text) ? text : std::string_view(), false);
  if (!first.next(word) || word != "ply" || first.next(word))
    throw ParseError("not a PLY file: the first line must be 'ply'", src.line());
  HeaderReading reading{src, {}};
  for (;;) {
    if (!src.nextLine(text))
      throw ParseError("the file ends inside the PLY header (no 'end_header')", src.line());
    if (!reading.line(text)) break;
  }
  PlyHeader& h = reading.header;
  h.endLine = src.line();
  findVertices(h, h.endLine);
  findFaces(h);
  return std::move(h);
}

}  // namespace convexloc::detail
