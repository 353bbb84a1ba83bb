// The SVG writer: well-formed XML, one cell polygon per core cell and one edge line per
// polygon edge, labels escaped, a heavy spray thinned and said so, 3D back to front.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "logic/app/legend.hpp"
#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "logic/draw/structure2d.hpp"
#include "logic/scene/scene2d.hpp"
#include "logic/view/camera2d.hpp"
#include "writers/svg_writer.hpp"

namespace cv = convexloc::viewer;
using convexloc::Location;
using convexloc::Method2D;
using convexloc::Vec2;

namespace {

// Checks that `xml` is well-formed (one root, tags nested and closed, attributes quoted,
// no raw '<' or stray '&' in text or values) and counts elements by "tag" and
// "tag.class". Returns an empty string, or the first problem.
std::string checkXml(const std::string& xml, std::map<std::string, int>& counts) {
  std::vector<std::string> open;
  int roots = 0;
  auto entityOk = [&](std::size_t amp) {
    const std::size_t semi = xml.find(';', amp);
    if (semi == std::string::npos) return false;
    const std::string e = xml.substr(amp + 1, semi - amp - 1);
    return e == "amp" || e == "lt" || e == "gt" || e == "quot" || e == "apos" ||
           (!e.empty() && e[0] == '#');
  };
  std::size_t i = 0;
  while (i < xml.size()) {
    if (xml[i] != '<') {
      if (xml[i] == '&' && !entityOk(i)) return "stray & at " + std::to_string(i);
      if (xml[i] == '>') return "raw > in text at " + std::to_string(i);
      if (!std::isspace(static_cast<unsigned char>(xml[i])) && open.empty())
        return "text outside the root";
      ++i;
      continue;
    }
    if (xml.compare(i, 4, "<!--") == 0) {
      const std::size_t end = xml.find("-->", i + 4);
      if (end == std::string::npos) return "unclosed comment";
      if (xml.substr(i + 4, end - i - 4).find("--") != std::string::npos) return "-- in comment";
      i = end + 3;
      continue;
    }
    if (xml.compare(i, 2, "<?") == 0) {
      i = xml.find("?>", i);
      if (i == std::string::npos) return "unclosed declaration";
      i += 2;
      continue;
    }
    // a tag: attributes' values may not hold '<' and hold '&' only as entities
    std::size_t j = i + 1;
    bool inValue = false;
    for (; j < xml.size() && (inValue || xml[j] != '>'); ++j) {
      if (xml[j] == '"') inValue = !inValue;
      if (inValue && xml[j] == '<') return "< in an attribute at " + std::to_string(j);
      if (inValue && xml[j] == '&' && !entityOk(j)) return "stray & in an attribute";
    }
    if (j >= xml.size()) return "unclosed tag";
    std::string tag = xml.substr(i + 1, j - i - 1);
    i = j + 1;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1))
        return "mismatched </" + tag.substr(1) + ">";
      open.pop_back();
      continue;
    }
    const bool empty = tag.back() == '/';
    const std::string name = tag.substr(0, tag.find_first_of(" /\n"));
    ++counts[name];
    const std::size_t cls = tag.find(" class=\"");
    if (cls != std::string::npos)
      ++counts[name + "." + tag.substr(cls + 8, tag.find('"', cls + 8) - cls - 8)];
    if (open.empty() && ++roots > 1) return "two roots";
    if (!empty) open.push_back(name);
  }
  return open.empty() && roots == 1 ? "" : "unclosed elements or no root";
}

