// Lecture files, the paper's figures, and the defects met on the way: the parser's
// FILE:LINE errors, slides that reset what the previous one set, figure presets, the drag
// message's vertex numbers, the Points panel's spray, a pinned 3D cell across methods.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "logic/app/lecture.hpp"
#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "logic/draw/y_gap.hpp"
#include "logic/narration/steps.hpp"
#include "logic/teach/figures.hpp"
#include "ui/ui_state.hpp"

namespace cv = convexloc::viewer;
using convexloc::Method3D;
using convexloc::Vec2;

namespace {

// every problem of a lecture, a line each
std::string joined(const cv::ParsedLecture& p) {
  std::string all;
  for (const std::string& line : p.problems) all += (all.empty() ? "" : "\n") + line;
  return all;
}

// the problems of a lecture text named "t.lecture"
std::string errorOf(const std::string& text) {
  return joined(cv::parseLecture(text, "t.lecture"));
}

cv::Options parsed(std::vector<std::string_view> args) {
  const cv::ParsedOptions p = cv::parseOptions(args);
  EXPECT_EQ(p.error, "");
  return p.options;
}

}  // namespace

// the shipped lecture, read
cv::Lecture shippedLecture() {
  const cv::ParsedLecture p =
      cv::loadLecture(std::string(CONVEXLOC_SOURCE_DIR) + "/assets/lectures/paper.lecture");
  EXPECT_TRUE(p.clean()) << joined(p);
  return p.lecture;
}

// the caption of the step a slide shows ("" without one)
std::string shownStep(const cv::Model& m) {
  const std::optional<cv::StepModel> steps = m.steps();
  if (!steps || m.step() < 0 || static_cast<std::size_t>(m.step()) >= steps->steps.size())
    return {};
  return steps->steps[static_cast<std::size_t>(m.step())].caption;
}

TEST(Lecture, ShippedLectureParsesWithEveryFigure) {
  const cv::ParsedLecture p =
      cv::loadLecture(std::string(CONVEXLOC_SOURCE_DIR) + "/assets/lectures/paper.lecture");
  ASSERT_TRUE(p.clean()) << joined(p);
  EXPECT_GE(p.lecture.slides.size(), 20u);
  EXPECT_LE(p.lecture.slides.size(), 28u);
  std::vector<bool> seen(cv::kFigureCount + 1, false);
  for (const cv::Slide& s : p.lecture.slides) {
    EXPECT_FALSE(s.title.empty());
    if (s.options.figure) seen[static_cast<std::size_t>(*s.options.figure)] = true;
  }
  for (int n = 1; n <= cv::kFigureCount; ++n) EXPECT_TRUE(seen[static_cast<std::size_t>(n)]) << n;
}

TEST(Lecture, SlidesKeysAndCaptions) {
  const cv::ParsedLecture p = cv::parseLecture(
      "# a comment\n\nslide First one\ncaption Two words, and more\nmethod wedge\n"
      "probe 0.5,0.25\nslide Second\nfigure 4\nresolution 9\n",
      "t.lecture");
  ASSERT_TRUE(p.clean()) << joined(p);
  ASSERT_EQ(p.lecture.slides.size(), 2u);
  const cv::Slide& a = p.lecture.slides[0];
  EXPECT_EQ(a.title, "First one");
  EXPECT_EQ(a.line, 3u);
  EXPECT_EQ(a.caption, "Two words, and more");
  EXPECT_EQ(a.options.method, "wedge");
  ASSERT_TRUE(a.options.probe);
  EXPECT_EQ(a.options.probe->y, 0.25);
  EXPECT_TRUE(a.gives("probe"));
  // the first slide gives the lecture the slides' look unless it names its own
  EXPECT_TRUE(a.gives("theme"));
  EXPECT_EQ(a.options.theme, cv::Theme::Light);
  EXPECT_EQ(a.options.fontScale, 2.0f);
  EXPECT_TRUE(a.options.hideUi);
  // figure 4's settings, overridden by the key after it
  const cv::Slide& b = p.lecture.slides[1];
  EXPECT_EQ(b.options.figure, 4);
  EXPECT_EQ(b.options.method, "uniform");
  EXPECT_EQ(b.options.resolution, 9u);
}

