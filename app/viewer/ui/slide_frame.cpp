// convexloc-viewer — the frame's slide, its page and its layout.
#include "ui/slide_frame.hpp"

#include <algorithm>

#include <imgui.h>

#include "logic/app/legend.hpp"
#include "ui/label_overlay.hpp"
#include "ui/scene_area.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

// a phone's slide: the bands of the window kept for the page's file button (top) and the
// drawer's and slides' buttons (bottom), as shares of the window's height
constexpr double kPhoneTopBand = 0.04;
constexpr double kPhoneBottomBand = 0.055;

// the drawn shape's width over its height, about (the 3D scenes as a square)
double shapeAspect(const Model& model) {
  if (model.dim == Dim::Three) return model.planes3d.enabled() ? 2.0 : 1.0;
  if (model.lines2d.enabled()) return 2.0;  // the dual view sits beside
  const Box2 b = model.scene2d.polygon().bounds();
  const double w = b.hi.x - b.lo.x, h = b.hi.y - b.lo.y;
  return w > 0.0 && h > 0.0 ? std::clamp(w / h, 0.2, 5.0) : 1.0;
}

// what the Steps window shows, where it shows (a placed point's query, the window not
// hidden, no Lines or Planes mode: they draw no placed point)
std::optional<StepsContent> stepsContent(const Model& model, const UiState& ui) {
  const bool dualMode = model.dim == Dim::Two ? model.lines2d.enabled() : model.planes3d.enabled();
  if (!model.settings.stepBoxVisible || dualMode) return std::nullopt;
  std::optional<StepModel> m = model.steps();
  if (!m || m->steps.empty()) return std::nullopt;
  StepsContent c;
  c.step = model.step();
  c.model = std::move(*m);
  c.controls = !onSlide(model, ui);  // a slide's steps move by its keys
  c.codeWanted = ui.stepsCode;
  return c;
}

// the 3D inset's wish: toward the patch from the cube's middle as the camera sees them
std::optional<InsetWish> cubeInsetWish(const Model& model) {
  const std::optional<CubeInset>& inset = cubeInsetFound(model);
  const auto centre = inset ? model.scene3d().centre() : std::nullopt;
  if (!centre) return std::nullopt;
  const ScreenProjection project = sceneProjection(model);
  InsetWish w;
  const auto a = project(cubeInsetAnchor(*inset, model.scene3d().cells()));
  const auto c = project(toGlm(*centre));
  w.toward = a && c ? glm::dvec2(*a - *c) : glm::dvec2(1.0, -1.0);
  w.textWidth = measureText(cubeInsetZoomText(*inset)).x;
  for (const std::string& line : cubeInsetTitleLines(*inset))
    w.textWidth = std::max(w.textWidth, measureText(line).x);
  w.linesOver = 2;
  return w;
}

// the 2D inset's wish: toward the tiny edges from the polygon's middle (y down on screen)
std::optional<InsetWish> zoomInsetWish(const Model& model) {
  const std::optional<ZoomInset> inset = zoomInsetFound(model);
  if (!inset) return std::nullopt;
  const Box2 b = model.scene2d.polygon().bounds(), s = inset->source;
  InsetWish w;
  w.toward = {s.lo.x + s.hi.x - b.lo.x - b.hi.x, b.lo.y + b.hi.y - s.lo.y - s.hi.y};
  w.textWidth = measureText("zoom " + magnificationText(*inset)).x;
  w.linesUnder = 0;
  return w;
}

// a slide's zoom inset, where its shape has one
std::optional<InsetWish> insetWish(const Model& model) {
  std::optional<InsetWish> w =
      model.dim == Dim::Three ? cubeInsetWish(model) : zoomInsetWish(model);
  if (w) {
    w->textRoom = insetTextRoom();
    w->textWidth += 8.0;
  }
  return w;
}

// the slide card's title: "4 / 27: Wedges" in a lecture, the figure's own title alone
std::string cardTitle(const UiState& ui) {
  if (!ui.show.active()) return {};
  const std::size_t count = ui.show.lecture.slides.size();
  const std::string& t = ui.show.slide().title;
  return count > 1 ? std::to_string(ui.show.current + 1) + " / " + std::to_string(count) + ": " + t
                   : t;
}

}  // namespace

bool onSlide(const Model& model, const UiState& ui) {
  return ui.show.active() || model.settings.present;
}

bool plotsSlide(const Model& model, const UiState& ui) {
  return ui.show.active() && model.whyOpen;
}

