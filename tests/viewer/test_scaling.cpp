// Why O(1): the measurement worker, the log-log layout and its SVG.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "logic/teach/log_plot.hpp"
#include "logic/teach/scaling.hpp"
#include "logic/teach/scaling_record.hpp"

namespace cv = convexloc::viewer;
using convexloc::Method2D;

namespace {

// a small measurement, run to its end
cv::ScalingProgress measureSmall(std::size_t most) {
  cv::ScalingWorker worker;
  cv::ScalingConfig c;
  c.sizes = cv::scalingSizes(most);
  c.tracedPoints = 200;
  c.timedPoints = 2048;
  c.minSeconds = 0.001;
  worker.start(c);
  worker.wait();
  return worker.snapshot();
}

const cv::ScalingSeries& seriesOf(const cv::ScalingResult& r, Method2D m) {
  return *std::find_if(r.series.begin(), r.series.end(),
                       [m](const cv::ScalingSeries& s) { return s.method == m; });
}

// A well-formedness check small enough to read: every tag closes in order, attribute
// values are quoted, and text holds no raw '<' and only known entities.
bool wellFormed(const std::string& xml, std::string& why) {
  std::vector<std::string> open;
  std::size_t i = 0;
  while (i < xml.size()) {
    if (xml[i] == '&') {
      const std::size_t semi = xml.find(';', i);
      const std::string e = semi == std::string::npos ? "" : xml.substr(i, semi - i + 1);
      if (e != "&amp;" && e != "&lt;" && e != "&gt;" && e != "&quot;" && e != "&apos;")
        return why = "bad entity at " + std::to_string(i), false;
      i = semi + 1;
      continue;
    }
    if (xml[i] != '<') {
      if (xml[i] == '>') return why = "raw > at " + std::to_string(i), false;
      ++i;
      continue;
    }
    const std::size_t end = xml.find('>', i);
    if (end == std::string::npos) return why = "unclosed tag", false;
    std::string tag = xml.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag.front() == '?') continue;
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) return why = "odd quotes: " + tag, false;
    if (tag.front() == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return why = "mismatched </" + tag, false;
      open.pop_back();
      continue;
    }
    const bool selfClosing = tag.back() == '/';
    const std::string name = tag.substr(0, tag.find_first_of(" /"));
    if (!selfClosing) open.push_back(name);
  }
  if (!open.empty()) return why = "unclosed <" + open.back() + ">", false;
  return true;
}

