// Lectures that survive mistakes: every problem reported at once as FILE:LINE naming the bad
// value, the other slides kept; --check's report and exit code; speaker notes; the problems
// shown over a slide until dismissed; Why O(1)'s recorded timings, read back exactly and
// true to the shipped lecture's caption.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "logic/app/lecture.hpp"
#include "logic/app/model.hpp"
#include "logic/app/option_values.hpp"
#include "logic/teach/scaling_record.hpp"

namespace cv = convexloc::viewer;
namespace fs = std::filesystem;

namespace {

// a folder of this test's own under the system's temporary one, made empty
fs::path scratchDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("convexloc-lecture-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

}  // namespace

TEST(LectureProblems, ThreeMistakesGiveThreeLinesAndTheOtherSlidesStay) {
  const fs::path dir = scratchDir("three");
  writeFile(dir / "talk.lecture",
            "slide One\n"           // 1
            "methd polar\n"         // 2: a typo of a key
            "spray 100\n"           // 3
            "slide Two\n"           // 4
            "method wedge\n"        // 5
            "slide Three\n"         // 6
            "probe 1.2,0.5x\n"      // 7: a bad number
            "slide Four\n"          // 8
            "shape missing.txt\n"   // 9: a file that is not there
            "slide Five\n"          // 10
            "generate regular\n");  // 11
  const cv::ParsedLecture p = cv::loadLecture((dir / "talk.lecture").string());
  const std::string file = (dir / "talk.lecture").string();
  ASSERT_EQ(p.problems.size(), 3u);
  EXPECT_EQ(p.problems[0], file + ":2: unknown key 'methd' (did you mean method?)");
  EXPECT_EQ(p.problems[1].rfind(file + ":7: probe needs X,Y or X,Y,Z", 0), 0u) << p.problems[1];
  EXPECT_TRUE(contains(p.problems[1], "'0.5x' is not a number")) << p.problems[1];
  EXPECT_EQ(p.problems[2].rfind(file + ":9: shape: file 'missing.txt' not found", 0), 0u);
  // the resolved path, beside the lecture, is named
  EXPECT_TRUE(contains(p.problems[2], (dir / "missing.txt").lexically_normal().string()))
      << p.problems[2];
  // every slide stays, the spoilt ones marked; their good lines are kept
  ASSERT_EQ(p.lecture.slides.size(), 5u);
  EXPECT_EQ(p.lecture.goodSlides(), 2u);
  EXPECT_FALSE(p.lecture.slides[0].good());
  EXPECT_EQ(p.lecture.slides[0].options.spray, 100u);
  EXPECT_TRUE(p.lecture.slides[1].good());
  EXPECT_TRUE(p.lecture.slides[4].good());
  cv::SlideShow show;
  show.lecture = p.lecture;
  EXPECT_EQ(show.goodFrom(0), 1u);
  EXPECT_EQ(show.goodFrom(2), 4u);
  EXPECT_EQ(show.goodFrom(5), 5u);
  // the other slides play
  cv::Model m;
  EXPECT_EQ(show.go(m, 1), "");
  EXPECT_EQ(show.go(m, 4), "");
  // a spoilt slide is shown with what it gave well, its problems over it
  EXPECT_EQ(show.go(m, 0), "");
  EXPECT_EQ(show.shownProblems(), std::vector<std::string>{p.problems[0]});
}

TEST(LectureProblems, TheSceneRefusalsGetTheLineOfTheirKey) {
  const fs::path dir = scratchDir("scene");
  // a shape file that is there but no convex polygon
  writeFile(dir / "bowtie.txt", "0 0\n2 2\n2 0\n0 2\n");
  writeFile(dir / "talk.lecture",
            "slide Good\nmethod polar\n"
            "slide Bowtie\nspray 0\nshape bowtie.txt\n"
            "slide Preset\npreset no-such-preset\n");
  cv::ParsedLecture p = cv::loadLecture((dir / "talk.lecture").string());
  ASSERT_TRUE(p.clean());
  cv::Model scratch;
  cv::checkSlides(p, scratch);
  const std::string file = (dir / "talk.lecture").string();
  ASSERT_EQ(p.problems.size(), 2u) << p.problems.front();
  EXPECT_EQ(p.problems[0].rfind(file + ":5: slide 'Bowtie': ", 0), 0u) << p.problems[0];
  EXPECT_EQ(p.problems[1].rfind(file + ":7: slide 'Preset': ", 0), 0u) << p.problems[1];
  EXPECT_TRUE(p.lecture.slides[0].good());
  std::string out;
  EXPECT_EQ(cv::checkReport(p, out), 1);
  EXPECT_TRUE(contains(out, "2 problems; 3 slides, 2 of them not shown as written")) << out;
}

TEST(LectureProblems, EverySceneProblemOfASlideIsReportedAtItsKeysLineInOrder) {
  const fs::path dir = scratchDir("keys");
  writeFile(dir / "talk.lecture",
            "slide Cube\n"         // 1
            "generate geodesic\n"  // 2
            "method cubemap\n"     // 3
            "probe 0.5,0.5\n"      // 4: two numbers on a polyhedron
            "resolution 100000\n"  // 5: past the cube map's largest
            "slide Polygon\n"      // 6
            "generate regular\n"   // 7
            "cell 3\n"             // 8: a 3D key on a polygon
            "method cubemap\n"     // 9: a 3D method on a polygon
            "slide Pinned\n"       // 10
            "generate geodesic\n"  // 11
            "method cubemap\n"     // 12
            "cell 999999\n");      // 13: no such cell
  cv::ParsedLecture p = cv::loadLecture((dir / "talk.lecture").string());
  ASSERT_TRUE(p.clean()) << p.problems.front();
  cv::Model scratch;
  cv::checkSlides(p, scratch);
  const std::string file = (dir / "talk.lecture").string();
  ASSERT_EQ(p.problems.size(), 5u);
  EXPECT_EQ(p.problems[0].rfind(file + ":4: slide 'Cube': probe X,Y is for a 2D scene", 0), 0u)
      << p.problems[0];
  EXPECT_EQ(p.problems[1].rfind(file + ":5: slide 'Cube': ", 0), 0u) << p.problems[1];
  EXPECT_TRUE(contains(p.problems[1], "resolution")) << p.problems[1];
  EXPECT_EQ(p.problems[2].rfind(file + ":8: slide 'Polygon': cell is for a 3D scene", 0), 0u)
      << p.problems[2];
  EXPECT_EQ(p.problems[3].rfind(file + ":9: slide 'Polygon': 'cubemap' is a 3D method", 0), 0u)
      << p.problems[3];
  EXPECT_EQ(p.problems[4].rfind(file + ":13: slide 'Pinned': cell 999999: the scene has ", 0), 0u)
      << p.problems[4];
  EXPECT_TRUE(contains(p.problems[4], " cells (0 .. ")) << p.problems[4];
}

TEST(LectureProblems, ACameraElevationPastTheVerticalIsNamed) {
  const fs::path dir = scratchDir("camera");
  writeFile(dir / "talk.lecture",
            "slide Cube\ngenerate geodesic\ncamera 30,95,fit\n"
            "slide Down\ngenerate geodesic\ncamera 30,-90,fit\n");
  const cv::ParsedLecture p = cv::loadLecture((dir / "talk.lecture").string());
  const std::string file = (dir / "talk.lecture").string();
  ASSERT_EQ(p.problems.size(), 1u);
  EXPECT_EQ(p.problems[0], file + ":3: camera: the elevation 95 is not within -90 .. 90 degrees");
  EXPECT_TRUE(p.lecture.slides[1].good());
}

TEST(LectureProblems, CheckExitsZeroWithOneLineOnTheShippedLecture) {
  cv::Options o;
  o.checkFile = std::string(CONVEXLOC_SOURCE_DIR) + "/assets/lectures/paper.lecture";
  std::string out, err;
  EXPECT_EQ(cv::lectureReport(o, out, err), 0) << out;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << out;
  EXPECT_TRUE(contains(out, ": OK, ")) << out;
  // a lecture that cannot be read: one problem with where it was looked for, exit 1
  o.checkFile = "/no/such/talk.lecture";
  out.clear();
  EXPECT_EQ(cv::lectureReport(o, out, err), 1);
  EXPECT_EQ(out.rfind("/no/such/talk.lecture: cannot be read", 0), 0u) << out;
}

TEST(LectureProblems, ProblemsBeforeTheFirstSlideShowOnItUntilDismissed) {
  const cv::ParsedLecture p = cv::parseLecture(
      "method polar\nslide A\nspray 0\nslide B\nresolution lots\nslide C\n", "t.lecture");
  ASSERT_EQ(p.problems.size(), 2u);
  EXPECT_EQ(p.problems[0].rfind("t.lecture:1: 'method' comes before any slide", 0), 0u);
  EXPECT_EQ(p.problems[1],
            "t.lecture:5: resolution needs a whole number from 0 (automatic) to "
            "2^26, not 'lots'");
  cv::SlideShow show;
  show.lecture = p.lecture;
  cv::Model m;
  ASSERT_EQ(show.go(m, 0), "");
  EXPECT_EQ(show.shownProblems(), std::vector<std::string>{p.problems[0]});
  show.dismiss();
  EXPECT_TRUE(show.shownProblems().empty());
  ASSERT_EQ(show.go(m, 1), "");
  EXPECT_EQ(show.shownProblems(), std::vector<std::string>{p.problems[1]});
  show.dismiss();
  EXPECT_TRUE(show.shownProblems().empty());
  ASSERT_EQ(show.go(m, 2), "");
  EXPECT_TRUE(show.shownProblems().empty());
  // dismissed stays dismissed when the lecturer comes back
  ASSERT_EQ(show.go(m, 0), "");
  EXPECT_TRUE(show.shownProblems().empty());
}

TEST(LectureProblems, NotesRepeatAndArePrintedWithTheSlideNumberAndTitle) {
  const cv::ParsedLecture p = cv::parseLecture(
      "slide First\nnotes Say hello.\nnotes \"Then  the question.\"\nmethod wedge\n"
      "slide Second\nslide Third\nnotes\nnotes last\n",
      "t.lecture");
  ASSERT_TRUE(p.clean()) << p.problems.front();
  EXPECT_EQ(p.lecture.slides[0].notes,
            (std::vector<std::string>{"Say hello.", "Then  the question."}));
  // notes are the lecturer's, never an option
  EXPECT_FALSE(p.lecture.slides[0].gives("notes"));
  EXPECT_EQ(p.lecture.slides[0].options.method, "wedge");
  EXPECT_EQ(cv::notesText(p.lecture),
            "1. First\n   Say hello.\n   Then  the question.\n\n2. Second\n\n3. Third\n\n"
            "   last\n");
  std::string out;
  EXPECT_EQ(cv::checkReport(p, out), 0);
  EXPECT_EQ(out, "t.lecture: OK, 3 slides, 2 with notes\n");
}

TEST(LectureProblems, OptionsNameTheBadValueAndTheNearestName) {
  const auto error = [](std::vector<std::string_view> args) {
    return cv::parseOptions(args).error;
  };
  EXPECT_EQ(error({"--probe", "1.2,0.5x"}), "--probe needs X,Y or X,Y,Z ('0.5x' is not a number)");
  EXPECT_EQ(error({"--line", "-3", "1", "3", "2a"}),
            "--line needs X1 Y1 X2 Y2 ('2a' is not a number)");
  EXPECT_EQ(error({"--theme", "purple"}), "--theme needs dark or light, not 'purple'");
  EXPECT_TRUE(contains(error({"--method", "cubmap"}), "(did you mean cubemap?)"));
  EXPECT_FALSE(contains(error({"--method", "zzz"}), "did you mean"));
  const std::vector<std::string_view> words = {"method", "probe", "resolution"};
  EXPECT_EQ(cv::nearestWord("methd", words), "method");
  EXPECT_EQ(cv::nearestWord("porbe", words), "probe");  // two letters swapped
  EXPECT_EQ(cv::nearestWord("resolutoin", words), "resolution");
  EXPECT_EQ(cv::nearestWord("wobble", words), "");
}

// === Why O(1), recorded

TEST(WhyRecord, ARecordReadsBackExactly) {
  cv::ScalingResult r;
  r.series = {{convexloc::Method2D::Halfplane, {{8, 6.11, 0.0, 70.3125, 160}}},
              {convexloc::Method2D::Polar,
               {{8, 0.1, 0.8633333333333333, 4.1, 1556}, {64, 0.0, 1.5, 1.0 / 3.0, 2676}}}};
  r.memory = {{0.1, 20.0, 240.0, 532, 1544}};
  cv::ScalingConfig c;
  c.tracedPoints = 300;
  const std::string text = cv::scalingRecord(r, c);
  cv::ScalingResult back;
  cv::ScalingConfig cb;
  std::string error;
  ASSERT_TRUE(cv::parseScalingRecord(text, "w.txt", back, cb, error)) << error;
  EXPECT_EQ(cb.sizes, (std::vector<std::size_t>{8, 64}));
  EXPECT_TRUE(cb.faces.empty());
  ASSERT_EQ(back.series.size(), std::size(convexloc::kAllMethods2D));
  const auto& polar = back.series[4].samples;
  ASSERT_EQ(polar.size(), 2u);
  EXPECT_EQ(polar[1].nsPerQuery, 1.0 / 3.0);
  EXPECT_EQ(polar[0].cellEdges, 0.8633333333333333);
  EXPECT_EQ(back.memory.at(0).polarBytes, 1544u);
  EXPECT_EQ(cv::scalingRecord(back, cb), text);
  // a bad line: FILE:LINE naming it
  EXPECT_FALSE(
      cv::parseScalingRecord("convexloc-why 1\n2d polr 8 1 0 4 100\n", "w.txt", back, cb, error));
  EXPECT_EQ(error, "w.txt:2: unknown method 'polr' for 2d");
  EXPECT_FALSE(cv::parseScalingRecord("slide A\n", "w.txt", back, cb, error));
  EXPECT_EQ(error.rfind("w.txt:1: not a Why O(1) record", 0), 0u);
}

// The shipped lecture's Why O(1) slide reads the shipped record, and its caption says what
// the recorded curves show: the half-planes' tests grow with N, the wedges' with lg N, the
// slab method's stay flat (its search compares numbers) while its time grows.
TEST(WhyRecord, TheShippedSlideReadsItsRecordAndTheCaptionIsTrue) {
  const cv::ParsedLecture p =
      cv::loadLecture(std::string(CONVEXLOC_SOURCE_DIR) + "/assets/lectures/paper.lecture");
  ASSERT_TRUE(p.clean());
  const auto why = std::find_if(p.lecture.slides.begin(), p.lecture.slides.end(),
                                [](const cv::Slide& s) { return !s.options.whyFrom.empty(); });
  ASSERT_NE(why, p.lecture.slides.end());
  cv::ScalingResult r;
  cv::ScalingConfig c;
  std::string error;
  ASSERT_TRUE(cv::readScalingRecord(why->options.whyFrom, r, c, error)) << error;
  const auto growth = [&](convexloc::Method2D m, double cv::ScalingSample::*what) {
    const auto& s = r.series[static_cast<std::size_t>(m)].samples;
    return s.back().*what / s.front().*what;
  };
  using convexloc::Method2D;
  const double lgGrowth = std::log2(static_cast<double>(c.sizes.back())) /
                          std::log2(static_cast<double>(c.sizes.front()));
  EXPECT_GT(growth(Method2D::Halfplane, &cv::ScalingSample::predicates), 1000.0);
  EXPECT_GT(growth(Method2D::Wedge, &cv::ScalingSample::predicates), 0.5 * lgGrowth);
  EXPECT_LT(growth(Method2D::Slab, &cv::ScalingSample::predicates), 1.1);
  EXPECT_GT(growth(Method2D::Slab, &cv::ScalingSample::nsPerQuery), 1.5);
  EXPECT_LT(growth(Method2D::Uniform, &cv::ScalingSample::predicates), 1.1);
  EXPECT_TRUE(contains(why->caption, "slab")) << why->caption;
  EXPECT_TRUE(contains(why->caption, "flat")) << why->caption;
  // shown on a model: finished at once, nothing measured
  cv::Model m;
  ASSERT_EQ(m.apply(why->options), "");
  EXPECT_TRUE(m.whyOpen);
  EXPECT_TRUE(m.scaling->snapshot().finished);
  EXPECT_FALSE(m.scaling->running());
}

TEST(LectureProblems, KeyLinesEndAtACommentAndExtraValuesAreNamed) {
  const cv::ParsedLecture p = cv::parseLecture(
      "slide A #1\nfigure 6   # Fig. 6's settings\nstep 2 #\ncaption a # b\nnotes c # d\n",
      "t.lecture");
  ASSERT_TRUE(p.clean()) << p.problems.front();
  const cv::Slide& s = p.lecture.slides[0];
  EXPECT_EQ(s.title, "A #1");
  EXPECT_EQ(s.options.figure, 6);
  EXPECT_EQ(s.options.step, 2);
  EXPECT_EQ(s.caption, "a # b");
  EXPECT_EQ(s.notes, std::vector<std::string>{"c # d"});
  const cv::ParsedLecture q = cv::parseLecture("slide A\nn 3 4 5\nhide-ui now\n", "t.lecture");
  ASSERT_EQ(q.problems.size(), 2u);
  EXPECT_EQ(q.problems[0],
            "t.lecture:2: 'n' was given more values than it takes ('4 5' is left "
            "over)");
  EXPECT_EQ(q.problems[1],
            "t.lecture:3: 'hide-ui' was given more values than it takes ('now' is "
            "left over)");
}

// a lecturer writes a lecture from docs/viewer.md: its example of the format is a clean
// lecture (its shape path read beside the shipped lecture, as the example says)
TEST(LectureProblems, TheDocumentedExampleIsACleanLecture) {
  std::ifstream in(std::string(CONVEXLOC_SOURCE_DIR) + "/docs/viewer.md");
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t start = doc.find("```text\nslide Polar query");
  ASSERT_NE(start, std::string::npos);
  const std::size_t from = doc.find('\n', start) + 1;
  const std::string example = doc.substr(from, doc.find("```", from) - from);
  const cv::ParsedLecture p = cv::parseLecture(
      example, "example.lecture", std::string(CONVEXLOC_SOURCE_DIR) + "/assets/lectures");
  EXPECT_TRUE(p.clean()) << p.problems.front();
  ASSERT_EQ(p.lecture.slides.size(), 2u);
  EXPECT_EQ(p.lecture.slides[0].options.step, 2);
  EXPECT_EQ(p.lecture.slides[0].notes.size(), 2u);
}

// `why PAGE` opens Why O(1) on that page on any slide: the 3D page over a 2D scene, the 2D
// page over a 3D one; without a page, the scene's
TEST(LectureProblems, WhyNamesThePageOnAnySlide) {
  const std::string record = std::string(CONVEXLOC_SOURCE_DIR) + "/assets/lectures/why-o1.txt";
  const cv::ParsedLecture p =
      cv::parseLecture("slide A\nwhy 3d\nwhy-from " + record + "\nslide B\n3d\nwhy-from " + record +
                           "\nslide C\n3d\nwhy 2d\nwhy-from " + record + "\nslide D\nspray 10\n",
                       "t.lecture");
  ASSERT_TRUE(p.clean()) << p.problems.front();
  EXPECT_EQ(p.lecture.slides[0].options.whyPage, "3d");
  EXPECT_TRUE(p.lecture.slides[0].options.why);
  EXPECT_EQ(p.lecture.slides[1].options.whyPage, "");
  cv::Model m;
  cv::SlideShow show;
  show.lecture = p.lecture;
  const struct {
    bool open, solid;
  } expected[] = {{true, true}, {true, true}, {true, false}, {false, false}};
  for (std::size_t k = 0; k < std::size(expected); ++k) {
    ASSERT_EQ(show.go(m, static_cast<std::ptrdiff_t>(k)), "");
    EXPECT_EQ(m.whyOpen, expected[k].open) << "slide " << k + 1;
    EXPECT_EQ(m.whySolid, expected[k].solid) << "slide " << k + 1;
  }
  EXPECT_EQ(m.dim, cv::Dim::Two);  // slide A's 2D scene stayed under its 3D page
  // the command line's name for it
  const cv::ParsedOptions o = cv::parseOptions(std::vector<std::string_view>{"--why-page", "3d"});
  EXPECT_EQ(o.error, "");
  EXPECT_EQ(o.options.whyPage, "3d");
}

// --check reports a page that is not one at its line, with the nearest page, and a second
// page as left over
TEST(LectureProblems, ABadWhyPageIsReportedAtItsLine) {
  const fs::path dir = scratchDir("why");
  writeFile(dir / "talk.lecture",
            "slide One\n"     // 1
            "method polar\n"  // 2
            "why 3D\n"        // 3: not a page
            "slide Two\n"     // 4
            "why 2d 3d\n"     // 5: two pages
            "slide Three\n"   // 6
            "why solid\n");   // 7: nothing near
  cv::Options o;
  o.checkFile = (dir / "talk.lecture").string();
  std::string out, err;
  EXPECT_EQ(cv::lectureReport(o, out, err), 1) << out;
  const std::string file = o.checkFile;
  EXPECT_TRUE(contains(out, file + ":3: the Why O(1) page is 2d (regular N-gons) or 3d (geodesic "
                                   "spheres), not '3D' (did you mean 3d?)\n"))
      << out;
  EXPECT_TRUE(contains(out, file + ":5: 'why' takes one page, 2d or 3d ('3d' is left over)\n"))
      << out;
  EXPECT_TRUE(contains(out, file + ":7: the Why O(1) page is 2d (regular N-gons) or 3d (geodesic "
                                   "spheres), not 'solid'\n"))
      << out;
  EXPECT_TRUE(contains(out, "3 problems; 3 slides, 3 of them not shown as written")) << out;
}
