// convexloc-viewer — a slide's boxes on its page.
#include "logic/teach/slide_layout.hpp"

#include <algorithm>
#include <cmath>

#include "logic/view/fit_room.hpp"

namespace convexloc::viewer {
namespace {

// `text` broken at spaces to `width` pixels at `scale` times the body size
std::vector<std::string> wrapAt(std::string_view text, double width, double scale,
                                const SlideMetrics& m, std::string_view indent = {}) {
  return breakAtSpaces(text, width / scale, m.measure, indent);
}

// the widest of `lines` at `scale` times the body size
double widest(const std::vector<std::string>& lines, double scale, const SlideMetrics& m) {
  double w = 0.0;
  for (const std::string& l : lines) w = std::max(w, m.widthAt(l, scale));
  return w;
}

// the height of `n` lines at `scale` times the body size
double linesHeight(std::size_t n, double scale, const SlideMetrics& m) {
  return n == 0 ? 0.0 : static_cast<double>(n) * (scale * m.font + m.spacing) - m.spacing;
}

// the title card at the area's top left: the title, a figure's caption under it
TextBox titleCard(const SlideContent& c, const SlideMetrics& m, std::size_t& titleLines) {
  TextBox t;
  titleLines = 0;
  if (c.title.empty()) return t;
  const double w = std::min(c.area.size().x * 0.7, m.font * 44.0) - 2.0 * m.padding;
  t.lines = wrapAt(c.title, w, kTitleScale, m);
  titleLines = t.lines.size();
  const std::vector<std::string> under =
      c.cardCaption.empty() ? std::vector<std::string>{} : wrapAt(c.cardCaption, w, 1.0, m);
  const double width = std::max(widest(t.lines, kTitleScale, m), widest(under, 1.0, m));
  const double height = linesHeight(titleLines, kTitleScale, m) +
                        (under.empty() ? 0.0 : m.spacing + linesHeight(under.size(), 1.0, m));
  t.lines.insert(t.lines.end(), under.begin(), under.end());
  t.scale = kTitleScale;
  t.box.lo = c.area.lo + glm::dvec2(m.margin);
  t.box.hi = t.box.lo + glm::dvec2(width, height) + glm::dvec2(2.0 * m.padding);
  return t;
}

// the caption centred along the area's bottom, 90% of its width at most
TextBox captionBox(const SlideContent& c, const SlideMetrics& m) {
  TextBox t;
  t.scale = kCaptionScale;
  if (c.caption.empty()) {
    t.box.lo = t.box.hi = {c.area.middle().x, c.area.hi.y};
    return t;
  }
  t.lines = wrapAt(c.caption, 0.9 * c.area.size().x - 2.0 * m.padding, kCaptionScale, m);
  const glm::dvec2 size =
      glm::dvec2(widest(t.lines, kCaptionScale, m), linesHeight(t.lines.size(), kCaptionScale, m)) +
      glm::dvec2(2.0 * m.padding);
  t.box.hi = {c.area.middle().x + 0.5 * size.x, c.area.hi.y - m.margin};
  t.box.lo = t.box.hi - size;
  return t;
}

}  // namespace

glm::dvec2 slidePageIn(glm::dvec2 window, glm::dvec2 page, bool given) {
  if (given || !(window.y > kUpright * window.x)) return page;
  return {kUprightPageWidth, kUprightPageWidth * std::min(window.y / window.x, kUprightMostAspect)};
}

PageFit fitPage(glm::dvec2 window, glm::dvec2 page) {
  PageFit f;
  if (window.x <= 0.0 || window.y <= 0.0 || page.x <= 0.0 || page.y <= 0.0) return f;
  f.scale = std::min(window.x / page.x, window.y / page.y);
  const glm::dvec2 size = page * f.scale;
  f.page.lo = 0.5 * (window - size);
  f.page.hi = f.page.lo + size;
  return f;
}

std::vector<ScreenRect> barsAround(ScreenRect outer, ScreenRect inner) {
  inner.lo = glm::clamp(inner.lo, outer.lo, outer.hi);
  inner.hi = glm::clamp(inner.hi, inner.lo, outer.hi);
  std::vector<ScreenRect> bars;
  for (const ScreenRect& r : {ScreenRect{outer.lo, {outer.hi.x, inner.lo.y}},
                              ScreenRect{{outer.lo.x, inner.hi.y}, outer.hi},
                              ScreenRect{{outer.lo.x, inner.lo.y}, {inner.lo.x, inner.hi.y}},
                              ScreenRect{{inner.hi.x, inner.lo.y}, {outer.hi.x, inner.hi.y}}})
    if (r.hi.x > r.lo.x && r.hi.y > r.lo.y) bars.push_back(r);
  return bars;
}

TextBox splitHeading(ScreenRect half, const std::string& text, const SlideMetrics& m,
                     double scale) {
  TextBox t;
  if (text.empty()) return t;
  t.lines = {text};
  t.scale = scale;
  const double pad = 0.6 * m.font * scale;
  const glm::dvec2 size = m.measure(text) * scale;
  const glm::dvec2 at{std::max(half.middle().x - 0.5 * size.x, half.lo.x + 2.0 * pad),
                      half.lo.y + pad};
  t.box = {at - glm::dvec2(pad, 0.5 * pad), at + size + glm::dvec2(pad, 0.5 * pad)};
  return t;
}

double splitHeadingBand(const SlideMetrics& m, double scale) {
  return 2.2 * m.font * scale;
}

double SlideMetrics::widthAt(std::string_view text, double scale) const {
  return measure(text).x * scale;
}

namespace {

// the scene's room: beside the legend's strip (right or bottom, whichever costs the drawing
// less) and the Steps window's (logic/view/fit_room), between the card and the caption
ScreenRect sceneRoom(const SlideContent& c, const SlideLayout& l, const SlideMetrics& m) {
  ScreenRect full = c.area;
  if (!l.title.lines.empty()) full.lo.y = l.title.box.hi.y;
  full.hi.y = c.caption.empty() ? c.area.hi.y : l.caption.box.lo.y;
  if (c.captionRoom > 0)
    full.hi.y = std::min(full.hi.y, c.area.hi.y - m.margin - 2.0 * m.padding -
                                        linesHeight(c.captionRoom, kCaptionScale, m));
  ScreenRect a = full;
  const glm::dvec2 strip = c.legend + glm::dvec2(2.0 * m.margin);
  const glm::dvec2 s = a.size();
  // the share of the drawing's width or height a strip leaves (none where it does not fit)
  const double keepsX = s.x > strip.x ? (s.x - strip.x) / s.x : 0.0;
  const double keepsY = s.y > strip.y ? (s.y - strip.y) / s.y : 0.0;
  const bool legend = c.legend.x > 0.0 && c.legend.y > 0.0 && (keepsX > 0.0 || keepsY > 0.0);
  if (legend) {
    if (keepsX >= keepsY)
      a.hi.x -= strip.x;
    else
      a.hi.y -= strip.y;
  }
  if (!l.steps) return a;
  CornerBoxes boxes;
  boxes.steps = l.steps->box.size();
  boxes.margin = m.margin;
  if (legend) boxes.legend = strip;
  return roomBesideCorners(a, full, boxes, c.shapeAspect);
}

}  // namespace

namespace {

// `m` with its text `scale` times as large (a side column's smaller text)
SlideMetrics scaled(const SlideMetrics& m, double scale) {
  SlideMetrics s = m;
  s.font *= scale;
  s.spacing *= scale;
  s.padding *= scale;
  s.frame *= scale;
  s.measure = [inner = m.measure, scale](std::string_view t) { return inner(t) * scale; };
  return s;
}

// The side column's width: the legend's and the Steps window's, no wider than leaves the
// figure its share of the page (negative: it does not fit).
double columnWidth(const SlideContent& c, const SlideMetrics& m, double band, double scale,
                   double& most) {
  const glm::dvec2 a = c.area.size();
  most = a.x - 3.0 * m.margin - kFigureShare * a.x * a.y / std::max(band, 1.0);
  double wanted = c.legend.x * scale;
  if (c.steps && !c.steps->model.steps.empty()) wanted = std::max(wanted, m.font * 15.0);
  return wanted;
}

// The inset's corner of the figure room: toward what it magnifies, as wide as the shape
// fitted to the room's height leaves beside it (at least a third of the room's height, at
// most 45% of it with its text where that is more; in a narrow room at most 40% of its
// width), the shape's room the rest.
void reserveInset(const InsetWish& w, double aspect, const SlideMetrics& m, SlideLayout& l) {
  const ScreenRect room = l.scene;
  const glm::dvec2 size = room.size();
  const double text = w.textRoom * (w.linesOver + w.linesUnder);
  const double beside = size.x - std::min(size.x, size.y * aspect) - m.margin;
  // (a narrow room: the inset at most 40% of its width, the shape the rest)
  const double narrow = 0.4 * size.x;
  const double least = std::min({size.y / 3.0, size.y - text, narrow});
  const double most = std::min(std::max(0.45 * size.y - text, least), narrow);
  double side = std::clamp(beside, least, most);
  const double width =
      std::min(std::max(side, std::min(w.textWidth, std::max(beside, side))), narrow);
  side = std::min(side, width);
  const bool right = w.toward.x >= 0.0, upper = w.toward.y <= 0.0;
  l.inset.lo = {right ? room.hi.x - width : room.lo.x, upper ? room.lo.y : room.hi.y - side - text};
  l.inset.hi = l.inset.lo + glm::dvec2(width, side + text);
  // the frame a little inside its box: its border's width is drawn outside the square
  const double pad = 0.1 * w.textRoom;
  l.insetFrame.lo = {l.inset.middle().x - 0.5 * side + pad,
                     l.inset.lo.y + w.textRoom * w.linesOver + pad};
  l.insetFrame.hi = l.insetFrame.lo + glm::dvec2(side - 2.0 * pad);
}

// The note's box in the figure room's upper corner, its lines at most 40% of the room wide.
void noteBox(const SlideContent& c, const SlideMetrics& m, double scale, SlideLayout& l) {
  TextBox& t = l.note;
  const ScreenRect room = l.scene;
  t.lines = wrapAt(c.note, 0.4 * room.size().x - 2.0 * m.padding, 1.0, m);
  t.scale = t.restScale = scale;
  t.padding = m.padding;
  const glm::dvec2 size = glm::dvec2(widest(t.lines, 1.0, m), linesHeight(t.lines.size(), 1.0, m)) +
                          glm::dvec2(2.0 * m.padding);
  t.box.lo = {c.noteRight ? room.hi.x - size.x : room.lo.x, room.lo.y};
  t.box.hi = t.box.lo + size;
}

// An upright page (a phone held upright): the Steps window and the legend in a row under the
// figure, side by side where both fit across (else the legend under the Steps window), the
// Steps window at most kUprightStepsShare of the page high, the figure's room the whole width
// above them.
void placeUnder(const SlideContent& c, const SlideMetrics& m, double scale, double top,
                double bottom, SlideLayout& l) {
  const bool steps = c.steps && !c.steps->model.steps.empty();
  const bool legend = c.legend.x > 0.0 && c.legend.y > 0.0;
  const double left = c.area.lo.x + m.margin, right = c.area.hi.x - m.margin;
  const glm::dvec2 legendSize = legend ? c.legend * scale : glm::dvec2(0.0);
  const bool beside = legend && legendSize.x + m.margin + m.font * 10.0 <= right - left;
  double rowTop = bottom;
  if (legend) {
    l.legend.hi = {right, bottom};
    l.legend.lo = l.legend.hi - legendSize;
    rowTop = l.legend.lo.y;
  }
  if (steps) {
    const double stepsBottom = legend && !beside ? l.legend.lo.y - m.margin : bottom;
    const double stepsRight = beside ? l.legend.lo.x - m.margin : right;
    // the figure's need first (the shape fitted to the page's width), the Steps window the rest
    // up to its share, three lines at least
    const double need = std::min(0.8 * (right - left) / std::max(c.shapeAspect, 0.25),
                                 kFigureShare * c.area.size().y);
    const double rest = stepsBottom - top - need - m.margin;
    const double most =
        std::max(std::min(kUprightStepsShare * c.area.size().y, rest), 3.0 * (m.font + m.spacing));
    // laid out once to learn its height, then again with its bottom on the row's
    const double height =
        layoutStepsInColumn(*c.steps, m, {{left, stepsBottom - most}, {stepsRight, stepsBottom}})
            .box.size()
            .y;
    l.steps =
        layoutStepsInColumn(*c.steps, m, {{left, stepsBottom - height}, {stepsRight, stepsBottom}});
    l.steps->textScale = scale;
    rowTop = std::min(rowTop, l.steps->box.lo.y);
  }
  l.columnScale = scale;
  l.scene = {{left, top}, {right, steps || legend ? rowTop - m.margin : bottom}};
}

// A slide with its text `scale` times the body size (`m` already scaled; `body` the
// unscaled): the card and the caption as elsewhere, the Steps window at the top and the
// legend at the bottom of a column on the right between them, the figure's room the rest.
// False where the figure's room is less than its share of the page.
bool slideColumn(const SlideContent& c, const SlideMetrics& m, double scale, SlideLayout& l) {
  l = SlideLayout{};
  l.title = titleCard(c, m, l.titleLines);
  l.caption = captionBox(c, m);
  l.title.padding = l.caption.padding = m.padding;
  l.title.restScale = scale;
  l.title.scale *= scale;
  l.caption.scale *= scale;
  l.caption.restScale = scale;  // its lines' gap: every line is at its first size
  const double top = (l.title.lines.empty() ? c.area.lo.y : l.title.box.hi.y) + m.margin;
  double bottom = (c.caption.empty() ? c.area.hi.y : l.caption.box.lo.y) - m.margin;
  if (c.captionRoom > 0)
    bottom = std::min(bottom, c.area.hi.y - 2.0 * m.margin - 2.0 * m.padding -
                                  linesHeight(c.captionRoom, kCaptionScale, m));
  const glm::dvec2 a = c.area.size();
  if (a.y > a.x) {
    placeUnder(c, m, scale, top, bottom, l);
    if (c.inset) reserveInset(*c.inset, c.shapeAspect, m, l);
    if (!c.note.empty()) noteBox(c, m, scale, l);
    // the figure's room as wide as the page: room enough when the shape fitted to its width
    // fills 80% of that (or the room keeps its share of the page)
    const glm::dvec2 room = l.scene.size();
    const double wanted = std::min(0.8 * room.x / std::max(c.shapeAspect, 0.25),
                                   kFigureShare * a.x * a.y / std::max(room.x, 1.0));
    return room.y >= wanted;
  }
  const bool steps = c.steps && !c.steps->model.steps.empty();
  const bool legend = c.legend.x > 0.0 && c.legend.y > 0.0;
  double most = 0.0;
  const double width = steps || legend ? columnWidth(c, m, bottom - top, scale, most) : 0.0;
  l.columnScale = scale;
  const double right = c.area.hi.x - m.margin;
  double stepsBottom = bottom;
  if (legend) {
    l.legend.hi = {right, bottom};
    l.legend.lo = l.legend.hi - c.legend * scale;
    stepsBottom = l.legend.lo.y - m.margin;
  }
  if (steps) {
    l.steps = layoutStepsInColumn(*c.steps, m, {{right - width, top}, {right, stepsBottom}});
    l.steps->textScale = scale;
  }
  const double left = width > 0.0 ? right - width - m.margin : right;
  l.scene = {{c.area.lo.x + m.margin, top}, {left, bottom}};
  if (c.inset) reserveInset(*c.inset, c.shapeAspect, m, l);
  if (!c.note.empty()) noteBox(c, m, scale, l);
  const glm::dvec2 room = l.scene.size();
  return width <= most && room.x * room.y >= kFigureShare * a.x * a.y;
}

// A slide: at the body size where the figure keeps its share of the page, else with its
// text smaller, down to kSlideTextShare of the page's height.
SlideLayout layoutSlideColumn(const SlideContent& c, const SlideMetrics& body) {
  // (an upright page, a phone's: its text down to kUprightLeastText of the slide's)
  const glm::dvec2 a = c.area.size();
  const double least =
      a.y > a.x ? kUprightLeastText : std::min(1.0, kSlideTextShare * a.y / body.font);
  SlideLayout l;
  for (double scale = 1.0;; scale = std::max(least, scale - 0.05)) {
    SlideMetrics m = scaled(body, scale);
    m.padding = 0.45 * m.font;  // a slide's boxes: tight around their text
    m.margin = 0.5 * m.font;
    if (slideColumn(c, m, scale, l) || scale <= least) return l;
  }
}

}  // namespace

PlotsLayout layoutPlots(ScreenRect room, std::size_t count, double fontPx) {
  PlotsLayout p;
  p.fontPx = fontPx;
  const double gap = 1.5 * fontPx, line = 1.6 * fontPx;
  const glm::dvec2 size = room.size();
  p.note = {{room.lo.x, room.hi.y - line}, room.hi};
  if (count == 0) return p;
  const double n = static_cast<double>(count);
  if (size.y > size.x) {
    // an upright page: the plots one over another, the room's width each
    const double h = (p.note.lo.y - 0.5 * fontPx - room.lo.y - (n - 1.0) * gap) / n;
    for (std::size_t i = 0; i < count; ++i) {
      const double y = room.lo.y + static_cast<double>(i) * (h + gap);
      p.plots.push_back({{room.lo.x, y}, {room.hi.x, y + h}});
    }
    return p;
  }
  const double w = (size.x - (n - 1.0) * gap) / n;
  for (std::size_t i = 0; i < count; ++i) {
    const double x = room.lo.x + static_cast<double>(i) * (w + gap);
    p.plots.push_back({{x, room.lo.y}, {x + w, p.note.lo.y - 0.5 * fontPx}});
  }
  return p;
}

double plotsTextPx(ScreenRect room, std::size_t count, double body, double pageHeight) {
  const double n = static_cast<double>(std::max<std::size_t>(count, 1));
  if (room.size().y > room.size().x) {
    // stacked: each plot the room's width, a share of its height
    const double across = room.size().x / (kPlotColumns * 0.56);
    const double down = room.size().y / (n * kPlotRows);
    return std::min({body, across, down});
  }
  // an average character about 0.56 of the text's height (DejaVu Sans); the gaps 1.5 of it
  const double across = room.size().x / (n * kPlotColumns * 0.56 + (n - 1.0) * 1.5);
  const double down = room.size().y / kPlotRows;
  return std::max(std::min({body, across, down}), kSlideTextShare * pageHeight);
}

ScreenRect SlideLayout::shapeRoom() const {
  ScreenRect r = scene;
  // the inset's (or the note's) strip off, a line's room apart
  const bool framed = inset.hi.x > inset.lo.x;
  const ScreenRect strip = framed ? inset : note.box;
  if (strip.hi.x <= strip.lo.x) return r;
  const double gap = framed ? 0.5 * (insetFrame.lo.y - inset.lo.y) : note.padding;
  if (strip.middle().x > scene.middle().x)
    r.hi.x = std::max(r.lo.x, strip.lo.x - gap);
  else
    r.lo.x = std::min(r.hi.x, strip.hi.x + gap);
  return r;
}

SlideLayout layoutSlide(const SlideContent& c, const SlideMetrics& m) {
  if (c.slide && c.plots > 0) {
    // a plots slide: the card and the caption as on any slide, the plots in the room between
    SlideContent bare = c;
    bare.steps.reset();
    bare.legend = glm::dvec2(0.0);
    SlideLayout l = layoutSlideColumn(bare, m);
    const double font = plotsTextPx(l.scene, c.plots, m.font * l.columnScale, c.area.size().y);
    l.plots = layoutPlots(l.scene, c.plots, font);
    return l;
  }
  if (c.slide) return layoutSlideColumn(c, m);
  SlideLayout l;
  l.title = titleCard(c, m, l.titleLines);
  l.caption = captionBox(c, m);
  const double bottom = (c.caption.empty() ? c.area.hi.y : l.caption.box.lo.y) - m.margin;
  const double top = (l.title.lines.empty() ? c.area.lo.y : l.title.box.hi.y) + m.margin;
  if (c.steps && !c.steps->model.steps.empty())
    l.steps = layoutSteps(*c.steps, m, c.area, bottom, top);
  if (c.legend.x > 0.0 && c.legend.y > 0.0) {
    l.legend.hi = {c.area.hi.x - m.margin, bottom};
    l.legend.lo = l.legend.hi - c.legend;
  }
  l.scene = sceneRoom(c, l, m);
  return l;
}

}  // namespace convexloc::viewer
