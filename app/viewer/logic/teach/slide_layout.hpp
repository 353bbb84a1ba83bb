// convexloc-viewer — a slide laid out once, GL-free: the page it sits on in the window
// (letterboxed), and the boxes on it (title, caption, Steps window, legend, the scene's
// room) with their wrapped lines. The window's ImGui boxes, the PNG taken of them and the
// SVG writer all draw from this one layout, so that a slide reads the same at any size and
// its SVG shows what its PNG shows.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "logic/base/colour.hpp"
#include "logic/base/screen_rect.hpp"
#include "logic/base/text_layout.hpp"
#include "logic/narration/steps.hpp"

namespace convexloc::viewer {

// the logical page a slide is laid out on: 1920 x 1080 units (16:9)
inline constexpr glm::dvec2 kSlidePage{1920.0, 1080.0};

// the page scaled into a window, centred: bars (the theme's background) fill the rest
struct PageFit {
  ScreenRect page;     // the page's rectangle in window pixels
  double scale = 1.0;  // window pixels per page unit
};

// The page a slide is laid out on in `window`: `page` where the lecture gave its own or the
// window is not upright; in an upright window (a phone held upright: taller than kUpright
// times its width) a page of the window's aspect (at most kUprightMostAspect) and
// kUprightPageWidth units wide, so that the slide fills the screen, its figure over its
// Steps window and legend, its text as large as a landscape slide's on that screen turned.
glm::dvec2 slidePageIn(glm::dvec2 window, glm::dvec2 page, bool given);
inline constexpr double kUpright = 1.2;
inline constexpr double kUprightPageWidth = 960.0;
inline constexpr double kUprightMostAspect = 2.4;
// an upright page's Steps window: at most this share of the page's height
inline constexpr double kUprightStepsShare = 0.24;
// an upright page's text may shrink to this share of the slide's where the figure needs room
inline constexpr double kUprightLeastText = 0.75;

// the largest page of `page`'s aspect centred in `window` (pixels); a window without pixels
// gives an empty page at scale 1
PageFit fitPage(glm::dvec2 window, glm::dvec2 page = kSlidePage);

// the four bars of `outer` around `inner` (top, bottom, left, right; empty ones left out):
// the letterbox around a page, and a slide's page around its figure's room, which the
// figure never draws past
std::vector<ScreenRect> barsAround(ScreenRect outer, ScreenRect inner);

// the text's sizes, in window pixels, as the drawing measures them (ImGui's in the window)
struct SlideMetrics {
  double font = 16.0;     // the body text's height
  double spacing = 6.0;   // the gap between two lines
  double padding = 12.0;  // a box's inner padding
  double frame = 24.0;    // a button row's height (the Steps window's controls)
  double margin = 10.0;   // the gap between a box and the area's edges, or two boxes
  // the body text's width and height; `size` times the body size where asked
  MeasureText measure;
  // a text's width at `scale` times the body size (text widths grow with the font)
  double widthAt(std::string_view text, double scale) const;
};

// what the Steps window shows: the method's steps and code, the step shown, its controls
struct StepsContent {
  StepModel model;
  int step = -1;         // the step shown (-1: all)
  bool controls = true;  // the row of buttons (a slide shows none: its keys step)
  int codeWanted = -1;   // the pseudo-code: 1 whole, 0 the current line, -1 whole where wide
};

// a step's lines in the Steps window
struct StepLines {
  std::size_t step = 0;            // which step (from 0)
  std::vector<std::string> lines;  // "3. edge 2: orient2d = +1", broken at spaces
};

// the Steps window laid out
struct StepsLayout {
  ScreenRect box;
  bool sideBySide = false;           // the code in a column beside the steps
  bool wholeCode = false;            // all the code (else the current line alone)
  bool controls = false;             // the controls' two rows are there
  std::vector<std::string> heading;  // the method and point, and the trace's note
  double headingTop = 0.0;           // the heading's first line's top
  double controlsTop = 0.0;          // the controls' two rows' top (none: the list's separator)
  std::vector<StepLines> shown;      // the steps shown (a long list: a window around the current)
  double listTop = 0.0;              // the first step line's top; the separator is a spacing above
  double listLeft = 0.0, codeLeft = 0.0;  // the columns' left edges
  double columnWidth = 0.0;               // the steps' column width
  std::vector<std::string> code;          // the code's lines shown, "> " on the current line
  std::vector<bool> codeCurrent;          // per code line: the current step's line
  double codeTop = 0.0;
  double lineStep = 0.0;   // a line's advance (font + spacing)
  double textScale = 1.0;  // its text's size over the body size (a slide's side column)
};

// a box of text: lines broken at spaces, `scale` times the body size
struct TextBox {
  ScreenRect box;
  std::vector<std::string> lines;
  double scale = 1.0;      // the first lines' size (the title's, or every caption line's)
  double restScale = 1.0;  // the rest's (a figure's caption under its title), and the gaps
  double padding = -1.0;   // the inner padding (negative: the window's own)
};

// a zoom inset a slide keeps a corner of its figure room for (tiny edges or faces
// magnified): the corner is the one toward what it magnifies
struct InsetWish {
  glm::dvec2 toward{0.0};             // from the shape's middle toward what it magnifies, on screen
  double textWidth = 0.0;             // its widest text line, window pixels
  double textRoom = 0.0;              // a text line's room over or under the frame
  int linesOver = 1, linesUnder = 1;  // text lines over and under the frame
};

// everything on a slide (or in the live scene) that the layout places
struct SlideContent {
  ScreenRect area;          // the scene's area: the page (or window) less the panels
  std::string title;        // the slide card's text ("4 / 27: Wedges"); empty: no card
  std::string cardCaption;  // a figure's caption under its title in the card
  std::string caption;      // the caption box's text at the bottom; empty: none
  std::optional<StepsContent> steps;
  glm::dvec2 legend{0.0};    // the legend's size; zero: none floats over the scene
  double shapeAspect = 1.0;  // the drawn shape's width over its height, about
  // the caption lines the scene leaves room for whatever the caption holds (a slide: 2, so
  // that slides with a one- and a two-line caption fit one figure alike); 0: the caption's own
  std::size_t captionRoom = 0;
  // a slide: the Steps window and the legend in a column on the right, the figure's room
  // the rest between the card and the caption (at least kFigureShare of the page)
  bool slide = false;
  // a plots slide (Why O(1)): this many plots side by side in the figure's room, a line of
  // text under them; 0: a scene
  std::size_t plots = 0;
  std::optional<InsetWish> inset;  // a slide's zoom inset
  // a slide's note on its figure (a far polygon's digits): a box in the figure room's upper
  // corner on the side `noteRight` names, its text the slide's box text
  std::string note;
  bool noteRight = true;
};

// the share of the page a slide's figure room keeps at least
inline constexpr double kFigureShare = 0.56;
// the smallest text on a slide, as a share of the page's height
inline constexpr double kSlideTextShare = 0.0225;

// a plots slide's figure: the plots side by side over a line of text, all at `fontPx`
struct PlotsLayout {
  std::vector<ScreenRect> plots;  // left to right, each with its title, axes and legend
  ScreenRect note;                // the line under them ("What was measured")
  double fontPx = 16.0;           // the plots' text height, at least kSlideTextShare of the page
};

// `count` plots side by side in `room` over a line of text, their text `fontPx` high
PlotsLayout layoutPlots(ScreenRect room, std::size_t count, double fontPx);

// the plots' text height on a slide: the slide's `body` text, smaller where a plot would hold
// fewer than kPlotColumns characters across or the room fewer than kPlotRows lines down, never
// under kSlideTextShare of the page's height `pageHeight` (plots stacked in an upright room:
// what their width and share of its height hold, at most `body`)
double plotsTextPx(ScreenRect room, std::size_t count, double body, double pageHeight);
inline constexpr double kPlotColumns = 34.0;  // a legend's longest name and its swatch
inline constexpr double kPlotRows = 22.0;     // title, axes, labels and a legend of six rows

// the boxes of one slide, in window pixels
struct SlideLayout {
  TextBox title;                     // the title card (with a figure's caption under the title)
  std::size_t titleLines = 0;        // how many of title.lines are the title's (the rest caption)
  TextBox caption;                   // the caption box, centred at the bottom
  std::optional<StepsLayout> steps;  // over the lower left corner, above the caption
  ScreenRect legend;                 // over the lower right corner, above the caption
  ScreenRect scene;                  // the figure's room, beside all of them
  double columnScale = 1.0;          // a slide's side column: its text over the body size
  std::optional<PlotsLayout> plots;  // a plots slide's plots in the scene's room
  // a slide's zoom inset: its box (the frame with its text) in the figure room's corner
  // toward what it magnifies, and its frame; empty without one
  ScreenRect inset, insetFrame;
  TextBox note;  // a slide's note on its figure, in the figure room's upper corner
  // the room the shape is fitted into: the figure room less the inset's or the note's strip
  // beside it
  ScreenRect shapeRoom() const;
};

// The Steps window over `area`'s lower left corner, its bottom at `bottom`, its top not
// above `top` where a shorter list allows (a long list shows a window of lines around the
// step shown). Laid out in logic/teach/slide_steps.cpp.
StepsLayout layoutSteps(const StepsContent& steps, const SlideMetrics& metrics, ScreenRect area,
                        double bottom, double top);

// The Steps window at the top of a slide's side `column`, as wide as it, as many lines of
// steps as it holds (a window of them around the step shown).
StepsLayout layoutStepsInColumn(const StepsContent& steps, const SlideMetrics& metrics,
                                ScreenRect column);

// the colour of a step's line in the Steps window: its sign's, the result's (`result`, the
// class's text colour), or the text's
Rgba stepColour(const Step& step, const Palette& pal, Rgba result);

// The split view's heading over a half (`half`, window pixels): `text` centred over it,
// never starting left of it, 0.3 text heights under its top; the box is the text and a
// padding of 0.6 text heights around it (half that above and below); the text `scale` times
// the body size. The window and the SVG draw it from here.
TextBox splitHeading(ScreenRect half, const std::string& text, const SlideMetrics& metrics,
                     double scale = 1.0);
// the band the halves' headings take over them: the box and 0.3 text heights over and under
double splitHeadingBand(const SlideMetrics& metrics, double scale = 1.0);
// a slide's halves' headings: text 2.4% of the page's height (a slide's figure keeps the
// height the halves need to fill their room)
inline constexpr double kSplitHeadingShare = 0.024;

// the title card's, caption's and legend's text sizes relative to the body text
inline constexpr double kTitleScale = 1.3;
inline constexpr double kCaptionScale = 1.5;

// Lays out a slide: the card over the area's top left, the caption centred along its
// bottom, the Steps window over the lower left and the legend over the lower right corner
// above the caption, and the scene's room beside them (logic/view/fit_room). Every size is
// taken from `metrics`, which grow with the text: at any page scale the boxes keep their
// places relative to the page.
SlideLayout layoutSlide(const SlideContent& content, const SlideMetrics& metrics);

}  // namespace convexloc::viewer