TEST(Lecture, AFirstSlidesOwnLookIsKept) {
  const cv::ParsedLecture dark =
      cv::parseLecture("slide A\ntheme dark\nfont-scale 1.5\nslide B\n", "t.lecture");
  ASSERT_TRUE(dark.clean()) << joined(dark);
  const cv::Slide& a = dark.lecture.slides[0];
  EXPECT_EQ(a.options.theme, cv::Theme::Dark);
  EXPECT_EQ(a.options.fontScale, 1.5f);
  EXPECT_TRUE(a.options.hideUi);
  // a first slide with a table to read keeps its panels and gets no hide-ui beside show-ui
  const cv::ParsedLecture table = cv::parseLecture("slide A\nshow-ui\n", "t.lecture");
  ASSERT_TRUE(table.clean()) << joined(table);
  EXPECT_FALSE(table.lecture.slides[0].gives("hide-ui"));
  EXPECT_FALSE(table.lecture.slides[0].options.hideUi);
}

TEST(Lecture, ErrorsNameFileAndLine) {
  EXPECT_EQ(errorOf("slide A\nmethod polar\nwobble 3\n"), "t.lecture:3: unknown key 'wobble'");
  EXPECT_EQ(errorOf("\n\nslide A\nresolution lots\n").rfind("t.lecture:4: resolution needs", 0),
            0u);
  EXPECT_EQ(errorOf("# intro\nmethod polar\nslide A\n")
                .rfind("t.lecture:2: 'method' comes before "
                       "any slide",
                       0),
            0u);
  EXPECT_EQ(errorOf("slide A\ncaption \"never closed\nslide B\n")
                .rfind("t.lecture:2: unterminated quote", 0),
            0u);
  EXPECT_EQ(errorOf("slide A\nshape \"my file.txt\n").rfind("t.lecture:2: unterminated quote", 0),
            0u);
  EXPECT_EQ(errorOf("slide A\nn 3 4\n").rfind("t.lecture:2: 'n' was given more values", 0), 0u);
  EXPECT_EQ(errorOf("slide A\nsize 800x600\n").rfind("t.lecture:2: 'size' is not a slide key", 0),
            0u);
  EXPECT_EQ(errorOf("slide A\nfigure 9\n").rfind("t.lecture:2: figure needs", 0), 0u);
  // options that exclude each other: the slide's line
  EXPECT_EQ(
      errorOf("\nslide A\npreset sliver\ngenerate regular\n").rfind("t.lecture:2: slide 'A'", 0),
      0u);
  EXPECT_EQ(errorOf("# nothing\n"), "t.lecture:1: no slides (start one with: slide TITLE)");
  EXPECT_EQ(
      joined(cv::loadLecture("/no/such.lecture")).rfind("/no/such.lecture: cannot be read", 0), 0u);
}

TEST(Figures, EveryFigureParsesAndIsLight) {
  for (int n = 1; n <= cv::kFigureCount; ++n) {
    const std::string number = std::to_string(n);
    const cv::Options o = parsed({"--figure", number});
    EXPECT_EQ(o.figure, n);
    EXPECT_EQ(o.theme, cv::Theme::Light) << n;
    EXPECT_TRUE(o.hideUi) << n;
    EXPECT_TRUE(o.method.has_value()) << n;
    EXPECT_FALSE(cv::figure(n).caption.empty());
    EXPECT_EQ(o.caption, cv::figure(n).caption) << n;
  }
  // later options override the figure's
  EXPECT_EQ(parsed({"--figure", "1", "--method", "wedge"}).method, "wedge");
  EXPECT_NE(cv::parseOptions(std::vector<std::string_view>{"--figure", "0"}).error, "");
  EXPECT_NE(cv::parseOptions(std::vector<std::string_view>{"--export", "d"}).error, "");
}