// the SVG's text as read: a line's words are tspans, each placed where the window draws it
std::string withoutTspans(const std::string& svg) {
  std::string out;
  std::size_t at = 0;
  while (at < svg.size()) {
    const std::size_t tag = svg.find("tspan", at);
    if (tag == std::string::npos || tag == 0) break;
    const bool opening = svg[tag - 1] == '<';
    const bool closing = tag >= 2 && svg.compare(tag - 2, 2, "</") == 0;
    const std::size_t end = svg.find('>', tag);
    if ((!opening && !closing) || end == std::string::npos) {
      out.append(svg, at, tag + 5 - at);
      at = tag + 5;
      continue;
    }
    out.append(svg, at, tag - (opening ? 1 : 2) - at);
    at = end + 1;
  }
  out.append(svg, at, std::string::npos);
  return out;
}

// a scene's SVG as the viewer writes it: its draw lists, a fitted camera, a fixed measure

std::string svgOf(const cv::Scene2D& scene, cv::DrawList& structure, cv::DrawList& overlay,
                  std::size_t maxPoints = 4000) {
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Light);
  cv::View2DOptions opt;
  cv::buildStructure2D(scene, pal, opt, structure);
  cv::buildOverlay2D(scene, pal, opt, overlay);
  cv::Camera2D cam;
  cam.setViewport({800.0, 600.0});
  cam.fit(scene.polygon().bounds(), {{0.0, 0.0}, {800.0, 600.0}});
  cv::SvgScene s;
  s.size = {800.0, 600.0};
  s.background = pal.background;
  s.text = pal.text;
  s.project = [cam](glm::dvec3 p) -> std::optional<glm::dvec3> {
    return glm::dvec3(cam.toScreen({p.x, p.y}), 0.0);
  };
  s.measure = [](std::string_view t) { return glm::dvec2(7.0 * t.size(), 14.0); };
  s.base = {&structure};
  s.overlay = {&overlay};
  for (Vec2 p : scene.points()) s.points.points.push_back({p.x, p.y, 0.0});
  s.points.classes = scene.classes();
  s.maxPoints = maxPoints;
  for (const convexloc::Cell2D& c : scene.cells()) {
    auto& o = s.cells.emplace_back();
    for (Vec2 v : c.outline) o.push_back({v.x, v.y, 0.0});
  }
  const convexloc::ConvexPolygon& poly = scene.polygon();
  for (std::size_t e = 0; e < poly.size(); ++e)
    s.edges.push_back({cv::at2(cv::toGlm(poly.edgeStart(e))), cv::at2(cv::toGlm(poly.edgeEnd(e)))});
  s.layout.caption.lines = {"Fig. 3 <polar slabs> & \"x_T\""};  // escaped where written
  s.layout.caption.box = {{100.0, 500.0}, {700.0, 580.0}};
  return cv::sceneSvg(s);
}

}  // namespace

TEST(Svg, WellFormedWithOneCellPolygonPerCellAndOneLinePerEdge) {
  for (Method2D m : {Method2D::Polar, Method2D::Slab, Method2D::Wedge}) {
    cv::Scene2D scene;
    const std::vector<Vec2> octagon =
        convexloc::generatePolygon(convexloc::PolygonKind::Regular, 8, 1);
    ASSERT_TRUE(scene.setShape(octagon, "octagon"));
    scene.setMethod(m);
    scene.place({0.1, 0.2});
    cv::DrawList structure, overlay;
    const std::string svg = svgOf(scene, structure, overlay);
    std::map<std::string, int> counts;
    ASSERT_EQ(checkXml(svg, counts), "") << svg.substr(0, 400);
    EXPECT_EQ(counts["svg"], 1);
    EXPECT_EQ(counts["polygon.cell"], static_cast<int>(scene.cells().size()));
    EXPECT_EQ(counts["line.edge"], 8);
    EXPECT_NE(svg.find("viewBox=\"0 0 800.00 600.00\""), std::string::npos);
    // the segments and labels of the draw lists are all there (none is off screen here)
    EXPECT_EQ(counts["line"] - counts["line.edge"],
              static_cast<int>(structure.segments.size() + overlay.segments.size()));
    EXPECT_GT(counts["text.label"], 8);  // vertex numbers at least
  }
}

