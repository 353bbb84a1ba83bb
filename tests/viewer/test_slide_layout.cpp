// The slide layout (logic/teach/slide_layout): the page letterboxed in any window, the
// boxes inside the page and apart, the Steps window off the title, the same placement
// relative to the page at 1280x720, 1920x1080 and 3840x2160.
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "logic/app/lecture.hpp"
#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "logic/teach/slide_layout.hpp"

namespace cv = convexloc::viewer;

namespace {

// a text measure of a font `font` pixels high: every character 0.55 of it wide
cv::MeasureText measureAt(double font) {
  return [font](std::string_view t) {
    return glm::dvec2(0.55 * font * static_cast<double>(t.size()), font);
  };
}

// the window's metrics at a page scale: the ImGui style's sizes grow with the text
cv::SlideMetrics metricsAt(double scale) {
  cv::SlideMetrics m;
  m.font = 32.0 * scale;  // a lecture's text size 2 on the 1920x1080 page
  m.spacing = 12.0 * scale;
  m.padding = 24.0 * scale;
  m.frame = 48.0 * scale;
  m.margin = 20.0 * scale;
  m.measure = measureAt(m.font);
  return m;
}

// a step-by-step query of `n` steps, the longer ones needing two lines in a narrow window
cv::StepsContent stepsOf(std::size_t n, int step) {
  cv::StepsContent s;
  s.model.title = "polar: point (0.25,-0.5)";
  s.model.note = "paper mode: no radius filter";
  s.model.code = {"octant from the signs of dx, dy and |dx| vs |dy|",
                  "slab i = floor(q * ratio) in the octant", "test the edges the slab lists"};
  for (std::size_t i = 0; i < n; ++i)
    s.model.steps.push_back({"edge " + std::to_string(i) + ": orient2d = +1 (inner side)" +
                                 (i % 3 == 0 ? ", the slab's second edge, tested as well" : ""),
                             static_cast<int>(i % 3)});
  s.step = step;
  s.controls = false;
  return s;
}

// a slide with every box: title, caption, steps, legend, in the page of `window`
cv::SlideLayout slideIn(glm::dvec2 window, std::size_t steps = 8, int step = 5) {
  const cv::PageFit fit = cv::fitPage(window);
  cv::SlideContent c;
  c.area = fit.page;
  c.title = "4 / 27: Wedges: a binary search over the rays from x0";
  c.caption =
      "Rays v0->v4 (clockwise), v0->v2, v0->v3 (counter-clockwise) halve the fan: x lies "
      "between v3 and v4.";
  c.steps = stepsOf(steps, step);
  c.legend = glm::dvec2(330.0, 260.0) * fit.scale;
  c.shapeAspect = 1.2;
  return cv::layoutSlide(c, metricsAt(fit.scale));
}

bool inside(const cv::ScreenRect& r, const cv::ScreenRect& page) {
  return r.lo.x >= page.lo.x - 1e-9 && r.lo.y >= page.lo.y - 1e-9 && r.hi.x <= page.hi.x + 1e-9 &&
         r.hi.y <= page.hi.y + 1e-9;
}

bool overlap(const cv::ScreenRect& a, const cv::ScreenRect& b) {
  return a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y;
}

// the boxes of a layout, by name
std::vector<std::pair<std::string, cv::ScreenRect>> boxesOf(const cv::SlideLayout& l) {
  std::vector<std::pair<std::string, cv::ScreenRect>> b = {
      {"title", l.title.box}, {"caption", l.caption.box}, {"legend", l.legend}, {"scene", l.scene}};
  if (l.steps) b.emplace_back("steps", l.steps->box);
  return b;
}

}  // namespace

TEST(SlideLayout, ThePageIsLetterboxedCentredAtItsAspect) {
  const cv::PageFit wide = cv::fitPage({2560.0, 1080.0});
  EXPECT_DOUBLE_EQ(wide.scale, 1.0);
  EXPECT_DOUBLE_EQ(wide.page.lo.x, 320.0);
  EXPECT_DOUBLE_EQ(wide.page.hi.x, 2240.0);
  EXPECT_DOUBLE_EQ(wide.page.lo.y, 0.0);
  const cv::PageFit tall = cv::fitPage({1440.0, 900.0});
  EXPECT_DOUBLE_EQ(tall.scale, 0.75);
  EXPECT_DOUBLE_EQ(tall.page.lo.y, 45.0);
  EXPECT_DOUBLE_EQ(tall.page.hi.y, 855.0);
  EXPECT_DOUBLE_EQ(cv::fitPage({0.0, 900.0}).scale, 1.0);
}

TEST(SlideLayout, EveryBoxIsInsideThePageAndNoTwoOverlap) {
  for (const glm::dvec2 window : {glm::dvec2(1280.0, 720.0), glm::dvec2(1920.0, 1080.0),
                                  glm::dvec2(3840.0, 2160.0), glm::dvec2(1440.0, 900.0)}) {
    for (const std::size_t steps : {std::size_t{3}, std::size_t{8}, std::size_t{30}}) {
      const cv::SlideLayout l = slideIn(window, steps, static_cast<int>(steps) - 1);
      const cv::ScreenRect page = cv::fitPage(window).page;
      const auto boxes = boxesOf(l);
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        EXPECT_TRUE(inside(boxes[i].second, page)) << boxes[i].first << " at " << window.x;
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
          EXPECT_FALSE(overlap(boxes[i].second, boxes[j].second))
              << boxes[i].first << " and " << boxes[j].first << " at " << window.x << "x"
              << window.y << ", " << steps << " steps";
      }
    }
  }
}

TEST(SlideLayout, TheSamePlacesRelativeToThePageAtEverySize) {
  const cv::SlideLayout ref = slideIn({1920.0, 1080.0});
  for (const glm::dvec2 window : {glm::dvec2(1280.0, 720.0), glm::dvec2(3840.0, 2160.0)}) {
    const cv::SlideLayout l = slideIn(window);
    const double k = window.x / 1920.0;
    const auto a = boxesOf(ref), b = boxesOf(l);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_NEAR(b[i].second.lo.x, k * a[i].second.lo.x, 1e-6 * window.x) << a[i].first;
      EXPECT_NEAR(b[i].second.lo.y, k * a[i].second.lo.y, 1e-6 * window.x) << a[i].first;
      EXPECT_NEAR(b[i].second.hi.x, k * a[i].second.hi.x, 1e-6 * window.x) << a[i].first;
      EXPECT_NEAR(b[i].second.hi.y, k * a[i].second.hi.y, 1e-6 * window.x) << a[i].first;
    }
    EXPECT_EQ(l.caption.lines, ref.caption.lines);
    EXPECT_EQ(l.title.lines, ref.title.lines);
    ASSERT_TRUE(l.steps && ref.steps);
    EXPECT_EQ(l.steps->shown.size(), ref.steps->shown.size());
  }
}

// a long list shows a run of steps around the one shown, which is always among them, and the
// window stays clear of the title card (slide 4 at 1280x720 once had it covered)
TEST(SlideLayout, ALongStepListShowsTheCurrentStepBelowTheTitle) {
  for (int step = 0; step < 30; step += 7) {
    const cv::SlideLayout l = slideIn({1280.0, 720.0}, 30, step);
    ASSERT_TRUE(l.steps);
    bool shown = false;
    for (const cv::StepLines& s : l.steps->shown) shown |= static_cast<int>(s.step) == step;
    EXPECT_TRUE(shown) << step;
    EXPECT_LT(l.steps->shown.size(), 30u);
    EXPECT_GE(l.steps->box.lo.y, l.title.box.hi.y);
  }
}

