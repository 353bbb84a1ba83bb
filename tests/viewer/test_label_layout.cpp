// Label placement: placed labels never overlap each other or a marker, keep off drawn lines
// where they can; text breaks at spaces; the fit leaves room beside the corner windows.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "logic/view/fit_room.hpp"
#include "logic/view/label_layout.hpp"

namespace cv = convexloc::viewer;

namespace {

// a monospaced measure: 7 pixels per character, 14 high
glm::dvec2 mono(std::string_view t) {
  return {7.0 * static_cast<double>(t.size()), 14.0};
}

}  // namespace

TEST(LabelLayout, CrowdedRandomLabelsNeverOverlapOrCoverAMarker) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> x(0.0, 600.0), y(0.0, 400.0);
  std::vector<std::string> texts;
  for (int i = 0; i < 300; ++i) texts.push_back(std::to_string(i * 37 % 1000));
  std::vector<cv::LabelRequest> labels;
  std::vector<cv::PixelDisc> markers;
  for (int i = 0; i < 300; ++i) labels.push_back({{x(rng), y(rng)}, {8.0, -8.0}, texts[i], false});
  for (int i = 0; i < 80; ++i) markers.push_back({{x(rng), y(rng)}, 5.0});
  const auto placed = cv::placeLabels(labels, markers, mono, 1.5);
  ASSERT_EQ(placed.size(), labels.size());
  std::size_t shown = 0;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (!placed[i].shown) continue;
    ++shown;
    for (std::size_t j = i + 1; j < placed.size(); ++j)
      EXPECT_FALSE(placed[j].shown && cv::boxesOverlap(placed[i], placed[j])) << i << " " << j;
    for (const cv::PixelDisc& m : markers) EXPECT_FALSE(cv::boxCoversDisc(placed[i], m)) << i;
  }
  // crowded, but most find a place
  EXPECT_GT(shown, 150u);
  EXPECT_LT(shown, labels.size());
}

TEST(LabelLayout, AFreeLabelKeepsItsOffsetAndAMarkedOneMovesOff) {
  // "x_T" asked onto its own cross: it moves off the marker
  const std::vector<cv::LabelRequest> labels{{{100.0, 100.0}, {0.0, 0.0}, "x_T", false},
                                             {{300.0, 100.0}, {10.0, 0.0}, "9", false}};
  const std::vector<cv::PixelDisc> markers{{{100.0, 100.0}, 8.0}};
  const auto placed = cv::placeLabels(labels, markers, mono, 1.0);
  ASSERT_TRUE(placed[0].shown && placed[1].shown);
  EXPECT_FALSE(cv::boxCoversDisc(placed[0], markers[0]));
  EXPECT_EQ(placed[1].centre, glm::dvec2(310.0, 100.0));
  EXPECT_FALSE(placed[1].leader);
}

TEST(LabelLayout, NeighbouringNumbersDoNotRunTogether) {
  // vertices 9 and 10 a few pixels apart, each asking for the same offset
  const std::vector<cv::LabelRequest> labels{{{200.0, 200.0}, {0.0, 12.0}, "9", false},
                                             {{212.0, 201.0}, {0.0, 12.0}, "10", false},
                                             {{205.0, 190.0}, {12.0, 0.0}, "135", false}};
  const auto placed = cv::placeLabels(labels, {}, mono, 1.0);
  for (std::size_t i = 0; i < placed.size(); ++i)
    for (std::size_t j = i + 1; j < placed.size(); ++j)
      EXPECT_FALSE(placed[i].shown && placed[j].shown && cv::boxesOverlap(placed[i], placed[j]));
  EXPECT_TRUE(placed[0].shown);
  EXPECT_TRUE(placed[1].shown);
}

TEST(LabelLayout, AnEssentialLabelIsShownWithALeaderWhenBoxedIn) {
  // a label whose every near candidate is covered by markers
  std::vector<cv::PixelDisc> markers;
  for (int dx = -60; dx <= 60; dx += 6)
    for (int dy = -40; dy <= 40; dy += 6) markers.push_back({{100.0 + dx, 100.0 + dy}, 4.0});
  const std::vector<cv::LabelRequest> labels{{{100.0, 100.0}, {0.0, 0.0}, "outside", true},
                                             {{100.0, 100.0}, {0.0, 0.0}, "dropped", false}};
  const auto placed = cv::placeLabels(labels, markers, mono, 1.0);
  EXPECT_TRUE(placed[0].shown);
  EXPECT_TRUE(placed[0].leader);
  EXPECT_FALSE(placed[1].shown);
}

