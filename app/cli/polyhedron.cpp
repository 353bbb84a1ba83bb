// convexloc CLI — the 3D commands (.off / .obj shapes).
//
// Polyhedra arrive with the 3D core. Until then this file only says so; replace it with the
// real classify3D / info3D / generatePoints3D, which follow the same contracts as the 2D
// commands in classify.cpp, info.cpp and generate.cpp.
#include "commands.hpp"

namespace convexloc::cli {
namespace {

// the one answer this build has for a polyhedron
[[noreturn]] void notYet(const std::string& shape) {
  failInput(shape, 0, "polyhedra (.off/.obj) are not supported by this build yet");
}

}  // namespace

void classify3D(const ClassifyOptions& o) {
  notYet(o.shape);
}

void info3D(const InfoOptions& o) {
  notYet(o.shape);
}

void generatePoints3D(const GeneratePointsOptions& o) {
  notYet(o.shape);
}

}  // namespace convexloc::cli