// every step's line and the heading fit the window's width: nothing is clipped (the Steps
// header on the 3D slides once ran past the window)
TEST(SlideLayout, TheStepsLinesFitTheWindow) {
  const cv::SlideMetrics m = metricsAt(2.0 / 3.0);
  const cv::SlideLayout l = slideIn({1280.0, 720.0}, 8, 2);
  ASSERT_TRUE(l.steps);
  const double inner = l.steps->box.size().x - 2.0 * m.padding;
  for (const std::string& h : l.steps->heading) EXPECT_LE(m.measure(h).x, inner) << h;
  for (const cv::StepLines& s : l.steps->shown)
    for (const std::string& line : s.lines)
      EXPECT_LE(m.measure(line).x, l.steps->columnWidth) << line;
  for (const std::string& c : l.steps->code) EXPECT_LE(m.measure(c).x, l.steps->columnWidth) << c;
}

// a step slide and the next one of the same query give the scene the same room, though
// their captions take one line and two: the shape does not jump between them (slides 7 -> 8
// and 13 -> 14)
TEST(SlideLayout, StepsOfOneQueryLeaveTheSceneTheSameRoom) {
  const cv::PageFit fit = cv::fitPage({1920.0, 1080.0});
  cv::SlideContent c;
  c.area = fit.page;
  c.title = "7 / 27: Uniform slabs: O(1)";
  c.legend = {330.0, 260.0};
  c.shapeAspect = 0.7;
  c.captionRoom = 2;
  c.caption = "Equal slabs: eq. (4) needs no search.";
  c.steps = stepsOf(5, 4);
  const cv::SlideLayout a = cv::layoutSlide(c, metricsAt(1.0));
  c.title = "8 / 27: Uniform slabs: eq. (4), no search";
  c.caption =
      "i = floor((y - ymin) / dy) = floor(7.34) = 7: one division finds the slab, its two "
      "edges decide.";
  c.steps = stepsOf(5, 0);
  const cv::SlideLayout b = cv::layoutSlide(c, metricsAt(1.0));
  ASSERT_NE(a.caption.lines.size(), b.caption.lines.size());
  EXPECT_EQ(a.scene.lo, b.scene.lo);
  EXPECT_EQ(a.scene.hi, b.scene.hi);
  for (const cv::SlideLayout* l : {&a, &b}) {
    EXPECT_FALSE(overlap(l->scene, l->caption.box));
    EXPECT_FALSE(overlap(l->scene, l->legend));
  }
}

// a legend taller than the room between the card and the caption still gets its strip on
// the right: the shape is fitted beside it, not under it (a lecture zoomed 1.5x at 720p)
TEST(SlideLayout, ALegendTallerThanTheRoomTakesTheRightStrip) {
  const cv::PageFit fit = cv::fitPage({1280.0, 720.0});
  cv::SlideContent c;
  c.area = fit.page;
  c.title = "2 / 5: Wedges: a binary search over the rays from x0";
  c.caption = "Rays v0->v4 (clockwise), v0->v2, v0->v3 (counter-clockwise) halve the fan.";
  c.legend = {420.0, 400.0};
  const cv::SlideLayout l = cv::layoutSlide(c, metricsAt(fit.scale * 1.5));
  ASSERT_LT(l.caption.box.lo.y - l.title.box.hi.y, c.legend.y + 20.0);
  EXPECT_FALSE(overlap(l.scene, l.legend));
  EXPECT_GT(l.scene.size().x, 0.0);
}