PageFit pageOf(const Model& model, const UiState& ui, glm::dvec2 window) {
  if (!onSlide(model, ui)) return {{{0.0, 0.0}, window}, 1.0};
  // a phone (the web page's drawer): the page between the page's file button at the top and
  // the drawer's and slides' buttons at the bottom
  const double top = model.settings.drawer ? kPhoneTopBand * window.y : 0.0;
  const double bottom = model.settings.drawer ? kPhoneBottomBand * window.y : 0.0;
  const glm::dvec2 room{window.x, window.y - top - bottom};
  PageFit f = fitPage(room, slidePageIn(room, model.settings.page, model.settings.pageGiven));
  f.page.lo.y += top;
  f.page.hi.y += top;
  return f;
}

SlideMetrics windowMetrics() {
  const ImGuiStyle& style = ImGui::GetStyle();
  SlideMetrics m;
  m.font = ImGui::GetFontSize();
  m.spacing = style.ItemSpacing.y;
  m.padding = style.WindowPadding.x;
  m.frame = ImGui::GetFrameHeight();
  m.margin = 0.625 * m.font;
  m.measure = measureText;
  return m;
}

SlideLayout frameLayout(const Model& model, const UiState& ui, glm::dvec2 window, bool withSteps) {
  SlideContent c;
  c.area = pageArea(model, ui, window);
  c.title = cardTitle(ui);
  // a caption the scene shows in its own box (--caption) is not written twice
  if (ui.show.active() && model.settings.caption.empty()) c.cardCaption = ui.show.slide().caption;
  c.caption = model.settings.caption;
  if (withSteps) c.steps = stepsContent(model, ui);
  const bool floating = model.settings.showLegend && rightPanelWidth(model, window) == 0.0f;
  if (floating && !ui.legendMoved) c.legend = {ui.legendSize[0], ui.legendSize[1]};
  const SlideMetrics m = windowMetrics();
  // a slide's legend sized from its rows before it is drawn: final on the first frame
  if (floating && !ui.legendMoved && onSlide(model, ui))
    c.legend = legendBoxSize(legendOf(model), m.measure, m.font, m.padding, m.spacing);
  c.shapeAspect = shapeAspect(model);
  if (onSlide(model, ui)) c.captionRoom = 2;
  c.slide = onSlide(model, ui);
  if (plotsSlide(model, ui)) c.plots = slidePlotCount();
  if (c.slide) c.inset = insetWish(model);
  if (c.slide && model.dim == Dim::Two && !model.lines2d.enabled() && !model.split.enabled())
    if (const auto note = offsetNote(model.scene2d.polygon())) {
      // the corner on vertex 0's side of the polygon (it is ringed there)
      const Box2 b = model.scene2d.polygon().bounds();
      c.note = *note;
      c.noteRight = model.scene2d.polygon().vertex(0).x >= 0.5 * (b.lo.x + b.hi.x);
    }
  return layoutSlide(c, m);
}

double splitHeadingScale(const Model& model, const UiState& ui, glm::dvec2 window) {
  if (!onSlide(model, ui)) return 1.0;
  const double page = pageOf(model, ui, window).page.size().y;
  return std::min(1.0, kSplitHeadingShare * page / ImGui::GetFontSize());
}

void slideDrawOptions(Model& model, const UiState& ui) {
  const bool slide = onSlide(model, ui);
  model.settings.view2d.zoomInset = !slide;  // (and the offset note: a slide boxes it)
  unsigned names = 0x3fu;
  if (slide) {
    names = 0u;
    if (model.dim == Dim::Three && model.hasScene3d()) {
      const auto& probe = model.scene3d().probe();
      if (probe && probe->trace.cubeFace >= 0) names |= 1u << probe->trace.cubeFace;
    }
  }
  model.settings.view3d.faceNames = names;
}

ScreenRect figureRoomOf(const Model& model, const UiState& ui) {
  if (plotsSlide(model, ui)) return ui.layout.scene;
  if (!onSlide(model, ui) || model.whyOpen) return {};
  return ui.layout.scene;
}

void drawLetterbox(const Model& model, const UiState& ui, glm::dvec2 window) {
  const ScreenRect p = pageOf(model, ui, window).page;
  std::vector<ScreenRect> bars = barsAround({{0.0, 0.0}, window}, p);
  if (const ScreenRect room = figureRoomOf(model, ui); room.hi.x > room.lo.x)
    for (const ScreenRect& r : barsAround(p, room)) bars.push_back(r);
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const ImU32 bg = u32(paletteFor(model.settings.theme).background);
  for (const ScreenRect& r : bars)
    dl->AddRectFilled(ImVec2(static_cast<float>(r.lo.x), static_cast<float>(r.lo.y)),
                      ImVec2(static_cast<float>(r.hi.x), static_cast<float>(r.hi.y)), bg);
}

}  // namespace convexloc::viewer
