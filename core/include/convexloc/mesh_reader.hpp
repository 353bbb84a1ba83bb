// convexloc — polyhedron files: OFF, OBJ, STL and PLY in, the same out. 3D point files are
// read by text_reader.hpp (readPoints3D), included here.
//
// Readers are strict and stream in constant memory beyond what the file holds: a count in
// a header is checked against the limits and never used to allocate beyond what the file's
// size can hold. A ParseError about text carries the 1-based line of the problem; one about
// binary data has line 0 and a message that starts "byte N: " with the offset of the record
// at fault. Numbers in text follow text_reader.hpp (decimal, no hex, inf or nan), whatever
// type a header declares; binary numbers are converted to doubles exactly, and NaN or
// infinite coordinates are refused. Readers check syntax and index ranges only;
// ConvexPolyhedron validates.
#pragma once

#include <cstddef>
#include <cstdint>
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

// the mesh formats, and point clouds (Xyz)
enum class MeshFormat : std::uint8_t { Off, Obj, Stl, Ply, Xyz };

// The format a path names by its extension (".off", ".obj", ".stl" or ".ply"; ".xyz" or
// ".pts" for a point cloud; any case).
std::optional<MeshFormat> meshFormatOf(std::string_view path);

// OFF: an optional header keyword ("OFF"; "COFF", "NOFF", "CNOFF", "STOFF" and the like
// allow extra numbers after each vertex's 3 coordinates; "4OFF" and "nOFF" are rejected),
// then "V F [E]" (on the header line or the next), V vertex lines "x y z", F face lines
// "k i1 ... ik [colour]" with 0-based indices and k >= 3. '#' starts a comment; blank
// lines are skipped; one record per line; nothing may follow the last face.

// OBJ: "v x y z [w = 1 | r g b [a]]" and "f a b c ..." where each reference is "i", "i/t",
// "i//n" or "i/t/n" with i 1-based, or negative counting back from the last vertex so far;
// every other statement (vn, vt, o, g, s, usemtl, l, ...) is ignored. Indices are returned
// 0-based. A face may refer to a vertex defined later in the file.

// STL, binary or ASCII. Binary: an 80-byte header, a little-endian uint32 facet count, then
// 50 bytes a facet (normal, 3 vertices as float32, a uint16 attribute); the file must be
// exactly 84 + 50 * count bytes. ASCII: "solid [name]", then per facet "facet normal i j k",
// "outer loop", 3 "vertex x y z", "endloop", "endfacet", then "endsolid [name]", one
// statement a line (several solids may follow one another). A file is ASCII when it starts
// with "solid" and its first 84 bytes are all text; a binary file's count then always holds a
// byte below 9, and any count over kMaxMeshElements is refused. Corners with exactly equal
// coordinates become one vertex (in order of first use); the facet normal is ignored: the
// orientation comes from the order of the vertices, as STL requires them anyway.

// PLY 1.0: "ply", "format ascii|binary_little_endian|binary_big_endian 1.0", comment and
// obj_info lines, elements with their properties, "end_header". Element "vertex" needs
// scalar properties x, y and z of any type (char, uchar, short, ushort, int, uint, float,
// double or the int8 .. float64 names); element "face" needs a list property
// "vertex_indices" (or "vertex_index") with an integer count and index type. Every other
// property and element is read past, lists included. A file without faces (a point cloud)
// gives a mesh with vertices only. ASCII records are one a line.

// XYZ and PTS point clouds: one point "x y z" a line, further numbers on it (intensity,
// colour, a normal) read past, numbers separated by blanks or commas, '#' comments and blank
// lines skipped; a first line holding one whole number is the point count (.pts), and must
// match. The mesh has vertices only: read it as a hull (loadHull, --hull).

// Parses a mesh in `format` (grammars above) from an open file, read to its end, or from the
// text or bytes in memory. Throws ParseError naming the line (text) or byte offset (binary).
MeshData parseMesh(MeshFormat format, std::FILE* file);
MeshData parseMesh(MeshFormat format, std::string_view bytes);

// Reads the mesh file at `path` ("-" is standard input, read as OFF), choosing the format by
// extension. Throws Error when it cannot be opened, UsageError for another extension.
MeshData readMesh(const std::string& path);

// Validates a mesh read from a file (ConvexPolyhedron); a mesh with vertices and no faces, or
// one refused as not convex, gets a GeometryError that suggests the hull.
ConvexPolyhedron polyhedronOf(const MeshData& mesh);

// Reads and validates a polyhedron file (readMesh, then polyhedronOf).
ConvexPolyhedron loadPolyhedron(const std::string& path);

// The convex hull of every vertex of a mesh file (readMesh, then ConvexPolyhedron::hullOf):
// the faces, if any, are ignored, so a point cloud works too.
ConvexPolyhedron loadHull(const std::string& path);

// The triangles of a polyhedron as a mesh (vertices and triangles as stored).
MeshData toMesh(const ConvexPolyhedron& polyhedron);

// Writes `mesh` as OFF or OBJ; every coordinate is the shortest decimal that reads back to
// the same double. Throws Error on a write failure.
void writeOff(std::FILE* out, const MeshData& mesh);
void writeObj(std::FILE* out, const MeshData& mesh);

// Writes `mesh` as binary STL (ASCII: `ascii`), faces fan-triangulated from their first
// vertex, normals zero. Binary STL holds float32: Error when a coordinate is not exactly a
// float. ASCII coordinates are shortest round-trip decimals of the doubles.
void writeStl(std::FILE* out, const MeshData& mesh, bool ascii = false);

// how writePly encodes the data
enum class PlyEncoding : std::uint8_t { Ascii, BinaryLittleEndian, BinaryBigEndian };

// Writes `mesh` as PLY: vertices x y z as double (`float32`: as float, Error when a
// coordinate is not exactly a float), faces as "list uchar int vertex_indices" (uint counts
// for faces of 256 vertices or more); ASCII numbers are shortest round-trip decimals.
void writePly(std::FILE* out, const MeshData& mesh, PlyEncoding encoding, bool float32 = false);

}  // namespace convexloc
