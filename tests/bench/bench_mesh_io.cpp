// convexloc-bench, mesh files: LoadMesh reads a geodesic sphere of about 100k triangles
// (coordinates rounded to floats, so that every format holds them exactly) from a file in
// each format and encoding through readMesh, as the tool does. Reported as triangles per
// second and bytes per second.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/mesh_reader.hpp"

using namespace convexloc;

namespace {

// the sphere, every coordinate a float (through a volatile: GCC 12's SLP vectorizer can fold
// a double-float-double round trip over x, y, z into nothing)
MeshData floatSphere() {
  MeshData m = generatePolyhedron(PolyhedronKind::Geodesic, 100000, 1);
  auto nearest = [](double v) {
    volatile float f = static_cast<float>(v);
    return static_cast<double>(f);
  };
  for (Vec3& p : m.vertices) p = {nearest(p.x), nearest(p.y), nearest(p.z)};
  return m;
}

// the formats, by benchmark name and file name
constexpr std::pair<const char*, const char*> kFormats[] = {{"off", "sphere.off"},
                                                            {"stl_ascii", "sphere_ascii.stl"},
                                                            {"stl_binary", "sphere.stl"},
                                                            {"ply_ascii", "sphere_ascii.ply"},
                                                            {"ply_le_float", "sphere_f.ply"},
                                                            {"ply_le_double", "sphere_le.ply"},
                                                            {"ply_be_double", "sphere_be.ply"}};

// writes `m` in format `k` of kFormats to `out`
void writeFormat(std::size_t k, std::FILE* out, const MeshData& m) {
  switch (k) {
    case 0: writeOff(out, m); break;
    case 1: writeStl(out, m, true); break;
    case 2: writeStl(out, m); break;
    case 3: writePly(out, m, PlyEncoding::Ascii); break;
    case 4: writePly(out, m, PlyEncoding::BinaryLittleEndian, true); break;
    case 5: writePly(out, m, PlyEncoding::BinaryLittleEndian); break;
    default: writePly(out, m, PlyEncoding::BinaryBigEndian); break;
  }
}

// The sphere written once in every format (on first use), in a directory removed at exit.
struct Files {
  std::filesystem::path dir;
  Files() {
    dir = std::filesystem::temp_directory_path() /
          ("convexloc-bench-meshes-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const MeshData m = floatSphere();
    for (std::size_t k = 0; k < std::size(kFormats); ++k) {
      std::FILE* f = std::fopen(path(k).c_str(), "wb");
      if (!f) throw Error("cannot write " + path(k));
      writeFormat(k, f, m);
      std::fclose(f);
    }
  }
  ~Files() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  std::string path(std::size_t k) const { return (dir / kFormats[k].second).string(); }
};

// reads format `k` with readMesh, as the tool does
void loadMesh(benchmark::State& state, std::size_t k) {
  static const Files files;
  const std::string path = files.path(k);
  const std::uintmax_t bytes = std::filesystem::file_size(path);
  std::size_t faces = 0;
  for (auto _ : state) {
    const MeshData m = readMesh(path);
    faces = m.faceCount();
    benchmark::DoNotOptimize(m.vertices.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * faces));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
  state.counters["triangles"] = static_cast<double>(faces);
  state.counters["MB"] = static_cast<double>(bytes) / 1e6;
}

[[maybe_unused]] const bool registered = [] {
  for (std::size_t k = 0; k < std::size(kFormats); ++k)
    benchmark::RegisterBenchmark((std::string("LoadMesh/") + kFormats[k].first).c_str(),
                                 [k](benchmark::State& s) { loadMesh(s, k); })
        ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace
