// convexloc fuzzing — the body shared by the mesh reader targets (OFF, OBJ, STL, PLY).
//
// The bytes are read twice, as text in memory and through a FILE: both readers must agree
// exactly (the same mesh, or the same error on the same line). A mesh must be well formed
// (checkMesh); ConvexPolyhedron either rejects it with a GeometryError naming a line of the
// file, or gives a polyhedron that is exactly what validation promises (checkPolyhedron) and
// that every 3D method locates exactly at its vertices, edges, faces and their neighbours.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "check3d.hpp"
#include "convexloc/error.hpp"
#include "convexloc/mesh_reader.hpp"
#include "fuzz_support.hpp"

namespace fuzz {

// lines in the text: a last line without '\n' counts
inline std::size_t lineCount(std::string_view text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n + (!text.empty() && text.back() != '\n');
}

// what one reading gave: a mesh, or an error's line and message
struct Reading {
  std::optional<MeshData> mesh;
  std::size_t line = 0;
  std::string error;
};

template <class ReadText, class ReadFile>
void meshReaderTarget(const std::uint8_t* data, std::size_t size, ReadText readText,
                      ReadFile readFile) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::size_t lines = lineCount(text);
  auto attempt = [&](auto&& read) {
    Reading r;
    try {
      r.mesh = read();
    } catch (const convexloc::ParseError& e) {
      r.line = e.line();
      r.error = e.what();
      if (r.error.empty()) fail("a ParseError without a message");
      if (r.line > lines)
        fail("ParseError names line " + std::to_string(r.line) + " of a " + std::to_string(lines) +
             "-line file: " + r.error);
    }
    return r;
  };
  Reading fromText = attempt([&] { return readText(text); });
  MemFile file(data, size);
  Reading fromFile = attempt([&] { return readFile(file.get()); });
  if (fromText.mesh.has_value() != fromFile.mesh.has_value() || fromText.line != fromFile.line ||
      fromText.error != fromFile.error)
    fail("the text reader says '" + fromText.error + "' (line " + std::to_string(fromText.line) +
         "), the FILE reader '" + fromFile.error + "' (line " + std::to_string(fromFile.line) +
         ")");
  if (!fromText.mesh) return;
  const MeshData& mesh = *fromText.mesh;
  checkSameMesh(mesh, *fromFile.mesh);
  checkMesh(mesh);
  std::optional<ConvexPolyhedron> poly;
  try {
    poly.emplace(mesh);
  } catch (const convexloc::GeometryError& e) {
    if (e.line() > lines)
      fail("GeometryError names line " + std::to_string(e.line()) + " of a " +
           std::to_string(lines) + "-line file: " + e.what());
    return;
  }
  if (poly->faceCount() > 200) return;  // the exact checks are O(F V)
  checkPolyhedron(*poly);
  std::vector<Vec3> queries;
  addHardPoints3d(queries, *poly);
  checkMethods3d(*poly, queries, 0);
}

}  // namespace fuzz
