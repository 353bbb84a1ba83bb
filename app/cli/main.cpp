// convexloc — exact point location in convex polygons and polyhedra, from the command line.
//
// This file only parses the command line (CLI11) and maps every outcome to an exit code:
// 0 done, 1 bad input (the message names the file and line), 2 bad usage (with the usage).
// The commands live in classify.cpp, info.cpp and generate.cpp; a SHAPE ending in .off or
// .obj is a polyhedron and takes the 3D half of each.
#include <CLI/CLI.hpp>

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <new>
#include <string>

#include "commands.hpp"
#include "convexloc/error.hpp"

#ifndef CONVEXLOC_VERSION
#define CONVEXLOC_VERSION "unknown"
#endif

namespace convexloc::cli {
namespace {

constexpr const char* kMethodHelp =
    "polygon: halfplane O(N), wedge O(log N), slab O(log N), uniform O(1) or polar O(1) "
    "(default polar); polyhedron: halfspace O(F), walk O(sqrt F) or cubemap O(1) (default "
    "cubemap)";

constexpr const char* kResolutionHelp =
    "uniform: slab count; polar: slabs per octant; cubemap: grid cells per side of each cube "
    "face (0: chosen from the shape)";

constexpr const char* kFormat = R"(
Files are text: one point 'x y' (polygon) or 'x y z' (polyhedron) per line, numbers
separated by spaces and/or a comma, '#' starts a comment, blank lines are skipped. A
polygon file lists the vertices of a convex polygon in either order around it. A SHAPE
ending in .off or .obj is a closed convex polyhedron in that format, faces in either
orientation.)";

constexpr const char* kExamples = R"(

Examples:
  convexloc classify assets/hexagon.txt assets/hexagon-points.txt
  convexloc info assets/hexagon.txt
  convexloc generate polygon --kind random --n 100 --seed 7 > polygon.txt
  convexloc generate points --shape polygon.txt --count 1000000 | convexloc classify polygon.txt -
  convexloc classify assets/cube.off assets/cube-points-3d.txt --method cubemap
  convexloc generate polyhedron --kind geodesic --n 100000 > sphere.off
  convexloc info sphere.off

Exit status: 0 done, 1 bad input, 2 bad usage.)";

// a check for a count, a seed or a resolution: digits only, at most `max` (CLI11 alone wraps
// "-3" around and saturates values past 2^64)
CLI::Validator wholeNumber(std::uint64_t max) {
  return CLI::Validator(
      [max](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        auto [stop, ec] = std::from_chars(text.data(), end, value);
        if (text.empty() || ec != std::errc{} || stop != end || value > max)
          return "expected a whole number from 0 to " + std::to_string(max) + ", got '" + text +
                 "'";
        return {};
      },
      "", "whole number");
}

// the subcommand the command line reached, and its full name ("convexloc generate points")
const CLI::App& reached(const CLI::App& app, std::string& name) {
  const CLI::App* at = &app;
  name = app.get_name();
  while (!at->get_subcommands().empty()) {
    at = at->get_subcommands().front();
    name += ' ' + at->get_name();
  }
  return *at;
}

// bad usage: the message, the usage line and where to read more, on stderr
int usageError(const CLI::App& app, const std::string& message) {
  std::string name;
  const CLI::App& sub = reached(app, name);
  auto formatter = std::dynamic_pointer_cast<CLI::Formatter>(sub.get_formatter());
  std::cerr << "convexloc: " << message << '\n'
            << (formatter ? formatter->make_usage(&sub, name) : "Usage: " + name + '\n') << "Run '"
            << name << " --help' for more information.\n"
            << std::flush;
  return kExitBadUsage;
}