TEST(LabelLayout, LinesBreakAtSpacesNeverInsideANumber) {
  const std::string text = "centre x_T = (0.02793342314053292, -0.5042585326694533) in octant 1";
  const auto lines = cv::breakAtSpaces(text, 7.0 * 24, mono);
  ASSERT_GT(lines.size(), 2u);
  std::string joined;
  for (const std::string& l : lines) {
    EXPECT_TRUE(l.size() <= 24 || l.find(' ') == std::string::npos) << l;
    joined += (joined.empty() ? "" : " ") + l;
  }
  EXPECT_EQ(joined, text);
  bool whole = false;
  for (const std::string& l : lines) whole |= l.find("-0.5042585326694533)") != std::string::npos;
  EXPECT_TRUE(whole);
  // line breaks in the text are kept
  EXPECT_EQ(cv::breakAtSpaces("a\nb", 1000.0, mono).size(), 2u);
}

TEST(LabelLayout, LabelsStayInsideTheWindow) {
  // asked to the left of an anchor at the window's left edge: it goes right instead
  const std::vector<cv::LabelRequest> labels{{{4.0, 50.0}, {-30.0, 0.0}, "octant 4", false}};
  const auto placed = cv::placeLabels(labels, {}, mono, 1.0, {{0.0, 0.0}, {200.0, 100.0}});
  ASSERT_TRUE(placed[0].shown);
  EXPECT_GE(placed[0].centre.x - 0.5 * placed[0].size.x, 0.0);
  EXPECT_LE(placed[0].centre.x + 0.5 * placed[0].size.x, 200.0);
}

namespace {

// true when the segment from `a` to `b` passes through the placed box
bool crosses(const cv::LabelPlacement& box, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 lo = box.centre - 0.5 * box.size, hi = box.centre + 0.5 * box.size;
  for (int i = 0; i <= 200; ++i) {
    const glm::dvec2 p = a + (b - a) * (i / 200.0);
    if (p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y) return true;
  }
  return false;
}

}  // namespace

TEST(LabelLayout, ALabelIsNotPlacedAcrossASegmentWhenAFreeSpotExists) {
  // "octant 1" asked right onto a line through its spot; the spots above the line are free
  const cv::PixelBox area{{0.0, 0.0}, {400.0, 300.0}};
  const glm::dvec2 a(0.0, 152.0), b(400.0, 152.0);
  cv::SegmentGrid lines(area, 4.0);
  lines.add(a, b);
  const std::vector<cv::LabelRequest> labels{{{200.0, 160.0}, {0.0, -8.0}, "octant 1", false}};
  const auto without = cv::placeLabels(labels, {}, mono, 1.0, area);
  ASSERT_TRUE(without[0].shown);
  EXPECT_TRUE(crosses(without[0], a, b));  // the asked spot is across the line
  const auto placed = cv::placeLabels(labels, {}, mono, 1.0, area, &lines);
  ASSERT_TRUE(placed[0].shown);
  EXPECT_FALSE(crosses(placed[0], a, b));
  EXPECT_EQ(lines.covered(placed[0]), 0);
}

TEST(LabelLayout, LinesNeverMakeLabelsOverlapOrDropThem) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(0.0, 600.0), y(0.0, 400.0);
  const cv::PixelBox area{{0.0, 0.0}, {600.0, 400.0}};
  cv::SegmentGrid lines(area, 4.0);
  for (int i = 0; i < 60; ++i) lines.add({x(rng), y(rng)}, {x(rng), y(rng)});
  // a segment far outside the area is clipped away, not drawn along the border
  lines.add({-500.0, -50.0}, {1200.0, -40.0});
  std::vector<std::string> texts;
  for (int i = 0; i < 120; ++i) texts.push_back(std::to_string(i * 7 + 100));
  std::vector<cv::LabelRequest> labels;
  for (int i = 0; i < 120; ++i) labels.push_back({{x(rng), y(rng)}, {8.0, -8.0}, texts[i], false});
  const auto plain = cv::placeLabels(labels, {}, mono, 1.0, area);
  const auto placed = cv::placeLabels(labels, {}, mono, 1.0, area, &lines);
  std::size_t shownPlain = 0, shown = 0, overPlain = 0, over = 0;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    shownPlain += plain[i].shown;
    shown += placed[i].shown;
    if (plain[i].shown) overPlain += lines.covered(plain[i]) > 0;
    if (!placed[i].shown) continue;
    over += lines.covered(placed[i]) > 0;
    for (std::size_t j = i + 1; j < placed.size(); ++j)
      EXPECT_FALSE(placed[j].shown && cv::boxesOverlap(placed[i], placed[j])) << i << " " << j;
  }
  EXPECT_GT(shown, 0.9 * static_cast<double>(shownPlain));
  EXPECT_LT(over, overPlain);
  // the top border row stays free: the far segment was clipped away
  EXPECT_EQ(lines.covered({true, {300.0, 1.0}, {500.0, 2.0}, false}), 0);
}