TEST(Svg, TextIsEscaped) {
  cv::Scene2D scene;
  cv::DrawList structure, overlay;
  const std::string svg = withoutTspans(svgOf(scene, structure, overlay));
  EXPECT_NE(svg.find("Fig. 3 &lt;polar slabs&gt; &amp; &quot;x_T&quot;"), std::string::npos);
  EXPECT_EQ(svg.find("<polar slabs>"), std::string::npos);
  EXPECT_EQ(cv::xmlEscape("a<b&c>'\""), "a&lt;b&amp;c&gt;&apos;&quot;");
}

TEST(Svg, AHeavySprayIsThinnedAndSaysSo) {
  cv::Scene2D scene;
  scene.spray({20000, 3, false});
  cv::DrawList structure, overlay;
  const std::string svg = svgOf(scene, structure, overlay, 4000);
  std::map<std::string, int> counts;
  ASSERT_EQ(checkXml(svg, counts), "");
  EXPECT_LE(counts["circle"], 4000 + 64);  // the points, and a few markers
  EXPECT_GE(counts["circle"], 2000);
  EXPECT_NE(svg.find("<!-- spray thinned for the SVG: 1 point in 5 of 20 000 drawn -->"),
            std::string::npos);
  EXPECT_EQ(counts["text.note"], 1);
  // a light spray is written whole, without a note
  scene.spray({1000, 3, false});
  const std::string light = svgOf(scene, structure, overlay, 4000);
  EXPECT_EQ(light.find("thinned"), std::string::npos);
}

TEST(Svg, ThreeDimensionalFillsAreWrittenBackToFront) {
  cv::DrawList mesh;
  const cv::Rgba near = cv::hex(0x00ff00), far = cv::hex(0xff0000);
  // the near triangle first in the list: the writer must still write the far one first
  mesh.triangle({0, 0, 1}, {1, 0, 1}, {0, 1, 1}, near);
  mesh.triangle({0, 0, 5}, {1, 0, 5}, {0, 1, 5}, far);
  cv::SvgScene s;
  s.size = {100.0, 100.0};
  s.depthSorted = true;
  s.project = [](glm::dvec3 p) -> std::optional<glm::dvec3> {
    return glm::dvec3(50.0 + 10.0 * p.x, 50.0 - 10.0 * p.y, p.z);  // depth: z
  };
  s.measure = [](std::string_view t) { return glm::dvec2(7.0 * t.size(), 14.0); };
  s.base = {&mesh};
  const std::string svg = cv::sceneSvg(s);
  const std::size_t farAt = svg.find("fill=\"#ff0000\""), nearAt = svg.find("fill=\"#00ff00\"");
  ASSERT_NE(farAt, std::string::npos);
  ASSERT_NE(nearAt, std::string::npos);
  EXPECT_LT(farAt, nearAt);
  std::map<std::string, int> counts;
  EXPECT_EQ(checkXml(svg, counts), "");
  EXPECT_EQ(counts["polygon"], 2);
}

TEST(Options, PresentationAndVectorFigureFlags) {
  const std::vector<std::string_view> args{
      "--present", "--caption",    "Fig. 3 & <4>", "--no-legend",  "--svg",
      "out.svg",   "--screenshot", "out.png",      "--font-scale", "2"};
  const cv::ParsedOptions parsed = cv::parseOptions(args);
  ASSERT_EQ(parsed.error, "");
  EXPECT_TRUE(parsed.options.present);
  EXPECT_TRUE(parsed.options.noLegend);
  EXPECT_EQ(parsed.options.caption, "Fig. 3 & <4>");
  EXPECT_EQ(parsed.options.svg, "out.svg");
  EXPECT_EQ(parsed.options.screenshot, "out.png");
  // the model takes them: panels hidden, the legend off, the caption, lines scaled with text
  cv::Model model;
  EXPECT_EQ(model.apply(parsed.options), "");
  EXPECT_TRUE(model.settings.present);
  EXPECT_FALSE(model.settings.showUi);
  EXPECT_FALSE(model.settings.showLegend);
  EXPECT_EQ(model.settings.caption, "Fig. 3 & <4>");
  EXPECT_FLOAT_EQ(model.settings.drawScale(), 2.0f);
  for (const char* bad : {"--svg", "--caption"}) {
    const std::vector<std::string_view> one{bad};
    EXPECT_FALSE(cv::parseOptions(one).error.empty()) << bad;
  }
}