// a lecture's own page (`page 1600x1200`, or --page): its aspect is kept, pillarboxed in a
// 16:9 window; a malformed size is refused
TEST(SlideLayout, ALecturesOwnPageKeepsItsAspect) {
  const cv::ParsedLecture parsed =
      cv::parseLecture("slide Four by three\npage 1600x1200\nspray 0\n", "test.lecture");
  ASSERT_TRUE(parsed.clean());
  ASSERT_TRUE(parsed.lecture.slides[0].options.page);
  EXPECT_EQ(*parsed.lecture.slides[0].options.page, std::pair(1600, 1200));
  for (const char* bad : {"1600", "1600x", "x1200", "100x1200", "1600x1200x3"}) {
    const std::vector<std::string_view> args = {"--page", bad};
    EXPECT_NE(cv::parseOptions(args).error, "") << bad;
  }
  const cv::PageFit fit = cv::fitPage({1920.0, 1080.0}, {1600.0, 1200.0});
  EXPECT_DOUBLE_EQ(fit.scale, 0.9);
  EXPECT_DOUBLE_EQ(fit.page.lo.x, 240.0);
  EXPECT_DOUBLE_EQ(fit.page.hi.x, 1680.0);
  EXPECT_DOUBLE_EQ(fit.page.lo.y, 0.0);
  cv::Model model;
  ASSERT_EQ(model.apply(parsed.lecture.slides[0].options), "");
  EXPECT_EQ(model.settings.page, glm::dvec2(1600.0, 1200.0));
  model.reset();  // the next slide keeps the lecture's page
  EXPECT_EQ(model.settings.page, glm::dvec2(1600.0, 1200.0));
}

// a slide (SlideContent::slide): at every page from 1024x768 to 3840x2160 and every text size
// from 0.75 to 2 times the lecture's, the figure's room keeps its share of the page, no two
// boxes overlap, and no text is smaller than 2.2% of the page's height
TEST(SlideLayout, ASlidesFigureKeepsItsShareAtEverySizeAndTextScale) {
  for (const glm::dvec2 window : {glm::dvec2(1024.0, 576.0), glm::dvec2(1280.0, 720.0),
                                  glm::dvec2(1920.0, 1080.0), glm::dvec2(3840.0, 2160.0)})
    for (const double text : {0.75, 1.0, 1.5, 2.0}) {
      const cv::PageFit fit = cv::fitPage(window);
      cv::SlideContent c;
      c.area = fit.page;
      c.title = "23 / 27: A polyhedron, one query through the cube map";
      c.caption =
          "d = x - x_T picks the cube face +x, (s, t) the cell; the paper's query tests "
          "the faces the cell lists.";
      c.steps = stepsOf(12, 6);
      c.legend = glm::dvec2(330.0, 260.0) * fit.scale * text;
      c.captionRoom = 2;
      c.slide = true;
      const cv::SlideMetrics m = metricsAt(fit.scale * text);
      const cv::SlideLayout l = cv::layoutSlide(c, m);
      const glm::dvec2 room = l.scene.size(), page = fit.page.size();
      EXPECT_GE(room.x * room.y, cv::kFigureShare * page.x * page.y * (1.0 - 1e-9))
          << window.x << " text " << text;
      const auto boxes = boxesOf(l);
      for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
          EXPECT_FALSE(overlap(boxes[i].second, boxes[j].second))
              << boxes[i].first << " and " << boxes[j].first << " at " << window.x << " text "
              << text;
      // the rule (2.2%); the layout's floor when it shrinks text is kSlideTextShare (2.25%)
      EXPECT_GE(m.font * std::min(1.0, l.columnScale), 0.022 * page.y);
      ASSERT_TRUE(l.steps);
    }
}

// A phone held upright gets a page of its own aspect unless the lecture gave one; a landscape
// window keeps the 16:9 page.
TEST(SlideLayout, AnUprightWindowGetsAnUprightPage) {
  EXPECT_EQ(cv::slidePageIn({1280.0, 800.0}, cv::kSlidePage, false), cv::kSlidePage);
  EXPECT_EQ(cv::slidePageIn({1000.0, 1100.0}, cv::kSlidePage, false), cv::kSlidePage);
  EXPECT_EQ(cv::slidePageIn({390.0, 844.0}, {1600.0, 1200.0}, true), glm::dvec2(1600.0, 1200.0));
  const glm::dvec2 phone = cv::slidePageIn({390.0, 844.0}, cv::kSlidePage, false);
  EXPECT_EQ(phone.x, cv::kUprightPageWidth);
  EXPECT_NEAR(phone.y / phone.x, 844.0 / 390.0, 1e-12);
  // the page fills the phone's screen
  const cv::PageFit fit = cv::fitPage({390.0, 844.0}, phone);
  EXPECT_NEAR(fit.page.size().x, 390.0, 1e-9);
  EXPECT_NEAR(fit.page.size().y, 844.0, 1e-9);
  // a very tall window: the page's aspect capped, letterboxed above and below
  const glm::dvec2 tall = cv::slidePageIn({300.0, 1200.0}, cv::kSlidePage, false);
  EXPECT_NEAR(tall.y / tall.x, cv::kUprightMostAspect, 1e-12);
}

