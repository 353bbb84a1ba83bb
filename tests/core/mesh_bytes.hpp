// Mesh files as bytes for the STL and PLY tests: what a writer produces, read back through a
// FILE or from memory, and binary records assembled by hand (independent of the writers'
// byte-order code).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/mesh_reader.hpp"

namespace meshbytes {

using convexloc::MeshData;
using convexloc::Vec3;

// the bytes `write(FILE*)` writes
template <class Write>
std::string written(Write&& write) {
  std::FILE* f = std::tmpfile();
  if (!f) throw std::runtime_error("no temporary file");
  write(f);
  std::fflush(f);
  const long size = std::ftell(f);
  std::rewind(f);
  std::string out(static_cast<std::size_t>(size), '\0');
  const std::size_t got = std::fread(out.data(), 1, out.size(), f);
  std::fclose(f);
  out.resize(got);
  return out;
}

// `parse(FILE*)` on a FILE holding `bytes`
template <class Parse>
MeshData throughFile(const std::string& bytes, Parse&& parse) {
  std::FILE* f = std::tmpfile();
  if (!f) throw std::runtime_error("no temporary file");
  std::fwrite(bytes.data(), 1, bytes.size(), f);
  std::rewind(f);
  try {
    MeshData m = parse(f);
    std::fclose(f);
    return m;
  } catch (...) {
    std::fclose(f);
    throw;
  }
}

// `v` rounded to the nearest float. Through a volatile: GCC 12.2's SLP vectorizer (-O2)
// folds the pair of conversions in a loop over x, y, z into nothing.
inline double nearestFloat(double v) {
  volatile float f = static_cast<float>(v);
  return static_cast<double>(f);
}

// every coordinate rounded to the nearest float (a shape STL can hold exactly)
inline MeshData toFloats(MeshData m) {
  for (Vec3& p : m.vertices) p = {nearestFloat(p.x), nearestFloat(p.y), nearestFloat(p.z)};
  return m;
}

// Bytes assembled one value at a time, in a chosen byte order, by shifts of the bit pattern.
struct Bytes {
  std::string s;
  bool big = false;
  // an unsigned value of `n` bytes
  Bytes& uint(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) {
      const int shift = 8 * (big ? n - 1 - i : i);
      s += static_cast<char>((v >> shift) & 0xff);
    }
    return *this;
  }
  Bytes& f32(float v) {
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    return uint(u, 4);
  }
  Bytes& f64(double v) {
    std::uint64_t u;
    std::memcpy(&u, &v, 8);
    return uint(u, 8);
  }
  Bytes& text(const std::string& t) {
    s += t;
    return *this;
  }
};

// a binary STL of `facets` (three corners each), header text `head` (padded to 80 bytes),
// the count `count` (the true one when negative)
inline std::string binaryStl(const std::vector<std::vector<Vec3>>& facets, std::string head = "",
                             long long count = -1) {
  head.resize(80, ' ');
  Bytes b;
  b.text(head).uint(count < 0 ? facets.size() : static_cast<std::uint64_t>(count), 4);
  for (const auto& f : facets) {
    b.f32(0).f32(0).f32(0);
    for (const Vec3& p : f)
      b.f32(static_cast<float>(p.x)).f32(static_cast<float>(p.y)).f32(static_cast<float>(p.z));
    b.uint(0, 2);
  }
  return b.s;
}

// the triangles of `m` (fan-triangulated) as corner triples
inline std::vector<std::vector<Vec3>> facetsOf(const MeshData& m) {
  std::vector<std::vector<Vec3>> out;
  for (std::size_t f = 0; f < m.faceCount(); ++f) {
    const auto face = m.face(f);
    for (std::size_t k = 2; k < face.size(); ++k)
      out.push_back({m.vertices[face[0]], m.vertices[face[k - 1]], m.vertices[face[k]]});
  }
  return out;
}

// the ParseError of parsing `text` in `format`, with its line ("no error", 0 when it parses)
struct Problem {
  std::string message;
  std::size_t line = 0;
};
inline Problem problemOf(convexloc::MeshFormat format, const std::string& text) {
  try {
    convexloc::parseMesh(format, text);
  } catch (const convexloc::ParseError& e) {
    return {e.what(), e.line()};
  }
  return {"no error", 0};
}

}  // namespace meshbytes