TEST(Figures, Figure5MarksTheSmallestGapAndThePapersCount) {
  cv::Model m;
  ASSERT_EQ(m.apply(parsed({"--figure", "5"})), "");
  EXPECT_TRUE(m.settings.view2d.showGap);
  const auto g = cv::smallestYGap(m.scene2d.polygon());
  ASSERT_TRUE(g);
  EXPECT_NEAR(g->gap(), 0.05, 1e-12);
  EXPECT_NEAR(g->paperSlabs(), 2.4 / 0.05, 1e-6);
  // convexloc's own count stays bounded, far below the paper's
  EXPECT_LT(m.scene2d.effectiveResolution(), g->paperSlabs());
}

TEST(Figures, Figure7PinsAOneFaceCellAndACrowdedOneWithoutThePlane) {
  cv::Model m;
  ASSERT_EQ(m.apply(parsed({"--figure", "7"})), "");
  ASSERT_EQ(m.dim, cv::Dim::Three);
  EXPECT_FALSE(m.settings.view3d.showSlice);
  const cv::Scene3D& s = m.scene3d();
  ASSERT_GE(s.pinnedCell(), 0);
  ASSERT_GE(s.secondPinnedCell(), 0);
  EXPECT_EQ(s.cells()[static_cast<std::size_t>(s.pinnedCell())].faces.size(), 1u);
  EXPECT_GT(s.cells()[static_cast<std::size_t>(s.secondPinnedCell())].faces.size(), 1u);
}

TEST(Lecture, ASlideResetsWhatThePreviousOneSet) {
  const cv::ParsedLecture p = cv::parseLecture(
      "slide A\nmethod wedge\nprobe 0.1,0.1\nspray 500\nline -3 1 3 2\nslide B\ncaption plain\n",
      "t.lecture");
  ASSERT_TRUE(p.clean()) << joined(p);
  cv::Model m;
  cv::SlideShow show;
  show.lecture = p.lecture;
  ASSERT_EQ(show.go(m, 0), "");
  EXPECT_TRUE(m.scene2d.probe());
  EXPECT_EQ(m.scene2d.points().size(), 500u);
  EXPECT_TRUE(m.lines2d.enabled());
  ASSERT_EQ(show.go(m, 5), "");  // clamped to the last
  EXPECT_EQ(show.current, 1u);
  EXPECT_FALSE(m.scene2d.probe());
  EXPECT_FALSE(m.lines2d.enabled());
  EXPECT_EQ(m.scene2d.method(), cv::Model().scene2d.method());
  EXPECT_EQ(m.scene2d.points().size(), cv::Model().scene2d.points().size());
}

TEST(Defects, DragMessageCountsVerticesAsTheLabelsDo) {
  cv::Scene2D s;
  const std::vector<Vec2> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  ASSERT_TRUE(s.setShape(square, "square"));
  s.beginDrag(0);
  EXPECT_FALSE(s.dragTo({1.5, 1.5}));  // vertex 0 made reflex
  ASSERT_TRUE(s.drag());
  EXPECT_NE(s.drag()->message.find("vertex 0 "), std::string::npos) << s.drag()->message;
  EXPECT_EQ(s.drag()->message.find("vertex 1 "), std::string::npos) << s.drag()->message;
}

TEST(Defects, PointsPanelStartsFromTheScenesSpray) {
  cv::Model m;
  ASSERT_EQ(m.apply(parsed({"--spray", "2000"})), "");
  cv::UiState ui;
  cv::followSpray(ui, m.scene2d.spraySettings());
  EXPECT_EQ(ui.sprayCount, 2000);
  // the user's edit stays until the scene's settings change
  ui.sprayCount = 7000;
  cv::followSpray(ui, m.scene2d.spraySettings());
  EXPECT_EQ(ui.sprayCount, 7000);
  m.scene2d.spray({4000, 3, true});
  cv::followSpray(ui, m.scene2d.spraySettings());
  EXPECT_EQ(ui.sprayCount, 4000);
  EXPECT_EQ(ui.spraySeed, 3u);
  EXPECT_TRUE(ui.sprayNear);
}

TEST(Defects, PinnedCellSurvivesMethodsTwoThenThree) {
  cv::Scene3D s;
  s.pin(5);
  const auto face = s.cells()[5].faces;
  s.setMethod(Method3D::Walk);
  EXPECT_EQ(s.pinnedCell(), -1);  // the walk has no cells
  s.setMethod(Method3D::Cubemap);
  EXPECT_EQ(s.pinnedCell(), 5);
  EXPECT_EQ(s.cells()[5].faces, face);
  s.pin(-1);
  s.setMethod(Method3D::Walk);
  s.setMethod(Method3D::Cubemap);
  EXPECT_EQ(s.pinnedCell(), -1);
}

TEST(Defects, HelpNamesEveryKey) {
  const std::string help = cv::usageText();
  for (const char* key : {"T theme (dark/light)", "PageDown", "--figure", "--lecture", "--export",
                          "--slice AXIS=V|none", "--y-gap"})
    EXPECT_NE(help.find(key), std::string::npos) << key;
}

TEST(Defects, DocsTinyEdgesExampleShowsTheBisection) {
  // docs/viewer.md: --preset tiny-edges --probe 0.99,0.96 (a crowded cell, past its radii)
  cv::Model m;
  ASSERT_EQ(m.apply(parsed({"--preset", "tiny-edges", "--probe", "0.99,0.96"})), "");
  ASSERT_TRUE(m.scene2d.probe());
  const auto& t = m.scene2d.probe()->trace;
  EXPECT_TRUE(t.crowded);
  EXPECT_FALSE(t.byRadius);
  EXPECT_GE(t.rays.size(), 2u);
}

TEST(Lecture, AFigureSlideWithoutCaptionSaysWhatTheFigureShows) {
  const cv::ParsedLecture p =
      cv::parseLecture("slide A\nfigure 3\nslide B\nfigure 3\ncaption mine\n", "t.lecture");
  ASSERT_TRUE(p.clean()) << joined(p);
  EXPECT_EQ(p.lecture.slides[0].caption, cv::figure(3).caption);
  EXPECT_EQ(p.lecture.slides[1].caption, "mine");
  EXPECT_EQ(p.lecture.slides[1].options.caption, "mine");
  // a caption before the figure is kept too
  const cv::ParsedLecture q = cv::parseLecture("slide A\ncaption first\nfigure 2\n", "t.lecture");
  ASSERT_TRUE(q.clean()) << joined(q);
  EXPECT_EQ(q.lecture.slides[0].options.caption, "first");
}

TEST(Lecture, ShippedLectureStepsThroughEachMethodsQuery) {
  // each method's query shown a step at a time, the polar one as the paper runs it
  const cv::Lecture l = shippedLecture();
  std::vector<std::string> stepped;
  bool polarRadii = false, cubemapStep = false;
  cv::Model m;
  cv::SlideShow show;
  show.lecture = l;
  for (std::size_t k = 0; k < l.slides.size(); ++k) {
    const cv::Options& o = l.slides[k].options;
    if (o.why) continue;  // measured in a worker thread: the smoke test shows it
    ASSERT_EQ(show.go(m, static_cast<std::ptrdiff_t>(k)), "") << l.slides[k].title;
    if (o.step < 1) continue;
    const std::string step = shownStep(m);
    EXPECT_FALSE(step.empty()) << l.slides[k].title;
    if (m.dim == cv::Dim::Three) {
      cubemapStep = cubemapStep || o.paper;
      continue;
    }
    const std::string method(convexloc::toString(m.scene2d.method()));
    if (method == "polar" && !o.paper) {
      polarRadii = step.find("radii") != std::string::npos;
      continue;
    }
    stepped.push_back(method + ": " + step.substr(0, step.find(':')));
  }
  const auto seen = [&](std::string_view prefix) {
    return std::any_of(stepped.begin(), stepped.end(),
                       [&](const std::string& s) { return s.starts_with(prefix); });
  };
  for (const char* prefix : {"wedge: ray", "slab: probe", "uniform: eq. (4)", "polar: octant",
                             "polar: ratio", "polar: edge"})
    EXPECT_TRUE(seen(prefix)) << prefix;
  EXPECT_TRUE(polarRadii) << "a slide shows convexloc's radius filter deciding";
  EXPECT_TRUE(cubemapStep) << "a slide steps through the cube map's query";
}