// parses the command line and runs the command it names
int run(int argc, char** argv) {
  CLI::App app{"convexloc: exact point location in convex polygons and polyhedra", "convexloc"};
  const CLI::Validator anyCount = wholeNumber(UINT64_MAX);
  const CLI::Validator resolution = wholeNumber(UINT32_MAX);
  app.set_version_flag("--version", "convexloc " CONVEXLOC_VERSION);
  app.require_subcommand(1);

  ClassifyOptions classifyOptions;
  CLI::App* classify = app.add_subcommand(
      "classify", "Print inside, boundary or outside for each point, one line per point, in order");
  classify
      ->add_option("SHAPE", classifyOptions.shape,
                   "Polygon file, one vertex 'x y' per line, or a polyhedron (.off/.obj)")
      ->required();
  classify
      ->add_option("POINTS", classifyOptions.points,
                   "Points file, one point 'x y' ('x y z' for a polyhedron) per line; '-' reads "
                   "standard input")
      ->required();
  classify->add_option("-m,--method", classifyOptions.method, kMethodHelp);
  classify->add_option("-r,--resolution", classifyOptions.resolution, kResolutionHelp)
      ->check(resolution)
      ->capture_default_str();

  InfoOptions infoOptions;
  CLI::App* info =
      app.add_subcommand("info", "Describe the shape and the subdivision each method builds on it");
  info->add_option("SHAPE", infoOptions.shape,
                   "Polygon file ('-' reads standard input) or polyhedron (.off/.obj)")
      ->required();
  info->add_option("-m,--method", infoOptions.method,
                   std::string("Report one method in detail: ") + kMethodHelp +
                       ". Without it: a table of every method for the shape");
  info->add_option("-r,--resolution", infoOptions.resolution, kResolutionHelp)
      ->check(resolution)
      ->capture_default_str();

  CLI::App* generate =
      app.add_subcommand("generate", "Write example polygons, polyhedra and point sets");
  generate->require_subcommand(1);
  GeneratePolygonOptions polygonOptions;
  CLI::App* genPolygon = generate->add_subcommand(
      "polygon", "Write the vertices of a convex polygon, one 'x y' per line, exact to the bit");
  genPolygon
      ->add_option("-k,--kind", polygonOptions.kind,
                   "regular, random, ellipse, sliver, tiny-edges, offset, degenerate or triangle")
      ->required();
  genPolygon->add_option("-n,--n", polygonOptions.n, "About how many vertices (at least 3)")
      ->check(anyCount)
      ->capture_default_str();
  genPolygon->add_option("-s,--seed", polygonOptions.seed, "Random seed")
      ->check(anyCount)
      ->capture_default_str();

  GeneratePolyhedronOptions polyhedronOptions;
  CLI::App* genPolyhedron = generate->add_subcommand(
      "polyhedron",
      "Write a convex polyhedron as OFF (or OBJ), faces counter-clockwise seen from outside, "
      "exact to the bit");
  genPolyhedron
      ->add_option("-k,--kind", polyhedronOptions.kind,
                   "tetrahedron, cube, octahedron, dodecahedron, icosahedron, geodesic, "
                   "sphere-hull, cube-hull, ellipsoid-hull, thin-slab, offset, tiny-faces or "
                   "coplanar")
      ->required();
  genPolyhedron
      ->add_option("-n,--n", polyhedronOptions.n,
                   "About how many triangles (at least 4; ignored by the platonic solids)")
      ->check(anyCount)
      ->capture_default_str();
  genPolyhedron->add_option("-s,--seed", polyhedronOptions.seed, "Random seed")
      ->check(anyCount)
      ->capture_default_str();
  genPolyhedron->add_option("-f,--format", polyhedronOptions.format, "off or obj")
      ->capture_default_str();

  GeneratePointsOptions pointsOptions;
  CLI::App* genPoints = generate->add_subcommand(
      "points",
      "Write query points around a shape, one 'x y' ('x y z' for a polyhedron) per line, "
      "exact to the bit");
  genPoints
      ->add_option("--shape", pointsOptions.shape,
                   "Polygon file or polyhedron (.off/.obj) the points are for")
      ->required();
  genPoints->add_option("-c,--count", pointsOptions.count, "How many points")
      ->check(anyCount)
      ->capture_default_str();
  genPoints->add_option("-s,--seed", pointsOptions.seed, "Random seed")
      ->check(anyCount)
      ->capture_default_str();
  genPoints->add_flag("--near-boundary", pointsOptions.nearBoundary,
                      "Hard cases: vertices, points on edges (and faces), one ulp off them "
                      "(default: uniform in the bounding box grown by 10%)");

  const IntersectCommand intersect = addIntersect(app);

  // after the subcommands, which would otherwise inherit it
  app.footer(std::string(kFormat) + kExamples);
  classify->footer(kFormat);
  info->footer(kFormat);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
      return app.exit(e, std::cout, std::cerr);  // --help, --version
    }
    return usageError(app, e.what());
  }

  try {
    if (*classify) {
      if (isPolyhedronPath(classifyOptions.shape))
        classify3D(classifyOptions);
      else
        classify2D(classifyOptions);
    } else if (*info) {
      if (isPolyhedronPath(infoOptions.shape))
        info3D(infoOptions);
      else
        info2D(infoOptions);
    } else if (*genPolygon) {
      generatePolygon(polygonOptions);
    } else if (*genPolyhedron) {
      generatePolyhedron(polyhedronOptions);
    } else if (*intersect.sub) {
      intersect.run();
    } else if (*genPoints) {
      if (isPolyhedronPath(pointsOptions.shape))
        generatePoints3D(pointsOptions);
      else
        generatePoints2D(pointsOptions);
    }
  } catch (const Failure& f) {
    if (f.isUsage()) return usageError(app, f.what());
    std::cerr << f.what() << '\n' << std::flush;
    return f.code();
  } catch (const convexloc::UsageError& e) {
    return usageError(app, e.what());
  }
  return kExitOk;
}

}  // namespace
}  // namespace convexloc::cli

int main(int argc, char** argv) {
  try {
    return convexloc::cli::run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fputs("convexloc: out of memory\n", stderr);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "convexloc: %s\n", e.what());
  } catch (...) {
    std::fputs("convexloc: unexpected error\n", stderr);
  }
  return convexloc::cli::kExitBadInput;
}