namespace {

// true when a row of the legend says `text`
bool lists(const cv::Legend& g, const std::string& text) {
  for (const cv::LegendRow& r : g.rows)
    if (r.text.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(Legend, ListsOnlyWhatIsDrawn) {
  cv::Model model;
  // polar cells of the default polygon list 2 edges at times: tinted, and listed
  ASSERT_EQ(model.scene2d.method(), Method2D::Polar);
  EXPECT_TRUE(lists(cv::legendOf(model), "cell listing 2+ edges"));
  EXPECT_TRUE(lists(cv::legendOf(model), "octant lines"));
  // a slab lists exactly its two edges: nothing is tinted, and no row says so
  model.scene2d.setMethod(Method2D::Slab);
  const cv::Legend slab = cv::legendOf(model);
  EXPECT_FALSE(lists(slab, "cell listing"));
  EXPECT_FALSE(lists(slab, "octant"));
  EXPECT_EQ(slab.title, "slab");
  ASSERT_EQ(slab.classes.size(), 3u);
  EXPECT_EQ(slab.classes[0].text, "inside");
  EXPECT_FALSE(slab.classes[0].count.empty());
  // 3D: the section's row only while the plane cuts the polyhedron
  model.show(cv::Dim::Three);
  EXPECT_TRUE(lists(cv::legendOf(model), "section"));
  model.scene3d().setSlice({2, -30.0});
  EXPECT_FALSE(lists(cv::legendOf(model), "section"));
}

// the SVG writes the slide layout's caption lines (the window's caption box draws the same
// layout), each within the box, none losing a word; the title card and Steps window too
TEST(Svg, TheSlideLayoutsBoxesAreWrittenWithEveryLine) {
  cv::SvgScene s;
  s.size = {400.0, 300.0};
  s.fontPixels = 10.0;
  s.project = [](glm::dvec3 p) -> std::optional<glm::dvec3> { return p; };
  s.measure = [](std::string_view t) { return glm::dvec2(7.0 * t.size(), 14.0); };
  cv::SlideContent c;
  c.area = {{0.0, 0.0}, s.size};
  c.title = "3 / 9: a <title> & more";
  c.caption = "a slide caption long enough to need several lines at this width, -0.2791048542";
  cv::StepsContent steps;
  steps.model.title = "polar: point (0.1,0.2)";
  steps.model.code = {"octant from signs", "slab from the ratio"};
  steps.model.steps = {{"octant 3", 0}, {"slab 2", 1}};
  steps.step = 1;
  steps.controls = false;
  c.steps = steps;
  cv::SlideMetrics m;
  m.font = 14.0;
  m.measure = s.measure;
  s.layout = cv::layoutSlide(c, m);
  const std::string svg = withoutTspans(cv::sceneSvg(s));
  std::map<std::string, int> counts;
  ASSERT_EQ(checkXml(cv::sceneSvg(s), counts), "");
  const std::vector<std::string>& lines = s.layout.caption.lines;
  ASSERT_GT(lines.size(), 2u);
  std::string joined;
  std::size_t at = 0;
  for (const std::string& line : lines) {
    EXPECT_LE(1.5 * s.measure(line).x, 0.9 * 400.0) << line;
    at = svg.find(">" + line + "</text>", at);
    ASSERT_NE(at, std::string::npos) << line;
    joined += (joined.empty() ? "" : " ") + line;
  }
  EXPECT_EQ(joined, c.caption);
  EXPECT_NE(svg.find("&lt;title&gt; &amp; more</text>"), std::string::npos);
  EXPECT_NE(svg.find(">2. slab 2</text>"), std::string::npos);
  EXPECT_NE(svg.find(">&gt; slab from the ratio</text>"), std::string::npos);
  for (const char* box : {"title", "caption", "steps"})
    EXPECT_NE(svg.find("<g id=\"" + std::string(box) + "\""), std::string::npos) << box;
}

TEST(Svg, TheLegendIsWrittenWithItsRows) {
  cv::Model model;
  cv::SvgScene s;
  s.size = {400.0, 300.0};
  s.project = [](glm::dvec3 p) -> std::optional<glm::dvec3> { return p; };
  s.measure = [](std::string_view t) { return glm::dvec2(7.0 * t.size(), 14.0); };
  s.legend = cv::legendOf(model);
  s.legendCorner = {390.0, 290.0};
  const std::string svg = cv::sceneSvg(s);
  std::map<std::string, int> counts;
  ASSERT_EQ(checkXml(svg, counts), "");
  EXPECT_NE(svg.find("<g id=\"legend\""), std::string::npos);
  EXPECT_NE(svg.find(">octant lines through x_T</text>"), std::string::npos);
  EXPECT_NE(svg.find(">inside</text>"), std::string::npos);
}

// ImGui draws a line from its top left floored, the baseline its ascent below (0.928 em,
// floored up a pixel), each glyph at the advance before it: the SVG gives the baseline and
// places each word (a hyphened word's parts) there, so that its reader's spacing cannot drift
TEST(Svg, TextIsPlacedWhereTheWindowDrawsIt) {
  cv::SvgScene s;
  s.size = {800.0, 600.0};
  s.project = [](glm::dvec3 p) -> std::optional<glm::dvec3> { return p; };
  s.measure = [](std::string_view t) { return glm::dvec2(7.0 * t.size(), 14.0); };
  s.fontPixels = 12.0;  // the ascent: floor(11.1 + 1) = 12
  s.layout.caption.lines = {"ab cd-ef"};
  s.layout.caption.box = {{100.5, 500.0}, {700.0, 580.0}};
  s.layout.caption.padding = 10.0;
  const std::string svg = cv::sceneSvg(s);
  EXPECT_NE(svg.find("y=\"522.00\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("<tspan x=\"110.00\">ab</tspan> <tspan x=\"131.00\">cd-</tspan>"
                     "<tspan x=\"152.00\">ef</tspan>"),
            std::string::npos)
      << svg;
  EXPECT_EQ(svg.find("dominant-baseline"), std::string::npos);
}

// a near-boundary spray hugs the edges: its points are written over the lines (as the window
// draws them), where the lines would hide them; otherwise only the boundary points are
TEST(Svg, PointsHuggingTheEdgesAreWrittenOverTheLines) {
  cv::SvgScene s;
  s.size = {100.0, 100.0};
  s.project = [](glm::dvec3 p) -> std::optional<glm::dvec3> { return p; };
  cv::DrawList lines;
  lines.segment({10.0, 50.0, 0.0}, {90.0, 50.0, 0.0}, {}, 3.0f);
  s.base = {&lines};
  const std::vector<convexloc::Location> classes = {convexloc::Location::Inside};
  s.points.points = {{50.0, 50.0, 0.0}};
  s.points.classes = classes;
  for (const bool over : {false, true}) {
    s.points.overLines = over;
    const std::string svg = cv::sceneSvg(s);
    const std::size_t line = svg.find("<line x1=\"10.00\""), point = svg.find("<circle");
    ASSERT_NE(line, std::string::npos);
    ASSERT_NE(point, std::string::npos);
    EXPECT_EQ(point > line, over);
  }
}
