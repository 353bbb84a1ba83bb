// The key queue: every press one action, in order, none merged or lost; the defects it
// fixes (three quick PageDowns advanced two slides, "Left Left" moved one step) replayed
// through the lecture and the model as the frame loop applies them.
#include <gtest/gtest.h>

#include <vector>

#include "logic/app/key_queue.hpp"
#include "logic/app/lecture.hpp"
#include "logic/app/model.hpp"

namespace cv = convexloc::viewer;
using cv::ActionKind;

namespace {

// key codes of this test's own (the window's are the platform's business)
enum Key : int { Next = 1, Prev, Left, Right, F12, Blank };

constexpr cv::KeyBinding kBindings[] = {
    {F12, {ActionKind::SaveSvg, 0}, false, true, 1},
    {F12, {ActionKind::Screenshot, 0}, false, true, 0},
    {Next, {ActionKind::NextSlide, 0}},
    {Prev, {ActionKind::PreviousSlide, 0}},
    {Blank, {ActionKind::ToggleBlank, 0}},
    {Left, {ActionKind::PrevStep, 0}, true},
    {Right, {ActionKind::NextStep, 0}, true},
};

std::vector<ActionKind> kinds(const std::vector<cv::Action>& actions) {
  std::vector<ActionKind> out;
  for (const cv::Action& a : actions) out.push_back(a.kind);
  return out;
}

// a lecture of five plain slides
cv::SlideShow fiveSlides() {
  const cv::ParsedLecture p = cv::parseLecture(
      "slide A\nspray 0\nslide B\nspray 0\nslide C\nspray 0\nslide D\nspray 0\nslide E\nspray 0\n",
      "t.lecture");
  EXPECT_TRUE(p.clean());
  cv::SlideShow show;
  show.lecture = p.lecture;
  return show;
}

}  // namespace

TEST(KeyQueue, EveryPressIsOneActionInOrder) {
  cv::KeyQueue q(kBindings);
  for (int key : {Next, Next, Left, Next, Prev}) q.press({key}, false);
  EXPECT_EQ(kinds(q.drain()), (std::vector<ActionKind>{ActionKind::NextSlide, ActionKind::NextSlide,
                                                       ActionKind::PrevStep, ActionKind::NextSlide,
                                                       ActionKind::PreviousSlide}));
  // drained whole: nothing is left for the next frame
  EXPECT_TRUE(q.empty());
  EXPECT_TRUE(q.drain().empty());
}

TEST(KeyQueue, RepeatsOnlyWhereTheKeyRepeatsAndTypingKeepsAllButF12) {
  cv::KeyQueue q(kBindings);
  q.press({Next, true}, false);   // a held PageDown does not run through the lecture
  q.press({Right, true}, false);  // a held arrow steps on
  q.press({Next}, true);          // typed into a text field
  q.press({F12}, true);           // a screenshot even then
  q.press({F12, false, true}, false);
  q.press({99}, false);  // unbound
  EXPECT_EQ(kinds(q.drain()), (std::vector<ActionKind>{ActionKind::NextStep, ActionKind::Screenshot,
                                                       ActionKind::SaveSvg}));
}

TEST(KeyQueue, ThreeQuickPageDownsAdvanceThreeSlides) {
  cv::KeyQueue q(kBindings);
  cv::SlideShow show = fiveSlides();
  cv::Model m;
  ASSERT_EQ(show.go(m, 0), "");
  // all three between two frames, as a quick clicker sends them
  for (int i = 0; i < 3; ++i) q.press({Next}, false);
  for (const cv::Action& a : q.drain())
    ASSERT_EQ(show.go(m, static_cast<std::ptrdiff_t>(show.target(a.kind))), "");
  EXPECT_EQ(show.current, 3u);
  // past the end: the last slide stays
  for (int i = 0; i < 3; ++i) q.press({Next}, false);
  for (const cv::Action& a : q.drain())
    ASSERT_EQ(show.go(m, static_cast<std::ptrdiff_t>(show.target(a.kind))), "");
  EXPECT_EQ(show.current, 4u);
}

TEST(KeyQueue, LeftLeftMovesTwoSteps) {
  cv::KeyQueue q(kBindings);
  cv::Model m;
  const cv::ParsedLecture p = cv::parseLecture(
      "slide S\ngenerate regular\nn 64\nmethod wedge\nprobe 0.3,0.2\nstep 5\nspray 0\n",
      "t.lecture");
  ASSERT_TRUE(p.clean());
  cv::SlideShow show;
  show.lecture = p.lecture;
  ASSERT_EQ(show.go(m, 0), "");
  ASSERT_EQ(m.step(), 4);
  q.press({Left}, false);
  q.press({Left}, false);
  for (const cv::Action& a : q.drain()) m.stepBy(a.kind == ActionKind::NextStep);
  EXPECT_EQ(m.step(), 2);
  // the first Right after a slide change counts
  ASSERT_EQ(show.go(m, 0), "");
  q.press({Right}, false);
  for (const cv::Action& a : q.drain()) m.stepBy(a.kind == ActionKind::NextStep);
  EXPECT_EQ(m.step(), 5);
}
