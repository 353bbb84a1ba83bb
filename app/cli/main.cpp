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
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "convexloc/error.hpp"
#include "convexloc/methods.hpp"

#ifndef CONVEXLOC_VERSION
#define CONVEXLOC_VERSION "unknown"
#endif

namespace convexloc::cli {
namespace {

// "a O(N), b O(log N) or c O(1)": every method of one dimension with its cost
template <class Method, std::size_t N>
std::string methodsWithCosts(const Method (&all)[N]) {
  std::string text;
  for (std::size_t i = 0; i < N; ++i) {
    const MethodInfo& info = methodInfo(all[i]);
    text.append(i == 0 ? "" : i + 1 == N ? " or " : ", ").append(info.name).append(" ");
    text.append(info.cost);
  }
  return text;
}

// what --method takes, for both kinds of shape
std::string methodHelp() {
  return "polygon: " + methodsWithCosts(kAllMethods2D) +
         " (default polar); polyhedron: " + methodsWithCosts(kAllMethods3D) + " (default cubemap)";
}

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

// === Commands: one small function each, registering its subcommand and what it runs

// a subcommand, and what runs when the command line names it
struct Command {
  CLI::App* sub = nullptr;
  std::function<void()> action;
};

// a whole-number option whose default the help shows; at most the largest T
template <class T>
void addWholeNumber(CLI::App* sub, const std::string& flags, T& value, const std::string& help) {
  sub->add_option(flags, value, help)
      ->check(wholeNumber(std::numeric_limits<T>::max()))
      ->capture_default_str();
}

// --seed, shared by every generator
void addSeed(CLI::App* sub, std::uint64_t& seed) {
  addWholeNumber(sub, "-s,--seed", seed, "Random seed");
}

// --resolution, shared by classify and info
void addResolution(CLI::App* sub, std::uint32_t& resolution) {
  addWholeNumber(sub, "-r,--resolution", resolution, kResolutionHelp);
}

// convexloc classify SHAPE POINTS [--method] [--resolution]
Command addClassify(CLI::App& app) {
  auto o = std::make_shared<ClassifyOptions>();
  CLI::App* sub = app.add_subcommand(
      "classify", "Print inside, boundary or outside for each point, one line per point, in order");
  sub->add_option("SHAPE", o->shape,
                  "Polygon file, one vertex 'x y' per line, or a polyhedron (.off/.obj)")
      ->required();
  sub->add_option("POINTS", o->points,
                  "Points file, one point 'x y' ('x y z' for a polyhedron) per line; '-' reads "
                  "standard input")
      ->required();
  sub->add_option("-m,--method", o->method, methodHelp());
  addResolution(sub, o->resolution);
  sub->footer(kFormat);
  return {sub, [o] { isPolyhedronPath(o->shape) ? classify3D(*o) : classify2D(*o); }};
}

// convexloc info SHAPE [--method] [--resolution]
Command addInfo(CLI::App& app) {
  auto o = std::make_shared<InfoOptions>();
  CLI::App* sub =
      app.add_subcommand("info", "Describe the shape and the subdivision each method builds on it");
  sub->add_option("SHAPE", o->shape,
                  "Polygon file ('-' reads standard input) or polyhedron (.off/.obj)")
      ->required();
  sub->add_option("-m,--method", o->method,
                  "Report one method in detail: " + methodHelp() +
                      ". Without it: a table of every method for the shape");
  addResolution(sub, o->resolution);
  sub->footer(kFormat);
  return {sub, [o] { isPolyhedronPath(o->shape) ? info3D(*o) : info2D(*o); }};
}

// convexloc generate polygon --kind [--n] [--seed]
Command addGeneratePolygon(CLI::App& generate) {
  auto o = std::make_shared<GeneratePolygonOptions>();
  CLI::App* sub = generate.add_subcommand(
      "polygon", "Write the vertices of a convex polygon, one 'x y' per line, exact to the bit");
  sub->add_option("-k,--kind", o->kind,
                  "regular, random, ellipse, sliver, tiny-edges, offset, degenerate or triangle")
      ->required();
  addWholeNumber(sub, "-n,--n", o->n, "About how many vertices (at least 3)");
  addSeed(sub, o->seed);
  return {sub, [o] { generatePolygon(*o); }};
}

// convexloc generate polyhedron --kind [--n] [--seed] [--format]
Command addGeneratePolyhedron(CLI::App& generate) {
  auto o = std::make_shared<GeneratePolyhedronOptions>();
  CLI::App* sub = generate.add_subcommand(
      "polyhedron",
      "Write a convex polyhedron as OFF (or OBJ), faces counter-clockwise seen from outside, "
      "exact to the bit");
  sub->add_option("-k,--kind", o->kind,
                  "tetrahedron, cube, octahedron, dodecahedron, icosahedron, geodesic, "
                  "sphere-hull, cube-hull, ellipsoid-hull, thin-slab, offset, tiny-faces or "
                  "coplanar")
      ->required();
  addWholeNumber(sub, "-n,--n", o->n,
                 "About how many triangles (at least 4; ignored by the platonic solids)");
  addSeed(sub, o->seed);
  sub->add_option("-f,--format", o->format, "off or obj")->capture_default_str();
  return {sub, [o] { generatePolyhedron(*o); }};
}

// convexloc generate points --shape [--count] [--seed] [--near-boundary]
Command addGeneratePoints(CLI::App& generate) {
  auto o = std::make_shared<GeneratePointsOptions>();
  CLI::App* sub = generate.add_subcommand(
      "points",
      "Write query points around a shape, one 'x y' ('x y z' for a polyhedron) per line, "
      "exact to the bit");
  sub->add_option("--shape", o->shape, "Polygon file or polyhedron (.off/.obj) the points are for")
      ->required();
  addWholeNumber(sub, "-c,--count", o->count, "How many points");
  addSeed(sub, o->seed);
  sub->add_flag("--near-boundary", o->nearBoundary,
                "Hard cases: vertices, points on edges (and faces), one ulp off them "
                "(default: uniform in the bounding box grown by 10%)");
  return {sub, [o] { isPolyhedronPath(o->shape) ? generatePoints3D(*o) : generatePoints2D(*o); }};
}

// every command, in the order the help lists them; a new command is one more line here
std::vector<Command> addCommands(CLI::App& app) {
  std::vector<Command> commands;
  commands.push_back(addClassify(app));
  commands.push_back(addInfo(app));
  CLI::App* generate =
      app.add_subcommand("generate", "Write example polygons, polyhedra and point sets");
  generate->require_subcommand(1);
  commands.push_back(addGeneratePolygon(*generate));
  commands.push_back(addGeneratePolyhedron(*generate));
  commands.push_back(addGeneratePoints(*generate));
  return commands;
}

// === Running

// parses the command line; the exit code when that ends the run (help, version, bad usage)
std::optional<int> parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
      return app.exit(e, std::cout, std::cerr);  // --help, --version
    }
    return usageError(app, e.what());
  }
  return std::nullopt;
}

// runs the command the command line named, mapping its failure to an exit code
int runNamed(const CLI::App& app, const std::vector<Command>& commands) {
  try {
    for (const Command& command : commands) {
      if (*command.sub) {
        command.action();
        break;
      }
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

// parses the command line and runs the command it names
int run(int argc, char** argv) {
  CLI::App app{"convexloc: exact point location in convex polygons and polyhedra", "convexloc"};
  app.set_version_flag("--version", "convexloc " CONVEXLOC_VERSION);
  app.require_subcommand(1);
  const std::vector<Command> commands = addCommands(app);
  // after the subcommands, which would otherwise inherit it
  app.footer(std::string(kFormat) + kExamples);
  if (const std::optional<int> code = parse(app, argc, argv)) return *code;
  return runNamed(app, commands);
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
