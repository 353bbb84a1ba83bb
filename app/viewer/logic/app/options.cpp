// convexloc-viewer — the command line, declared once on CLI11: each option's names, value,
// group, help, problem text and whether a lecture's slide may set it stand in one row of
// option_table.cpp, so that --help, the parser, its errors and the lecture keys all come from it.
#include "logic/app/options.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

#include <CLI/CLI.hpp>

#include "logic/app/option_table.hpp"
#include "logic/app/option_values.hpp"

namespace convexloc::viewer {
namespace {

// the row of an option name ("--line", "-h"), or null
const OptionSpec* specOf(std::string_view name) {
  for (const OptionSpec& s : optionTable()) {
    std::string_view names = s.names;
    while (!names.empty()) {
      const std::size_t comma = std::min(names.find(','), names.size());
      if (names.substr(0, comma) == name) return &s;
      names.remove_prefix(std::min(comma + 1, names.size()));
    }
  }
  return nullptr;
}

// what the row's option needs, as an error
std::string needsText(const OptionSpec& s) {
  std::string_view names = s.names;
  names = names.substr(names.rfind(',') == std::string_view::npos ? 0 : names.rfind(',') + 1);
  return std::string(names) + " needs " + s.needs;
}

// what the row's option needs and which of the values `v` given is wrong
std::string valueProblem(const OptionSpec& s, const Values& v) {
  if (v.empty()) return needsText(s);
  const std::string bad = badPart(v);
  return needsText(s) + (bad.starts_with("not ") ? ", " + bad : " (" + bad + ")");
}

// the problem an option's values raise, thrown out of CLI11's parse
struct OptionProblem {
  std::string message;
};

// --help's usage line and the shape argument, which CLI11 does not declare
class ViewerHelp : public CLI::Formatter {
 public:
  std::string make_usage(const CLI::App*, std::string) const override {
    return "Usage: convexloc-viewer [SHAPE] [options]\n\n"
           "  SHAPE                 a polygon (.txt, one vertex 'x y' per line) or a polyhedron\n"
           "                        (.off, .obj, .stl, .ply; a PLY point cloud shows its convex\n"
           "                        hull); without one, a random polygon with the paper's polar\n"
           "                        slabs\n";
  }
  // the option's line of help broken at spaces into lines of at most 64 characters (CLI11
  // indents each under the first)
  std::string make_option_desc(const CLI::Option* opt) const override {
    std::string out, line;
    std::istringstream words(opt->get_description());
    for (std::string w; words >> w;) {
      if (!line.empty() && line.size() + 1 + w.size() > 64) {
        out += line + "\n";
        line.clear();
      }
      line += (line.empty() ? "" : " ") + w;
    }
    return out + line;
  }
};

// every row of the option table on `app`, writing into `o`, each taking effect where it stands on
// the command line (so a later option overrides an earlier one, or a figure's)
void declare(CLI::App& app, Options& o) {
  app.set_help_flag();
  app.allow_extras();
  app.formatter(std::make_shared<ViewerHelp>());
  app.get_formatter()->column_width(24);
  for (const OptionSpec& s : optionTable()) {
    const auto run = [&o, &s](const Values& v) {
      std::string why;
      if (!s.apply(v, o, why)) throw OptionProblem{why.empty() ? valueProblem(s, v) : why};
      return true;
    };
    CLI::Option* opt = nullptr;
    if (s.count == 0) {
      opt = app.add_flag_callback(
          s.names, [run] { run({}); }, s.help);
    } else {
      opt = app.add_option(s.names, run, s.help)->type_size(s.count)->expected(1);
      opt->type_name(s.value);
    }
    opt->group(s.group)->trigger_on_parse();
  }
}

// an unknown option, or the shape file (only one), from what CLI11 left over
std::string leftOver(const std::vector<std::string>& rest, Options& o) {
  for (const std::string& a : rest) {
    if (!a.empty() && a[0] == '-' && a != "-") return "unknown option " + a + " (see --help)";
    if (!o.shape.empty()) return "more than one shape given: " + o.shape + " and " + a;
    o.shape = a;
  }
  return {};
}

// options that exclude each other
std::string conflicts(const Options& o) {
  if (!o.shape.empty() && (o.preset || o.generate))
    return "give a shape file, --preset or --generate, not several";
  if (o.preset && o.generate) return "give --preset or --generate, not both";
  if (!o.exportDir.empty() && o.lecture.empty() && !o.figure)
    return "--export needs --lecture FILE or --figure N";
  if (o.exportFirst && o.exportDir.empty()) return "--export-first needs --export DIR";
  if (o.showUi && (o.hideUi || o.present))
    return "--show-ui shows the panels: give it or --hide-ui / --present, not both";
  return {};
}

}  // namespace

std::string parseInto(std::span<const std::string_view> args, Options& o) {
  CLI::App app;
  declare(app, o);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 reads from the back
  try {
    app.parse(reversed);
  } catch (const OptionProblem& p) {
    return p.message;
  } catch (const CLI::ArgumentMismatch& e) {
    // too few values: the option's name heads CLI11's message
    const std::string what = e.what();
    const OptionSpec* s = specOf(what.substr(0, what.find(':')));
    return s ? needsText(*s) : what;
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  return leftOver(app.remaining(), o);
}

ParsedOptions parseOptions(std::span<const std::string_view> args) {
  ParsedOptions r;
  r.error = parseInto(args, r.options);
  if (r.error.empty()) r.error = conflicts(r.options);
  return r;
}

bool setsTheRun(std::string_view key) {
  const OptionSpec* s = specOf("--" + std::string(key));
  return s && s->run;
}

std::string usageText() {
  Options o;
  CLI::App app("convexloc-viewer: see how point location in a convex polygon or polyhedron works",
               "convexloc-viewer");
  declare(app, o);
  app.footer(
      "Mouse: drag to pan (3D: orbit; right drag pans), wheel to zoom at the cursor, click to\n"
      "place a point (3D: on the slicing plane; Shift-click pins the cell under the cursor),\n"
      "drag a vertex handle to edit the polygon; in the Lines mode (L) a drag places a line.\n"
      "In the 3D Planes mode (L) the panel's sliders move the plane.\n"
      "Keys: F fit, H hide panels, T theme (dark/light), 1..5 method, L lines mode (3D: planes\n"
      "mode), Space new spray, Esc clear the point, F12 screenshot, V (or Shift+F12) SVG, P\n"
      "presentation mode, G legend, Left/Right previous/next step of the placed point's query, R\n"
      "the radius filter on/off (paper-faithful mode); in a lecture PageDown / PageUp next and\n"
      "previous slide, Home / End first and last, B (or .) blank screen, N speaker notes, D\n"
      "dismiss a slide's problems. Every key press counts once, in order.");
  return app.help();
}

}  // namespace convexloc::viewer
