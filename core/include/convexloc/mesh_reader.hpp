// convexloc — polyhedron files: OFF and OBJ in, OFF and OBJ out. 3D point files are read by
// text_reader.hpp (readPoints3D), included here.
//
// Readers are strict and stream in constant memory beyond what the file holds: a count in
// a header is checked against the limits and never used to allocate. Every ParseError
// carries the 1-based line of the problem. Numbers follow text_reader.hpp (decimal, no hex,
// inf or nan). Readers check syntax and index ranges only; ConvexPolyhedron validates.
#pragma once

#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/text_reader.hpp"

namespace convexloc {

// The most vertices, and the most faces, a mesh file may hold or announce.
inline constexpr std::size_t kMaxMeshElements = kMaxPolyhedronFaces;

// the two mesh formats
enum class MeshFormat : std::uint8_t { Off, Obj };

// The format a path names by its extension (".off" or ".obj", any case), if either.
std::optional<MeshFormat> meshFormatOf(std::string_view path);

// OFF: an optional header keyword ("OFF"; "COFF", "NOFF", "CNOFF", "STOFF" and the like
// allow extra numbers after each vertex's 3 coordinates; "4OFF" and "nOFF" are rejected),
// then "V F [E]" (on the header line or the next), V vertex lines "x y z", F face lines
// "k i1 ... ik [colour]" with 0-based indices and k >= 3. '#' starts a comment; blank
// lines are skipped; one record per line; nothing may follow the last face.
MeshData parseOff(std::FILE* file);
MeshData parseOff(std::string_view text);

// OBJ: "v x y z [w = 1 | r g b [a]]" and "f a b c ..." where each reference is "i", "i/t",
// "i//n" or "i/t/n" with i 1-based, or negative counting back from the last vertex so far;
// every other statement (vn, vt, o, g, s, usemtl, l, ...) is ignored. Indices are returned
// 0-based. A face may refer to a vertex defined later in the file.
MeshData parseObj(std::FILE* file);
MeshData parseObj(std::string_view text);

// Reads the mesh file at `path` ("-" is standard input, read as OFF), choosing the format by
// extension. Throws Error when it cannot be opened, UsageError for another extension.
MeshData readMesh(const std::string& path);

// Reads and validates a polyhedron file (readMesh, then ConvexPolyhedron).
ConvexPolyhedron loadPolyhedron(const std::string& path);

// The triangles of a polyhedron as a mesh (vertices and triangles as stored).
MeshData toMesh(const ConvexPolyhedron& polyhedron);

// Writes `mesh` as OFF or OBJ; every coordinate is the shortest decimal that reads back to
// the same double. Throws Error on a write failure.
void writeOff(std::FILE* out, const MeshData& mesh);
void writeObj(std::FILE* out, const MeshData& mesh);

}  // namespace convexloc
