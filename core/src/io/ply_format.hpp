// convexloc (internal) — a PLY header as read (ply_header.cpp), for the body reader
// (ply_reader.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/byte_source.hpp"

namespace convexloc::detail {

// the scalar types of PLY 1.0
enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

// the bytes a value of type `t` takes in a binary file
constexpr std::size_t plyTypeSize(PlyType t) noexcept {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: break;
  }
  return 8;
}

// whether `t` is one of the integer types
constexpr bool plyInteger(PlyType t) noexcept {
  return t != PlyType::Float32 && t != PlyType::Float64;
}

// "property TYPE NAME" or "property list COUNT_TYPE TYPE NAME"
struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;     // the value's type (a list's items)
  PlyType countType = PlyType::UInt8;  // a list's count, when `list`
  bool list = false;
  std::size_t line = 0;  // the header line that declares it
};

// "element NAME COUNT" and its properties, in the order of the file
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::size_t line = 0;
  // the bytes of one binary record when no property is a list, else 0
  std::size_t fixedBytes() const noexcept;
};

// how the data after the header is stored
enum class PlyStorage : std::uint8_t { Ascii, BinaryLittleEndian, BinaryBigEndian };

// the header: format and elements; which element holds the vertices and which the faces,
// and where x, y, z and the face's index list sit among their properties
struct PlyHeader {
  PlyStorage storage = PlyStorage::Ascii;
  std::vector<PlyElement> elements;
  std::size_t vertexElement = 0;       // index into elements
  std::size_t xyz[3] = {0, 0, 0};      // property indices of x, y, z
  std::size_t faceElement = SIZE_MAX;  // SIZE_MAX: no faces
  std::size_t indexList = 0;           // property index of vertex_indices
  std::size_t endLine = 0;             // the line of "end_header"
};

// Reads the header from the start of `src` up to and including "end_header", leaving `src`
// at the first byte of the data. ParseError naming the header line at fault.
PlyHeader readPlyHeader(ByteSource& src);

}  // namespace convexloc::detail