TEST(Lecture, ShippedLectureHasTheTeachingViews) {
  const cv::Lecture l = shippedLecture();
  const auto any = [&](auto pred) { return std::any_of(l.slides.begin(), l.slides.end(), pred); };
  EXPECT_TRUE(any([](const cv::Slide& s) { return s.options.split.has_value(); }));
  EXPECT_TRUE(any([](const cv::Slide& s) { return s.options.buildStep.has_value(); }));
  EXPECT_TRUE(any([](const cv::Slide& s) { return s.options.why; }));
  EXPECT_TRUE(any([](const cv::Slide& s) { return s.options.line.has_value(); }));
  EXPECT_TRUE(any([](const cv::Slide& s) { return s.options.plane.has_value(); }));
  // the 3D dual right after the 2D one
  for (std::size_t k = 0; k + 1 < l.slides.size(); ++k)
    if (l.slides[k].options.line) {
      EXPECT_TRUE(l.slides[k + 1].options.plane.has_value());
    }
  // every caption short enough for two lines at text scale 2
  for (const cv::Slide& s : l.slides) EXPECT_LE(s.caption.size(), 150u) << s.title;
}

TEST(Lecture, ShowUiParsesAndExcludesHidingThePanels) {
  const cv::Options o = parsed({"--show-ui"});
  EXPECT_TRUE(o.showUi);
  EXPECT_FALSE(o.hideUi);
  // over a figure's own --hide-ui
  const cv::Options f = parsed({"--figure", "3", "--show-ui"});
  EXPECT_TRUE(f.showUi);
  EXPECT_FALSE(f.hideUi);
  using Args = std::vector<std::string_view>;
  EXPECT_NE(cv::parseOptions(Args{"--show-ui", "--hide-ui"}).error, "");
  EXPECT_NE(cv::parseOptions(Args{"--present", "--show-ui"}).error, "");
  EXPECT_NE(cv::usageText().find("--show-ui"), std::string::npos);
  EXPECT_NE(cv::usageText().find("--no-steps"), std::string::npos);
}

TEST(Lecture, AShowUiSlideShowsThePanelsForItselfAlone) {
  const cv::ParsedLecture p = cv::parseLecture(
      "slide A\nhide-ui\nslide B\nshow-ui\ncompare\nslide C\nmethod wedge\n", "t.lecture");
  ASSERT_TRUE(p.clean()) << joined(p);
  cv::Model m;
  cv::SlideShow show;
  show.lecture = p.lecture;
  ASSERT_EQ(show.go(m, 0), "");
  EXPECT_FALSE(m.settings.showUi);
  ASSERT_EQ(show.go(m, 1), "");
  EXPECT_TRUE(m.settings.showUi);
  EXPECT_FALSE(m.settings.present);
  ASSERT_EQ(show.go(m, 2), "");
  EXPECT_FALSE(m.settings.showUi);
  // back and forth: the lecture's look stays the first slide's
  ASSERT_EQ(show.go(m, 1), "");
  EXPECT_TRUE(m.settings.showUi);
  ASSERT_EQ(show.go(m, 0), "");
  EXPECT_FALSE(m.settings.showUi);
}

// a show opened at a later slide (--slide K, the web page's link to a slide) has the first
// slide's look all the same
TEST(Lecture, AShowOpenedAtALaterSlideHasTheLecturesLook) {
  const cv::ParsedLecture p = cv::parseLecture(
      "slide A\ntheme light\nfont-scale 2\nhide-ui\nslide B\nmethod wedge\nslide C\n", "t.lecture");
  ASSERT_TRUE(p.clean()) << joined(p);
  cv::Model m;
  cv::SlideShow show;
  show.lecture = p.lecture;
  ASSERT_EQ(show.go(m, 1), "");
  EXPECT_EQ(show.current, 1u);
  EXPECT_EQ(m.settings.theme, cv::Theme::Light);
  EXPECT_EQ(m.settings.fontScale, 2.0f);
  EXPECT_FALSE(m.settings.showUi);
  ASSERT_EQ(show.go(m, 2), "");
  EXPECT_EQ(m.settings.theme, cv::Theme::Light);
}

