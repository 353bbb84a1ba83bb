// convexloc — reading a mesh file by its extension, and the mesh of a polyhedron.
//
// The readers live one format a file: off_reader.cpp, obj_reader.cpp, stl_reader.cpp,
// ply_header.cpp with ply_reader.cpp; the writers in mesh_writer.cpp.
#include "convexloc/mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/text_reader.hpp"
#include "io/mesh_parsers.hpp"

namespace convexloc {
namespace {

// the format's parser run over a FILE or over text: OFF and OBJ read lines, STL and PLY bytes
template <class Input>
MeshData parseAs(MeshFormat format, Input in) {
  if (format == MeshFormat::Off || format == MeshFormat::Obj || format == MeshFormat::Xyz) {
    LineReader src(in);
    if (format == MeshFormat::Xyz) return detail::parseXyzFrom(src);
    return format == MeshFormat::Off ? detail::parseOffFrom(src) : detail::parseObjFrom(src);
  }
  detail::ByteSource src(in);
  return format == MeshFormat::Stl ? detail::parseStlFrom(src) : detail::parsePlyFrom(src);
}

}  // namespace

MeshData parseMesh(MeshFormat format, std::FILE* file) {
  return parseAs(format, file);
}
MeshData parseMesh(MeshFormat format, std::string_view text) {
  return parseAs(format, text);
}

std::optional<MeshFormat> meshFormatOf(std::string_view path) {
  if (path.size() < 4) return std::nullopt;
  std::string ext(path.substr(path.size() - 4));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".xyz" || ext == ".pts") return MeshFormat::Xyz;
  return std::nullopt;
}

MeshData readMesh(const std::string& path) {
  std::optional<MeshFormat> format = path == "-" ? MeshFormat::Off : meshFormatOf(path);
  if (!format)
    throw UsageError("unknown mesh format: '" + path +
                     "' (expected .off, .obj, .stl or .ply, or a point cloud .xyz or .pts)");
  InputFile in(path);
  return parseMesh(*format, in.get());
}

ConvexPolyhedron polyhedronOf(const MeshData& mesh) {
  if (mesh.faceCount() == 0 && !mesh.vertices.empty())
    throw GeometryError("the mesh has no faces, only " + std::to_string(mesh.vertices.size()) +
                            " vertices (a point cloud?): take the convex hull of its vertices "
                            "instead (--hull; hull=True in Python)",
                        mesh.vertexLines.empty() ? 0 : mesh.vertexLines.back());
  try {
    return ConvexPolyhedron(mesh);
  } catch (const GeometryError& e) {
    // faces no longer exactly planar (coordinates rounded by an exporter) fail this way
    const std::string what = e.what();
    if (what.rfind("not convex", 0) != 0 || what.find("--hull") != std::string::npos) throw;
    throw GeometryError(what +
                            " (where rounded coordinates left faces not exactly planar, "
                            "--hull takes the convex hull of the vertices; hull=True in Python)",
                        e.line());
  }
}

ConvexPolyhedron loadPolyhedron(const std::string& path) {
  return polyhedronOf(readMesh(path));
}

ConvexPolyhedron loadHull(const std::string& path) {
  const MeshData mesh = readMesh(path);
  return ConvexPolyhedron::hullOf(mesh.vertices);
}

MeshData toMesh(const ConvexPolyhedron& polyhedron) {
  MeshData mesh;
  mesh.vertices.assign(polyhedron.vertices().begin(), polyhedron.vertices().end());
  mesh.indices.reserve(3 * polyhedron.faceCount());
  mesh.faceStart.reserve(polyhedron.faceCount() + 1);
  for (const auto& t : polyhedron.triangles()) mesh.addFace({t[0], t[1], t[2]});
  return mesh;
}

}  // namespace convexloc
