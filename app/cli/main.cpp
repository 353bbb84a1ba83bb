// convexloc — exact point location in convex polygons and polyhedra, from the command line.
//
// This file only parses the command line (CLI11) and maps every outcome to an exit code:
// 0 done, 1 bad input (the message names the file and line), 2 bad usage (with the usage).
// The commands live in classify.cpp, info.cpp and generate.cpp; a SHAPE ending in .off, .obj,
// .stl or .ply is a polyhedron and takes the 3D half of each. Each command is declared here by one
// small function (its subcommand, its options, the action it runs), and addCommands lists
// them in the order the help shows.
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
#include "convexloc/generate2d.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/methods.hpp"

#ifndef CONVEXLOC_VERSION
#define CONVEXLOC_VERSION "unknown"
#endif

namespace convexloc::cli {
namespace {

// "a, b or c": `text` of each value of `all`
template <class T, std::size_t N, class Text>
std::string listWithOr(const T (&all)[N], Text&& text) {
  std::string list;
  for (std::size_t i = 0; i < N; ++i)
    list.append(i == 0 ? "" : i + 1 == N ? " or " : ", ").append(text(all[i]));
  return list;
}

// "a O(N), b O(log N) or c O(1)": every method of one dimension with its cost
template <class Method, std::size_t N>
std::string methodsWithCosts(const Method (&all)[N]) {
  return listWithOr(all, [](Method m) {
    const MethodInfo& info = methodInfo(m);
    return std::string(info.name) + " " + std::string(info.cost);
  });
}

// "a, b or c": every kind a generator makes
template <class Kind, std::size_t N>
std::string kindsOf(const Kind (&all)[N]) {
  return listWithOr(all, [](Kind k) { return std::string(toString(k)); });
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
ending in .off, .obj, .stl (ASCII or binary) or .ply (ASCII or binary) is a closed convex
polyhedron in that format, faces in either orientation. With --hull the shape is the convex
hull of the file's points, in any order: a PLY point cloud without faces works too, and so
does a scan ending in .xyz or .pts ('x y z' a line, further columns read past).)";

constexpr const char* kExamples = R"(

Examples:
  convexloc classify assets/hexagon.txt assets/hexagon-points.txt
  convexloc info assets/hexagon.txt
  convexloc generate polygon --kind random --n 100 --seed 7 > polygon.txt
  convexloc generate points --shape polygon.txt --count 1000000 | convexloc classify polygon.txt -
  convexloc classify assets/cube.off assets/cube-points-3d.txt --method cubemap
  convexloc info assets/sphere-cloud.ply --hull
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

// === Commands: one small function each, declaring its subcommand and what it runs

// A subcommand being declared, and the options the command line fills for it; they live as
// long as the action that reads them.
template <class Options>
struct Declared {
  CLI::App* sub = nullptr;
  std::shared_ptr<Options> options = std::make_shared<Options>();
  // the command that runs `action(options)` when the command line names it
  template <class Action>
  Command runs(Action action) const {
    return {sub, [o = options, action] { action(*o); }};
  }
};

// declares the subcommand `name` of `parent`, with options at their defaults
template <class Options>
Declared<Options> declare(CLI::App& parent, const std::string& name,
                          const std::string& description) {
  return {parent.add_subcommand(name, description)};
}

// the action that runs the 3D half for a polyhedron SHAPE (.off/.obj/.stl/.ply), else the 2D half
template <class Options>
auto byDimension(void (*run2D)(const Options&), void (*run3D)(const Options&)) {
  return [run2D, run3D](const Options& o) { isPolyhedronPath(o.shape) ? run3D(o) : run2D(o); };
}

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
  const auto c = declare<ClassifyOptions>(
      app, "classify",
      "Print inside, boundary or outside for each point, one line per point, in order");
  c.sub
      ->add_option("SHAPE", c.options->shape,
                   "Polygon file, one vertex 'x y' per line, or a polyhedron "
                   "(.off/.obj/.stl/.ply)")
      ->required();
  c.sub
      ->add_option("POINTS", c.options->points,
                   "Points file, one point 'x y' ('x y z' for a polyhedron) per line; '-' reads "
                   "standard input")
      ->required();
  c.sub->add_option("-m,--method", c.options->method, methodHelp());
  addResolution(c.sub, c.options->resolution);
  c.sub->add_flag("--hull", c.options->hull, kHullHelp);
  c.sub->footer(kFormat);
  return c.runs(byDimension(classify2D, classify3D));
}

// convexloc info SHAPE [--method] [--resolution] [--intersect]
Command addInfo(CLI::App& app) {
  const auto c = declare<InfoOptions>(
      app, "info", "Describe the shape and the subdivision each method builds on it");
  c.sub
      ->add_option("SHAPE", c.options->shape,
                   "Polygon file ('-' reads standard input) or polyhedron (.off/.obj/.stl/.ply)")
      ->required();
  c.sub->add_option("-m,--method", c.options->method,
                    "Report one method in detail: " + methodHelp() +
                        ". Without it: a table of every method for the shape");
  addResolution(c.sub, c.options->resolution);
  c.sub->add_flag("--intersect", c.options->intersect,
                  "Report the line (polygon) or plane (polyhedron) methods of 'intersect' too, "
                  "building the polyhedron's dual (seconds per 10^5 faces); a polygon's table "
                  "shows them without it");
  c.sub->add_flag("--hull", c.options->hull, kHullHelp);
  c.sub->footer(kFormat);
  return c.runs(byDimension(info2D, info3D));
}

// declares the generator `name` of a shape: its --kind (required), --n and --seed
template <class Options, class Kind, std::size_t N>
Declared<Options> declareShapeGenerator(CLI::App& generate, const char* name,
                                        const char* description, const Kind (&kinds)[N],
                                        const char* sizeHelp) {
  auto c = declare<Options>(generate, name, description);
  c.sub->add_option("-k,--kind", c.options->kind, kindsOf(kinds))->required();
  addWholeNumber(c.sub, "-n,--n", c.options->n, sizeHelp);
  addSeed(c.sub, c.options->seed);
  return c;
}

// convexloc generate polygon --kind [--n] [--seed]
Command addGeneratePolygon(CLI::App& generate) {
  return declareShapeGenerator<GeneratePolygonOptions>(
             generate, "polygon",
             "Write the vertices of a convex polygon, one 'x y' per line, exact to the bit",
             kAllPolygonKinds, "About how many vertices (at least 3)")
      .runs(generatePolygon);
}

// convexloc generate polyhedron --kind [--n] [--seed] [--format]
Command addGeneratePolyhedron(CLI::App& generate) {
  const auto c = declareShapeGenerator<GeneratePolyhedronOptions>(
      generate, "polyhedron",
      "Write a convex polyhedron as OFF (or OBJ, PLY, STL), faces counter-clockwise seen from "
      "outside, exact to the bit",
      kAllPolyhedronKinds, "About how many triangles (at least 4; ignored by the platonic solids)");
  c.sub
      ->add_option("-f,--format", c.options->format,
                   "off, obj, ply (binary, double coordinates) or stl (ASCII; binary STL holds "
                   "only float32)")
      ->capture_default_str();
  return c.runs(generatePolyhedron);
}

// convexloc generate points --shape [--count] [--seed] [--near-boundary]
Command addGeneratePoints(CLI::App& generate) {
  const auto c = declare<GeneratePointsOptions>(
      generate, "points",
      "Write query points around a shape, one 'x y' ('x y z' for a polyhedron) per line, "
      "exact to the bit");
  c.sub
      ->add_option("--shape", c.options->shape,
                   "Polygon file or polyhedron (.off/.obj/.stl/.ply) the points are for")
      ->required();
  addWholeNumber(c.sub, "-c,--count", c.options->count, "How many points");
  addSeed(c.sub, c.options->seed);
  c.sub->add_flag("--near-boundary", c.options->nearBoundary,
                  "Hard cases: vertices, points on edges (and faces), one ulp off them "
                  "(default: uniform in the bounding box grown by 10%)");
  return c.runs(byDimension(generatePoints2D, generatePoints3D));
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
  commands.push_back(addIntersect(app));
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