// On an upright page the Steps window and the legend lie under the figure, whose room keeps
// the page's width and its share of the page; no box covers another.
TEST(SlideLayout, AnUprightSlidePutsStepsAndLegendUnderTheFigure) {
  // phones at the slide's text and half as large again; tablets held upright (squarer pages,
  // where text that large leaves the figure too little) at the slide's text
  const std::vector<std::pair<glm::dvec2, double>> cases = {
      {{390.0, 844.0}, 1.0},  {{390.0, 844.0}, 1.5},  {{780.0, 1688.0}, 1.0},
      {{780.0, 1688.0}, 1.5}, {{768.0, 1024.0}, 1.0}, {{1024.0, 1366.0}, 1.0}};
  for (const auto& [window, text] : cases) {
    const cv::PageFit fit = cv::fitPage(window, cv::slidePageIn(window, cv::kSlidePage, false));
    cv::SlideContent c;
    c.area = fit.page;
    c.title = "13 / 27: Polar query, step 2: the ratio picks the slab";
    c.caption =
        "Inside the octant, k = floor(q * |dy| / |dx|) = floor(4 * 0.11) = 0 picks the "
        "slab: cell 31.";
    c.steps = stepsOf(5, 1);
    c.legend = glm::dvec2(330.0, 260.0) * fit.scale * text;
    c.captionRoom = 2;
    c.slide = true;
    c.shapeAspect = 1.2;
    const cv::SlideMetrics m = metricsAt(fit.scale * text);
    const cv::SlideLayout l = cv::layoutSlide(c, m);
    const std::string at =
        std::to_string(window.x) + "x" + std::to_string(window.y) + " text " + std::to_string(text);
    ASSERT_TRUE(l.steps) << at;
    const glm::dvec2 room = l.scene.size(), page = fit.page.size();
    // the room the page's width, and tall enough for the shape fitted to it to fill 80% of it
    EXPECT_GE(room.x, 0.9 * page.x) << at;
    EXPECT_GE(room.y, 0.8 * room.x / c.shapeAspect - 1e-9) << at;
    EXPECT_GE(l.columnScale, cv::kUprightLeastText) << at;
    EXPECT_LE(l.scene.hi.y, l.steps->box.lo.y) << at;
    EXPECT_LE(l.scene.hi.y, l.legend.lo.y) << at;
    EXPECT_LE(l.steps->box.hi.y, l.caption.box.lo.y) << at;
    // the current step among those listed
    ASSERT_FALSE(l.steps->shown.empty()) << at;
    EXPECT_LE(l.steps->shown.front().step, 1u) << at;
    EXPECT_GE(l.steps->shown.back().step, 1u) << at;
    const auto boxes = boxesOf(l);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      EXPECT_TRUE(inside(boxes[i].second, fit.page)) << boxes[i].first << " at " << at;
      for (std::size_t j = i + 1; j < boxes.size(); ++j)
        EXPECT_FALSE(overlap(boxes[i].second, boxes[j].second))
            << boxes[i].first << " and " << boxes[j].first << " at " << at;
    }
  }
}

