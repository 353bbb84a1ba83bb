// convexloc (internal) — each mesh format's parser over its source: lines for the text
// formats, bytes (with offsets for errors) for STL and PLY. mesh_reader.cpp runs them over a
// FILE or over text; each is defined in its format's file.
#pragma once

#include "convexloc/polyhedron.hpp"
#include "convexloc/text_reader.hpp"
#include "io/byte_source.hpp"

namespace convexloc::detail {

// OFF (off_reader.cpp)
MeshData parseOffFrom(LineReader& src);
// OBJ (obj_reader.cpp)
MeshData parseObjFrom(LineReader& src);
// a point cloud, x y z a line (xyz_reader.cpp)
MeshData parseXyzFrom(LineReader& src);
// STL, ASCII or binary (stl_reader.cpp)
MeshData parseStlFrom(ByteSource& src);
// PLY, ASCII or binary in either byte order (ply_reader.cpp)
MeshData parsePlyFrom(ByteSource& src);

}  // namespace convexloc::detail
