// convexloc CLI — `generate polygon`, `generate polyhedron` and `generate points`: files in the
// formats classify reads.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

#include "commands.hpp"
#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/mesh_reader.hpp"

namespace convexloc::cli {
namespace {

// points generated per call of the core generator; fixed, so the output never depends on it
constexpr std::size_t kPointBlock = std::size_t{1} << 16;

// the seed of block `b` of a point stream: block 0 uses the seed itself, so a short stream
// equals one call of generatePoints; later blocks use a hash of (seed, b)
std::uint64_t blockSeed(std::uint64_t seed, std::size_t b) {
  if (b == 0) return seed;
  Rng mix(seed ^ (static_cast<std::uint64_t>(b) * 0xd1b54a32d192ed03ULL));
  return mix.next();
}

// the kind `parsed` from `name`, or a bad-usage failure listing every kind of `all`
template <class Kind, std::size_t N>
Kind kindOrFail(const std::string& name, std::optional<Kind> parsed, const Kind (&all)[N],
                const char* shape) {
  if (parsed) return *parsed;
  failUsage("unknown " + std::string(shape) + " kind '" + name + "'; choose one of " +
            namesOf(all));
}

// the header line of a point file: the command that wrote it
std::string pointsHeader(const GeneratePointsOptions& o) {
  return "# convexloc generate points --shape " + displayName(o.shape) + " --count " +
         std::to_string(o.count) + " --seed " + std::to_string(o.seed) +
         (o.nearBoundary ? " --near-boundary" : "") + "\n";
}

// Writes `o.count` points made by `make(n, seed)` in blocks of kPointBlock, so that memory
// stays constant however many are asked for.
template <class Make>
void writePoints(const GeneratePointsOptions& o, Make&& make) {
  Output out;
  out.put(pointsHeader(o));
  for (std::size_t done = 0, b = 0; done < o.count; ++b) {
    const std::size_t n = std::min(kPointBlock, o.count - done);
    for (const auto& p : make(n, blockSeed(o.seed, b))) out.point(p);
    done += n;
  }
  out.finish();
}

}  // namespace

void generatePolygon(const GeneratePolygonOptions& o) {
  const PolygonKind kind =
      kindOrFail(o.kind, parsePolygonKind(o.kind), kAllPolygonKinds, "polygon");
  std::vector<Vec2> vertices;
  try {
    vertices = convexloc::generatePolygon(kind, o.n, o.seed);
  } catch (const UsageError& e) {
    failUsage(e.what());
  }
  Output out;
  out.put("# convexloc generate polygon --kind " + std::string(toString(kind)) + " --n " +
          std::to_string(o.n) + " --seed " + std::to_string(o.seed) + "\n");
  out.put("# " + std::to_string(vertices.size()) +
          " vertices, counter-clockwise, one 'x y' per line");
  out.put(kind == PolygonKind::Degenerate
              ? " (repeated and collinear on purpose: it reduces to a square)\n"
              : "\n");
  for (Vec2 v : vertices) out.point(v);
  out.finish();
}

void generatePolyhedron(const GeneratePolyhedronOptions& o) {
  const PolyhedronKind kind =
      kindOrFail(o.kind, parsePolyhedronKind(o.kind), kAllPolyhedronKinds, "polyhedron");
  if (o.format != "off" && o.format != "obj" && o.format != "ply" && o.format != "stl")
    failUsage("unknown format '" + o.format + "'; choose off, obj, ply or stl");
  MeshData mesh;
  try {
    mesh = convexloc::generatePolyhedron(kind, o.n, o.seed);
  } catch (const UsageError& e) {
    failUsage(e.what());
  }
  try {
    // PLY as binary doubles and STL as text: both keep every bit of the doubles
    if (o.format == "obj")
      writeObj(stdout, mesh);
    else if (o.format == "ply")
      writePly(stdout, mesh, PlyEncoding::BinaryLittleEndian);
    else if (o.format == "stl")
      writeStl(stdout, mesh, true);
    else
      writeOff(stdout, mesh);
  } catch (const Error& e) {
    throw Failure(kExitBadInput, std::string("convexloc: cannot write the output: ") + e.what());
  }
  Output().finish();  // flushes stdout and reports a failed write
}

void generatePoints2D(const GeneratePointsOptions& o) {
  const ConvexPolygon polygon = loadPolygon(o.shape);
  writePoints(o, [&](std::size_t n, std::uint64_t seed) {
    return convexloc::generatePoints(polygon, n, seed, o.nearBoundary);
  });
}

void generatePoints3D(const GeneratePointsOptions& o) {
  const ConvexPolyhedron polyhedron = loadPolyhedron(o.shape);
  writePoints(o, [&](std::size_t n, std::uint64_t seed) {
    return convexloc::generatePoints3D(polyhedron, n, seed, o.nearBoundary);
  });
}

}  // namespace convexloc::cli