// a plots slide on an upright page stacks its plots, each the room's width
TEST(SlideLayout, AnUprightPlotsSlideStacksItsPlots) {
  const cv::ScreenRect room{{10.0, 60.0}, {380.0, 760.0}};
  const double font = cv::plotsTextPx(room, 3, 13.0, 844.0);
  EXPECT_LE(font, 13.0);
  const cv::PlotsLayout p = cv::layoutPlots(room, 3, font);
  ASSERT_EQ(p.plots.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(p.plots[i].lo.x, room.lo.x);
    EXPECT_EQ(p.plots[i].hi.x, room.hi.x);
    EXPECT_TRUE(inside(p.plots[i], room));
    if (i > 0) {
      EXPECT_LT(p.plots[i - 1].hi.y, p.plots[i].lo.y);
    }
  }
  EXPECT_LE(p.plots[2].hi.y, p.note.lo.y);
}

// a list cut to a window around the current step says which steps it shows, the current
// among them
TEST(SlideLayout, ACutStepListSaysWhichStepsItShows) {
  cv::SlideMetrics m = metricsAt(1.0);
  const cv::StepsLayout l =
      cv::layoutStepsInColumn(stepsOf(12, 8), m, {{1400.0, 100.0}, {1900.0, 600.0}});
  ASSERT_FALSE(l.shown.empty());
  ASSERT_LT(l.shown.size(), 12u);
  const std::size_t first = l.shown.front().step + 1, last = l.shown.back().step + 1;
  EXPECT_LE(first, 9u);
  EXPECT_GE(last, 9u);
  const std::string want = "steps " + std::to_string(first) + "-" + std::to_string(last) + " of 12";
  EXPECT_EQ(l.heading.back(), want);
  EXPECT_GE(l.box.lo.y, 100.0);
  // all twelve where the column holds them: no range line
  const cv::StepsLayout all =
      cv::layoutStepsInColumn(stepsOf(12, 8), m, {{1400.0, 0.0}, {1900.0, 2000.0}});
  EXPECT_EQ(all.shown.size(), 12u);
  EXPECT_NE(all.heading.back().rfind("steps ", 0), 0u);
}

// Why O(1) on a slide: its plots side by side and the line under them in the figure room, the
// room its share of the page, no Steps window or legend, the plots' text at least the slide
// rule's share of the page and no larger than what a plot's width and the room's height hold
TEST(SlideLayout, APlotsSlidesPlotsFillItsFigureAtSlideTextSize) {
  for (const glm::dvec2 window : {glm::dvec2(1280.0, 720.0), glm::dvec2(1280.0, 800.0),
                                  glm::dvec2(1920.0, 1080.0), glm::dvec2(3840.0, 2160.0)})
    for (const double text : {0.75, 1.0, 1.5, 2.0}) {
      const cv::PageFit fit = cv::fitPage(window);
      cv::SlideContent c;
      c.area = fit.page;
      c.title = "18 / 27: Why O(1): cost against N";
      c.caption =
          "Tests per query grow with N (half-planes), lg N (wedges); slab compares y values: its "
          "tests stay flat, its time grows; uniform, polar: flat.";
      c.steps = stepsOf(8, 2);  // a plots slide draws neither
      c.legend = glm::dvec2(330.0, 260.0) * fit.scale * text;
      c.captionRoom = 2;
      c.slide = true;
      c.plots = 3;
      const cv::SlideMetrics m = metricsAt(fit.scale * text);
      const cv::SlideLayout l = cv::layoutSlide(c, m);
      const std::string at = std::to_string(window.x) + "x" + std::to_string(window.y) + " text " +
                             std::to_string(text);
      ASSERT_TRUE(l.plots) << at;
      EXPECT_FALSE(l.steps) << at;
      EXPECT_EQ(l.legend.size(), glm::dvec2(0.0)) << at;
      const glm::dvec2 room = l.scene.size(), page = fit.page.size();
      EXPECT_GE(room.x * room.y, cv::kFigureShare * page.x * page.y * (1.0 - 1e-9)) << at;
      const cv::PlotsLayout& p = *l.plots;
      ASSERT_EQ(p.plots.size(), 3u) << at;
      std::vector<std::pair<std::string, cv::ScreenRect>> boxes = {
          {"title", l.title.box}, {"caption", l.caption.box}, {"note", p.note}};
      for (std::size_t i = 0; i < p.plots.size(); ++i) {
        EXPECT_TRUE(inside(p.plots[i], l.scene)) << "plot " << i << " at " << at;
        EXPECT_GT(p.plots[i].size().y, 0.5 * room.y) << at;
        boxes.emplace_back("plot " + std::to_string(i), p.plots[i]);
      }
      EXPECT_TRUE(inside(p.note, l.scene)) << at;
      for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
          EXPECT_FALSE(overlap(boxes[i].second, boxes[j].second))
              << boxes[i].first << " and " << boxes[j].first << " at " << at;
      EXPECT_GE(p.fontPx, 0.022 * page.y) << at;
      const double floor = cv::kSlideTextShare * page.y;
      EXPECT_LE(p.fontPx, std::max(m.font, floor) + 1e-9) << at;
      // above the floor, a plot holds kPlotColumns characters across
      if (p.fontPx > floor + 1e-9) {
        EXPECT_GE(p.plots[0].size().x, cv::kPlotColumns * 0.56 * p.fontPx * (1.0 - 1e-9)) << at;
      }
    }
}

