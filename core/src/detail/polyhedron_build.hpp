// convexloc (internal) — the validation of a polyhedron as a pipeline of named checks.
//
// The checks run from the cheap and local to the global, so that the first error is the
// most specific one: the mesh's arrays, numbers and indices, faces, edges (open,
// non-manifold, orientation), pieces and Euler characteristic, volume, zero-area triangles,
// convexity edge by edge (exact orient3d), and last the global test that the surface wraps
// around its inside exactly once. Each check throws its own GeometryError (UsageError for
// inconsistent arrays or a mesh too large) naming the witness.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "convexloc/polyhedron.hpp"

namespace convexloc::detail {

// a, b, c lie on one line (exact: every component of (b - a) x (c - a) is zero)
bool collinear(Vec3 a, Vec3 b, Vec3 c);

// six times the signed volume of the tetrahedron (o, a, b, c), in long double; p receives
// a, b and c relative to o
long double sixVolume(Vec3 o, Vec3 a, Vec3 b, Vec3 c, long double (&p)[3][3]);

// A fold across an edge between triangles (a, b, p) and (b, a, q), measured in long double
// for a message (polyhedron_fold.cpp): q's distance off the plane of a, b, p, the angle between
// the two planes, and the most that rounding the corners' coordinates could explain.
struct Fold {
  long double off = 0;       // q's distance from the plane of a, b, p
  long double degrees = 0;   // the angle between the planes, in degrees
  long double rounding = 0;  // the largest `off` that rounding the corners can make
  bool float32 = false;      // every coordinate of the four corners is a float32
};
Fold measureFold(Vec3 a, Vec3 b, Vec3 p, Vec3 q);
// "a fold of D degrees, X off the plane: " and whether --hull is safe or fills a dent
std::string describeFold(const Fold& fold);
// "within (beyond) the rounding of float32 (double) coordinates": whether rounding explains
// the fold's `off`
std::string roundingVerdict(const Fold& fold);

// "(x, y, z)" with enough digits to find the point again
std::string show(Vec3 p);
// "(x, y)" likewise (polygon.cpp)
std::string show(Vec2 p);

// Validates and normalises a mesh into a ConvexPolyhedron, step by step; the steps run in
// the order declared.
class PolyhedronBuilder {
 public:
  using Triangle = ConvexPolyhedron::Triangle;

  // fills `out` from `mesh`; `suspects`, when given, receives the input vertices a failed
  // convexity check blames
  PolyhedronBuilder(ConvexPolyhedron& out, const MeshData& mesh,
                    std::vector<std::uint32_t>* suspects);

  // === the mesh as given (polyhedron_checks.cpp)
  // faceStart and the line vectors agree with the data; not too many vertices (UsageError)
  void checkArrays() const;
  // every coordinate finite
  void checkFiniteVertices() const;
  // faces exist, have 3 vertices or more, index existing vertices; not too many triangles
  void checkFaces();
  // merges vertices with equal coordinates, drops unused ones
  void mergeVertices();
  // drops consecutive repeats, rejects other repeats, fan-triangulates
  void fanTriangulate();
  // each undirected edge used exactly twice, in opposite directions; fills neighbours
  void pairEdges();
  // one piece, a topological sphere
  void checkOnePieceSphere() const;
  // the vertices of every input face in one plane (exact orient3d), whatever its first vertex
  void checkPlanarFaces() const;

  // === the geometry (polyhedron_checks.cpp)
  // four vertices not in one plane (kept in tetra)
  void findTetrahedron();
  // removes zero-area triangles by flipping their longest edge into the neighbour
  void flipSlivers();
  // convex across every edge, exact; reverses a surface that is clockwise throughout
  void checkConvexEdges();

  // === faces as planes (polyhedron_planes.cpp)
  // merges adjacent coplanar triangles (exact orient3d) into plane faces, with their corner
  // loops and a fat triangle of each
  void mergePlanes();

  // === the whole (polyhedron_centre.cpp)
  // a double point strictly inside every face plane, when one exists
  void findCentre();
  // the surface wraps around its inside exactly once
  void checkWindsOnce() const;
  // the exact bounding box of the vertices
  void findBounds();

 private:
  // the triangles of each plane face, in CSR form (planeTriangles)
  void groupTrianglesByPlane(std::uint32_t planes);
  // each plane face's corner loop and its fat triangle
  void chainPlaneLoops();
  // "vertex K (x, y, z)" for vertex k, K its input index
  std::string vertexName(std::uint32_t k) const;
  // "edge A-B from (..) to (..)"
  std::string edgeName(std::uint32_t a, std::uint32_t b) const;
  // "face F" for the input face triangle t comes from
  std::string faceName(std::uint32_t t) const;
  // the source line of input vertex i, face f, triangle t (0 when the mesh has none)
  std::size_t vertexLine(std::size_t i) const;
  std::size_t faceLine(std::size_t f) const;
  std::size_t triangleLine(std::uint32_t t) const;
  // the input vertices of the edges listed by their first corner
  void blame(const std::vector<std::uint32_t>& corners) const;
  // throws for input face f, whose vertex w lies off the plane of its vertices a, b, c
  // (merged indices): not planar, by how much
  [[noreturn]] void throwNotPlanar(std::size_t f, const Triangle& plane, std::uint32_t w) const;
  // throws for input face f (merged vertex indices) when its vertices are not in one plane
  void checkPlanar(std::size_t f, const std::vector<std::uint32_t>& polygon) const;
  // throws for the first reflex edge of the minority side (sign < 0: the reflex ones)
  [[noreturn]] void throwReflex(std::uint32_t firstReflex, std::uint32_t firstConvex,
                                bool reflexIsMinority) const;
  // each vertex as seen from the centre (or the exact centroid of the tetrahedron), scaled
  // per axis so that no product in a solid angle overflows or underflows
  std::vector<Vec3> directionsFromInside() const;

  ConvexPolyhedron& out_;
  const MeshData& mesh_;
  std::vector<std::uint32_t>* suspects_;
  std::vector<std::uint8_t> used_;         // input vertex used by a face
  std::vector<std::uint32_t> id_;          // input vertex -> merged vertex
  std::size_t triangleBound_ = 0;          // triangles the fan triangulation may make
  std::uint32_t tetra_[4] = {0, 1, 0, 0};  // four vertices spanning a volume
};

}  // namespace convexloc::detail