TEST(LabelLayout, ALabelKeepsOffAWindowOverTheSceneWhereItCan) {
  // "inside" asked to the right of its point, where the legend floats
  const cv::PixelBox area{{0.0, 0.0}, {400.0, 300.0}};
  const cv::PixelBox legend{{210.0, 100.0}, {400.0, 300.0}};
  cv::SegmentGrid lines(area, 4.0);
  lines.block(legend);
  const std::vector<cv::LabelRequest> labels{{{200.0, 150.0}, {30.0, 0.0}, "inside", true}};
  const auto placed = cv::placeLabels(labels, {}, mono, 1.0, area, &lines);
  ASSERT_TRUE(placed[0].shown);
  const glm::dvec2 lo = placed[0].centre - 0.5 * placed[0].size;
  const glm::dvec2 hi = placed[0].centre + 0.5 * placed[0].size;
  EXPECT_TRUE(hi.x <= legend.lo.x || lo.y >= legend.hi.y || hi.y <= legend.lo.y);
  // a window over every candidate: the label is still shown (the windows only steer)
  cv::SegmentGrid all(area, 4.0);
  all.block(area);
  EXPECT_TRUE(cv::placeLabels(labels, {}, mono, 1.0, area, &all)[0].shown);
}

TEST(LabelLayout, ContinuedLinesAreIndented) {
  const auto lines =
      cv::breakAtSpaces("1. k = floor(8*0.386316) = 3 -> cell 12", 7.0 * 16, mono, "  ");
  ASSERT_GT(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("1. ", 0), 0u);
  for (std::size_t i = 1; i < lines.size(); ++i) EXPECT_EQ(lines[i].rfind("  ", 0), 0u) << lines[i];
  // every word of the text stands whole on some line
  for (const char* word : {"floor(8*0.386316)", "->", "12"}) {
    bool whole = false;
    for (const std::string& l : lines) whole |= l.find(word) != std::string::npos;
    EXPECT_TRUE(whole) << word;
  }
}

// === the fit's room beside the Steps window and the legend

namespace {

// true when the two rectangles share area
bool overlap(const cv::ScreenRect& a, const cv::ScreenRect& b) {
  return a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y;
}

}  // namespace

TEST(FitRoom, TheStepsWindowGetsTheStripThatLeavesTheLargerDrawing) {
  const cv::ScreenRect full{{0.0, 0.0}, {1600.0, 900.0}};
  cv::CornerBoxes boxes;
  boxes.steps = {700.0, 300.0};
  const cv::ScreenRect steps{{10.0, 590.0}, {710.0, 890.0}};
  // a square scene: the left strip keeps 880 x 900, the bottom one 1600 x 580
  const cv::ScreenRect square = cv::roomBesideCorners(full, full, boxes, 1.0);
  EXPECT_FALSE(overlap(square, steps));
  EXPECT_GE(square.lo.x, 720.0);
  EXPECT_EQ(square.hi.y, 900.0);
  // a wide one (4:1): the bottom strip
  const cv::ScreenRect wide = cv::roomBesideCorners(full, full, boxes, 4.0);
  EXPECT_FALSE(overlap(wide, steps));
  EXPECT_EQ(wide.lo.x, 0.0);
  EXPECT_LE(wide.hi.y, 580.0);
  // no Steps window, or one clear of the fitted area: the fit is left as it was
  const cv::ScreenRect fitted{{800.0, 0.0}, {1600.0, 900.0}};
  EXPECT_EQ(cv::roomBesideCorners(fitted, full, {}, 1.0).lo, fitted.lo);
  EXPECT_EQ(cv::roomBesideCorners(fitted, full, boxes, 1.0).lo, fitted.lo);
}

TEST(FitRoom, TheLegendsStripIsChosenWithTheStepsWindows) {
  const cv::ScreenRect full{{0.0, 0.0}, {1920.0, 900.0}};
  cv::CornerBoxes boxes;
  boxes.steps = {900.0, 400.0};
  boxes.legend = {440.0, 300.0};
  const cv::ScreenRect steps{{10.0, 490.0}, {910.0, 890.0}};
  const cv::ScreenRect legend{{1490.0, 610.0}, {1910.0, 890.0}};
  // what the fit had: the legend's strip on the right
  const cv::ScreenRect fitted{{0.0, 0.0}, {1480.0, 900.0}};
  for (const double aspect : {0.5, 1.0, 2.0, 4.0}) {
    const cv::ScreenRect r = cv::roomBesideCorners(fitted, full, boxes, aspect);
    EXPECT_FALSE(overlap(r, steps)) << aspect;
    EXPECT_FALSE(overlap(r, legend)) << aspect;
    // as large a drawing as any of the four pairs of strips leaves
    const double h = std::min(r.size().x / aspect, r.size().y);
    EXPECT_GE(h, std::min((1480.0 - 920.0) / aspect, 900.0) - 1e-9) << aspect;
    EXPECT_GE(h, std::min(1920.0 / aspect, 480.0) - 1e-9) << aspect;
  }
  // a boxed-in scene: no strip keeps 40% of the drawing, the window floats
  boxes.steps = {1800.0, 800.0};
  const cv::ScreenRect kept = cv::roomBesideCorners(fitted, full, boxes, 1.0);
  EXPECT_EQ(kept.lo, fitted.lo);
  EXPECT_EQ(kept.hi, fitted.hi);
}
