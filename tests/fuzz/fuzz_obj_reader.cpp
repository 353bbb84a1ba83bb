// Fuzz target: the OBJ reader (parseMesh), then ConvexPolyhedron and every 3D method; see
// mesh_reader_target.hpp for what is checked.
#include <cstddef>
#include <cstdint>

#include "mesh_reader_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::meshReaderTarget(
      data, size,
      [](std::string_view text) { return convexloc::parseMesh(convexloc::MeshFormat::Obj, text); },
      [](std::FILE* file) { return convexloc::parseMesh(convexloc::MeshFormat::Obj, file); });
  return 0;
}