// a zoom inset keeps the figure room's corner toward what it magnifies, off every other
// box, and the shape is fitted beside it, keeping the room's height
TEST(SlideLayout, AnInsetKeepsTheCornerTowardWhatItMagnifies) {
  for (const glm::dvec2 window : {glm::dvec2(1280.0, 720.0), glm::dvec2(3840.0, 2160.0)})
    for (const double text : {0.75, 1.0, 2.0})
      for (const glm::dvec2 toward : {glm::dvec2(1.0, -1.0), glm::dvec2(-3.0, 0.5)}) {
        const cv::PageFit fit = cv::fitPage(window);
        cv::SlideContent c;
        c.area = fit.page;
        c.title = "24 / 27: Degenerate in 3D: tiny faces";
        c.caption = "A corner rounded by tiny triangles: the cube map refines its cells there.";
        c.legend = glm::dvec2(330.0, 260.0) * fit.scale * text;
        c.captionRoom = 2;
        c.slide = true;
        const cv::SlideMetrics m = metricsAt(fit.scale * text);
        c.inset = cv::InsetWish{toward, 14.0 * m.font * 0.55, 1.6 * m.font, 2, 1};
        const cv::SlideLayout l = cv::layoutSlide(c, m);
        const std::string at = std::to_string(window.x) + " text " + std::to_string(text);
        ASSERT_GT(l.inset.size().x, 0.0) << at;
        // in the figure room, at the corner toward the tiny things
        EXPECT_TRUE(inside(l.inset, l.scene)) << at;
        EXPECT_DOUBLE_EQ(toward.x > 0.0 ? l.inset.hi.x : l.inset.lo.x,
                         toward.x > 0.0 ? l.scene.hi.x : l.scene.lo.x)
            << at;
        EXPECT_DOUBLE_EQ(toward.y < 0.0 ? l.inset.lo.y : l.inset.hi.y,
                         toward.y < 0.0 ? l.scene.lo.y : l.scene.hi.y)
            << at;
        EXPECT_TRUE(inside(l.insetFrame, l.inset)) << at;
        EXPECT_GE(l.insetFrame.size().x, l.scene.size().y / 3.0 - 0.2 * 1.6 * m.font - 1e-9) << at;
        // off the other boxes and the shape's room, which keeps the figure room's height
        for (const auto& [name, box] : boxesOf(l))
          if (name != "scene") {
            EXPECT_FALSE(overlap(l.inset, box)) << name << " at " << at;
          }
        const cv::ScreenRect shape = l.shapeRoom();
        EXPECT_FALSE(overlap(l.inset, shape)) << at;
        EXPECT_DOUBLE_EQ(shape.size().y, l.scene.size().y) << at;
        EXPECT_GE(shape.size().x, 0.8 * l.scene.size().y) << at;
      }
}