TEST(Lecture, ALaterSlidesTextSizeIsItsOwn) {
  const cv::ParsedLecture p = cv::parseLecture(
      "slide A\nfont-scale 2\ntheme light\nslide B\nfont-scale 1.25\nslide C\n", "t.lecture");
  ASSERT_TRUE(p.clean()) << joined(p);
  cv::Model m;
  cv::SlideShow show;
  show.lecture = p.lecture;
  ASSERT_EQ(show.go(m, 0), "");
  ASSERT_EQ(show.go(m, 1), "");
  EXPECT_EQ(m.settings.fontScale, 1.25f);
  ASSERT_EQ(show.go(m, 2), "");
  EXPECT_EQ(m.settings.fontScale, 2.0f);
  EXPECT_EQ(m.settings.theme, cv::Theme::Light);
}

// a lecture that opens on a figure shows it as the figure looks (light, large, no panels)
TEST(Lecture, AFigureSlideBringsItsOwnLook) {
  const cv::ParsedLecture p =
      cv::parseLecture("slide Polar\nfigure 6\nstep 2\nslide After\nmethod wedge\n", "t.lecture");
  ASSERT_TRUE(p.clean()) << joined(p);
  cv::Model m;
  cv::SlideShow show;
  show.lecture = p.lecture;
  ASSERT_EQ(show.go(m, 0), "");
  EXPECT_EQ(m.settings.theme, cv::Theme::Light);
  EXPECT_FALSE(m.settings.showUi);
  EXPECT_GT(m.settings.fontScale, 1.0f);
  // the figure's look is the first slide's, so the lecture's
  ASSERT_EQ(show.go(m, 1), "");
  EXPECT_EQ(m.settings.theme, cv::Theme::Light);
}

TEST(Lecture, TeachingViewsDoNotLeakIntoTheNextSlide) {
  const cv::ParsedLecture p = cv::parseLecture(
      "slide Split\nmethod halfplane\nsplit polar\nprobe 0.1,0.1\nno-steps\n"
      "slide Build\nmethod polar\nbuild-step 3\n"
      "slide Planes\nplane -1 0 0.35 1 -0.5 0.1 0 1 0.45\n"
      "slide Plain\n3d\n",
      "t.lecture");
  ASSERT_TRUE(p.clean()) << joined(p);
  cv::Model m;
  cv::SlideShow show;
  show.lecture = p.lecture;
  ASSERT_EQ(show.go(m, 0), "");
  EXPECT_TRUE(m.split.enabled());
  EXPECT_FALSE(m.settings.stepBoxVisible);
  ASSERT_EQ(show.go(m, 1), "");
  EXPECT_FALSE(m.split.enabled());
  EXPECT_TRUE(m.settings.stepBoxVisible);
  EXPECT_TRUE(m.build.active);
  ASSERT_EQ(show.go(m, 2), "");
  EXPECT_FALSE(m.build.active);
  EXPECT_TRUE(m.planes3d.enabled());
  ASSERT_EQ(show.go(m, 3), "");
  EXPECT_FALSE(m.planes3d.enabled());
  EXPECT_EQ(m.dim, cv::Dim::Three);
}

TEST(Lecture, SlideStartsTheLectureAtASlideNumberedFromOne) {
  // --slide K (the web page's ?lecture=paper&slide=K)
  EXPECT_EQ(parsed({"--lecture", "x.lecture"}).slide, 1);
  EXPECT_EQ(parsed({"--lecture", "x.lecture", "--slide", "12"}).slide, 12);
  for (const char* bad : {"0", "-1", "two", "1.5", ""})
    EXPECT_NE(cv::parseOptions(std::vector<std::string_view>{"--slide", bad}).error, "") << bad;
}