std::size_t countOf(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(Scaling, SizesGrowByEightUpToTheLargest) {
  EXPECT_EQ(cv::scalingSizes(4096), (std::vector<std::size_t>{8, 64, 512, 4096}));
  const std::vector<std::size_t> full = cv::scalingSizes(1000000);
  EXPECT_EQ(full.back(), 1000000u);
  EXPECT_TRUE(std::is_sorted(full.begin(), full.end()));
}

TEST(Scaling, WorkerOnTinySizesFinishesWithMonotoneN) {
  const cv::ScalingProgress p = measureSmall(512);
  EXPECT_TRUE(p.finished);
  EXPECT_FALSE(p.running);
  EXPECT_EQ(p.done, p.total);
  ASSERT_EQ(p.result.series.size(), std::size(convexloc::kAllMethods2D));
  for (const cv::ScalingSeries& s : p.result.series) {
    ASSERT_EQ(s.samples.size(), 3u) << toString(s.method);
    for (std::size_t i = 1; i < s.samples.size(); ++i)
      EXPECT_GT(s.samples[i].n, s.samples[i - 1].n);
    for (const cv::ScalingSample& x : s.samples) EXPECT_GT(x.nsPerQuery, 0.0);
  }
  EXPECT_EQ(p.result.memory.size(), 9u);
}

TEST(Scaling, PolarStaysBoundedWhileHalfplaneGrowsWithN) {
  const cv::ScalingProgress p = measureSmall(4096);
  const auto& half = seriesOf(p.result, Method2D::Halfplane).samples;
  const auto& polar = seriesOf(p.result, Method2D::Polar).samples;
  ASSERT_EQ(half.size(), 4u);
  // halfplane tests every edge of an inside point: its mean grows about like N
  EXPECT_GT(half.back().predicates, 100.0 * half.front().predicates);
  EXPECT_GT(half.back().predicates, 0.2 * 4096);
  for (const cv::ScalingSample& x : polar) {
    EXPECT_LE(x.predicates, 3.0);
    EXPECT_GE(x.cellEdges, 0.5);  // the paper's query tests what the cell lists
    EXPECT_LE(x.cellEdges, 3.0);
  }
}

TEST(Scaling, SolidsOnGeodesicSpheres) {
  cv::ScalingWorker worker;
  cv::ScalingConfig c;
  c.faces = cv::geodesicSizes(1280);
  c.tracedPoints = 200;
  c.timedPoints = 1024;
  c.minSeconds = 0.001;
  EXPECT_EQ(c.faces, (std::vector<std::size_t>{20, 80, 320, 1280}));
  worker.start(c);
  worker.wait();
  const cv::ScalingProgress p = worker.snapshot();
  EXPECT_TRUE(p.finished);
  ASSERT_EQ(p.result.series3d.size(), std::size(convexloc::kAllMethods3D));
  const auto& half = p.result.series3d[0].samples;  // halfspace
  const auto& cube = p.result.series3d[2].samples;  // cubemap
  ASSERT_EQ(half.size(), 4u);
  ASSERT_EQ(cube.size(), 4u);
  EXPECT_EQ(half.back().n, 1280u);
  EXPECT_GT(half.back().predicates, 20.0 * half.front().predicates);
  for (const cv::ScalingSample& x : cube) EXPECT_LE(x.predicates, 4.0);
  const std::string svg = cv::scalingSvg(p.result, c, cv::Theme::Dark, true);
  std::string why;
  EXPECT_TRUE(wellFormed(svg, why)) << why;
  EXPECT_EQ(countOf(svg, "<polyline"), 3u + 3u + 3u);  // tests, time, memory
  EXPECT_EQ(cv::solidSvgPath("/tmp/why.svg"), "/tmp/why-3d.svg");
}

TEST(Scaling, StepsWithoutAThreadMeasureWhatTheThreadMeasures) {
  // the web page's way: one method at one size per step() on the caller's thread
  cv::ScalingConfig c;
  c.sizes = cv::scalingSizes(512);
  c.faces = cv::geodesicSizes(80);
  c.tracedPoints = 100;
  c.timedPoints = 512;
  c.minSeconds = 0.0;
  cv::ScalingWorker threaded, stepped;
  threaded.start(c);
  threaded.wait();
  stepped.start(c, false);
  std::size_t steps = 0;
  for (; stepped.running() && steps < 1000; ++steps) {
    const cv::ScalingProgress before = stepped.snapshot();
    stepped.step();
    // at most one measurement a step, so that a frame is never long
    EXPECT_LE(stepped.snapshot().done, before.done + 1);
  }
  EXPECT_EQ(steps, (c.sizes.size() * std::size(convexloc::kAllMethods2D)) +
                       (c.faces.size() * std::size(convexloc::kAllMethods3D)) + 1);
  const cv::ScalingProgress a = threaded.snapshot(), b = stepped.snapshot();
  EXPECT_TRUE(b.finished);
  EXPECT_EQ(b.done, b.total);
  EXPECT_EQ(a.total, b.total);
  ASSERT_EQ(a.result.series.size(), b.result.series.size());
  for (std::size_t i = 0; i < a.result.series.size(); ++i) {
    ASSERT_EQ(a.result.series[i].samples.size(), b.result.series[i].samples.size());
    for (std::size_t k = 0; k < a.result.series[i].samples.size(); ++k) {
      // the same points traced: the same predicate counts, the same memory
      EXPECT_EQ(a.result.series[i].samples[k].predicates, b.result.series[i].samples[k].predicates);
      EXPECT_EQ(a.result.series[i].samples[k].bytes, b.result.series[i].samples[k].bytes);
    }
  }
  ASSERT_EQ(a.result.series3d.size(), b.result.series3d.size());
  for (std::size_t i = 0; i < a.result.series3d.size(); ++i)
    EXPECT_EQ(a.result.series3d[i].samples.size(), b.result.series3d[i].samples.size());
  EXPECT_EQ(a.result.memory.size(), b.result.memory.size());
}

TEST(Scaling, CancelStopsASteppedRun) {
  cv::ScalingWorker worker;
  cv::ScalingConfig c;
  c.sizes = cv::scalingSizes(1000000);
  worker.start(c, false);
  worker.step();
  worker.cancel();  // measures nothing more
  EXPECT_FALSE(worker.running());
  const cv::ScalingProgress p = worker.snapshot();
  EXPECT_FALSE(p.running);
  EXPECT_TRUE(p.cancelled);
  EXPECT_EQ(p.done, 1u);
}

TEST(Scaling, TheLinearMethodStopsAtItsLimit) {
  cv::ScalingConfig c;
  c.linearLimit = 64;
  EXPECT_TRUE(cv::measured(c, Method2D::Halfplane, 64));
  EXPECT_FALSE(cv::measured(c, Method2D::Halfplane, 512));
  EXPECT_TRUE(cv::measured(c, Method2D::Polar, 1000000));
}

TEST(Scaling, CancelStopsAndJoins) {
  cv::ScalingWorker worker;
  cv::ScalingConfig c;
  c.sizes = cv::scalingSizes(1000000);
  worker.start(c);
  worker.cancel();
  const cv::ScalingProgress p = worker.snapshot();
  EXPECT_FALSE(p.running);
  EXPECT_FALSE(worker.running());
  EXPECT_LT(p.done, p.total);
}

TEST(Scaling, PaperMemoryGrowsAsTheGapShrinksWhileOursStaysBounded) {
  const cv::MemorySample wide = cv::measureMemory(1e-1), narrow = cv::measureMemory(1e-9);
  EXPECT_NEAR(narrow.gap, 1e-9, 1e-12);
  EXPECT_NEAR(narrow.paperSlabs, 2.0 / narrow.gap, 2.0);
  EXPECT_GT(narrow.paperBytes, 1e7 * wide.paperBytes);
  EXPECT_LT(narrow.polarBytes, 100000u);
  EXPECT_LT(narrow.uniformBytes, 100000u);
}

TEST(Scaling, SvgIsWellFormedWithOnePolylinePerMethod) {
  const cv::ScalingProgress p = measureSmall(64);
  cv::ScalingConfig c;
  c.sizes = cv::scalingSizes(64);
  const std::string svg = cv::scalingSvg(p.result, c, cv::Theme::Light);
  std::string why;
  EXPECT_TRUE(wellFormed(svg, why)) << why;
  // five methods in each of the two plots against N, the paper's polar in the first, and
  // three memory curves
  EXPECT_EQ(countOf(svg, "<polyline"), 5u + 1u + 5u + 3u);
  for (const Method2D m : convexloc::kAllMethods2D) {
    std::string legend(1, '>');
    legend.append(toString(m)).append(" ");
    EXPECT_GE(countOf(svg, legend), 2u) << toString(m);
  }
}

TEST(LogPlot, TextIsEscaped) {
  EXPECT_EQ(cv::xmlEscape("a<b & \"c\" > 'd'"), "a&lt;b &amp; &quot;c&quot; &gt; &apos;d&apos;");
  cv::LogPlot plot;
  plot.title = "N < 10 & more";
  plot.series.push_back({"x<y", cv::hex(0x112233), {{1.0, 1.0}, {10.0, 100.0}}, false});
  const cv::PlotDrawing d = cv::layoutLogPlot(plot, {{0.0, 0.0}, {400.0, 300.0}}, cv::PlotStyle{});
  const std::string svg = cv::svgDocument(std::span(&d, 1), {400.0, 300.0}, cv::hex(0xffffff), 12);
  std::string why;
  EXPECT_TRUE(wellFormed(svg, why)) << why;
  EXPECT_NE(svg.find("N &lt; 10 &amp; more"), std::string::npos);
}

TEST(LogPlot, DecadeLabels) {
  EXPECT_EQ(cv::decadeText(0), "1");
  EXPECT_EQ(cv::decadeText(2), "100");
  EXPECT_EQ(cv::decadeText(3), "1k");
  EXPECT_EQ(cv::decadeText(7), "10M");
  EXPECT_EQ(cv::decadeText(-1), "0.1");
  EXPECT_EQ(cv::decadeText(-9), "1e-9");
}

TEST(ScalingOptions, WhySplitAndBuildFlags) {
  const std::vector<std::string_view> args = {
      "--why", "--why-max", "4096", "--split", "wedge", "--build-step", "3", "--why-svg", "x.svg"};
  const cv::ParsedOptions p = cv::parseOptions(args);
  ASSERT_TRUE(p.error.empty()) << p.error;
  EXPECT_TRUE(p.options.why);
  EXPECT_EQ(p.options.whyMost, 4096u);
  EXPECT_EQ(p.options.split, "wedge");
  EXPECT_EQ(p.options.buildStep, 3u);
  EXPECT_EQ(p.options.whySvg, "x.svg");
  const std::vector<std::string_view> bad = {"--why-max", "5"};
  EXPECT_FALSE(cv::parseOptions(bad).error.empty());
  EXPECT_NE(cv::usageText().find("--why-svg FILE"), std::string::npos);
}

TEST(ScalingOptions, SplitAndBuildApplyToTheModel) {
  cv::Model model;
  cv::Options o;
  o.split = "wedge";
  o.buildStep = 4;
  EXPECT_TRUE(model.apply(o).empty());
  EXPECT_TRUE(model.split.enabled());
  EXPECT_EQ(model.split.method(), Method2D::Wedge);
  EXPECT_TRUE(model.build.active);
  EXPECT_EQ(model.build.step, 4u);
  o.split = "cubemap";
  EXPECT_FALSE(model.apply(o).empty());
}

// A slide's pages from the shipped record: three plots (the 3D page's third the memory of
// each 3D method against F), every line, mark and text (its width estimated from the style's
// character width) inside its plot, the text at the layout's size
TEST(ScalingSlide, PagesFromTheRecordKeepInsideTheirPlots) {
  cv::ScalingResult r;
  cv::ScalingConfig c;
  std::string error;
  ASSERT_TRUE(cv::readScalingRecord(
      std::string(CONVEXLOC_SOURCE_DIR) + "/assets/lectures/why-o1.txt", r, c, error))
      << error;
  for (const double page : {720.0, 1080.0, 2160.0})
    for (const bool solid : {false, true}) {
      const double font = cv::kSlideTextShare * page;
      const cv::ScreenRect room{{0.02 * page, 0.1 * page}, {1.76 * page, 0.85 * page}};
      const cv::PlotsLayout l = cv::layoutPlots(room, cv::slidePlotCount(), font);
      const cv::PlotStyle st = cv::slidePlotStyle(cv::Theme::Light, font);
      const std::vector<cv::PlotDrawing> d = cv::slideDrawings(r, c, st, l, solid);
      // three plots, the legend the first two share (the 3D page: all three), the line under
      ASSERT_EQ(d.size(), 5u);
      const auto in = [](glm::dvec2 p, const cv::ScreenRect& b) {
        return p.x >= b.lo.x - 1e-6 && p.x <= b.hi.x + 1e-6 && p.y >= b.lo.y - 1e-6 &&
               p.y <= b.hi.y + 1e-6;
      };
      for (const cv::PlotDrawing& dr : d) {
        for (const cv::PlotPath& p : dr.paths)
          for (const glm::dvec2 q : p.points) EXPECT_TRUE(in(q, dr.rect)) << page << solid;
        for (const cv::PlotText& t : dr.texts) {
          const double w = st.charWidth * static_cast<double>(t.text.size());
          const glm::dvec2 lo{t.p.x - t.anchor * w, t.p.y - 0.5 * font};
          EXPECT_TRUE(in(lo, dr.rect) && in(lo + glm::dvec2(w, font), dr.rect))
              << "'" << t.text << "' at " << page << (solid ? " 3D" : " 2D");
          EXPECT_FALSE(t.bold);  // the window draws no bold
        }
      }
      // the memory plot: one curve per method (the 3D page's per 3D method)
      const auto memory = std::find_if(d.begin(), d.end(), [](const cv::PlotDrawing& dr) {
        return !dr.texts.empty() && dr.texts.front().text.starts_with("Memory against");
      });
      ASSERT_NE(memory, d.end());
      const std::size_t curves = std::count_if(memory->paths.begin(), memory->paths.end(),
                                               [](const cv::PlotPath& p) { return p.series; });
      EXPECT_EQ(curves, solid ? r.series3d.size() : 3u);
      // every series named once in a legend on the page
      std::size_t names = 0;
      for (const cv::PlotDrawing& dr : d)
        for (const cv::PlotText& t : dr.texts)
          names += t.text == "walk  O(sqrt F)" || t.text == "wedge  O(log N)";
      EXPECT_EQ(names, 1u) << page << solid;
    }
  // the memory against F holds each 3D sample's bytes
  const cv::LogPlot m = cv::memoryPlot3D(r, c);
  ASSERT_EQ(m.series.size(), r.series3d.size());
  for (std::size_t i = 0; i < m.series.size(); ++i) {
    ASSERT_EQ(m.series[i].points.size(), r.series3d[i].samples.size());
    for (std::size_t k = 0; k < m.series[i].points.size(); ++k)
      EXPECT_EQ(m.series[i].points[k].y, static_cast<double>(r.series3d[i].samples[k].bytes));
  }
}
