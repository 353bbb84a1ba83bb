// convexloc-viewer — the SVG export's glue: draw lists, camera and font to writers/svg_writer.
#include "writers/svg_export.hpp"

#include <cfloat>

#include <imgui.h>

#include "logic/app/legend.hpp"
#include "ui/label_overlay.hpp"
#include "ui/scene_area.hpp"
#include "ui/slide_frame.hpp"
#include "ui/widgets.hpp"
#include "writers/svg_writer.hpp"

namespace convexloc::viewer {
namespace {

// the sprayed points of a scene, as the renderer draws them
template <class Scene>
void sprayOf(const Scene& scene, const Model& model, const SceneView& view, SvgScene& s) {
  const Palette& pal = paletteFor(model.settings.theme);
  s.points.points.reserve(scene.points().size());
  for (const auto& p : scene.points()) {
    if constexpr (requires { p.z; })
      s.points.points.push_back({p.x, p.y, p.z});
    else
      s.points.points.push_back({p.x, p.y, 0.0});
  }
  s.points.classes = scene.classes();
  s.points.visibleMask = model.settings.visibleMask;
  s.points.overLines = pointsOverLines(model);
  s.points.size = view.pointSize();
  s.points.colours[0] = pal.inside;
  s.points.colours[1] = pal.boundary;
  s.points.colours[2] = pal.outside;
  s.points.rim = pal.rim;
}

// 2D: the structure under the overlay, core's cells and the polygon's edges
void scene2d(const Model& model, const SceneView& view, const UiState& ui, SvgScene& s) {
  s.base = {&view.structure()};
  s.overlay = {&view.overlay()};
  const Scene2D& scene = model.scene2d;
  if (model.split.enabled() && !model.lines2d.enabled()) {
    SvgSplit split;
    split.left = model.split.left();
    split.right = model.split.right();
    const Camera2D right = model.split.rightCamera(model.camera2d);
    split.project = [right](glm::dvec3 p) -> std::optional<glm::dvec3> {
      return glm::dvec3(right.toScreen({p.x, p.y}), 0.0);
    };
    split.base = {&view.splitStructure()};
    split.overlay = {&view.splitOverlay()};
    split.headings = {ui.splitHeadings[0], ui.splitHeadings[1]};
    s.split = std::move(split);
  }
  if (model.lines2d.enabled()) {
    s.points.visibleMask = 0;  // the Lines mode hides the spray
    return;
  }
  sprayOf(scene, model, view, s);
  for (const Cell2D& c : scene.cells()) {
    std::vector<glm::dvec3>& o = s.cells.emplace_back();
    for (Vec2 v : c.outline) o.push_back({v.x, v.y, 0.0});
  }
  const ConvexPolygon& poly = scene.polygon();
  for (std::size_t e = 0; e < poly.size(); ++e)
    s.edges.push_back({at2(toGlm(poly.edgeStart(e))), at2(toGlm(poly.edgeEnd(e)))});
}

// 3D: the mesh, structure and section sorted back to front, lit from the eye
void scene3d(const Model& model, const SceneView& view, SvgScene& s) {
  s.depthSorted = true;
  s.eye = model.camera3d.eye();
  s.base = {&view.mesh(), &view.structure(), &view.section()};
  s.overlay = {&view.overlay()};
  sprayOf(model.scene3d(), model, view, s);
  if (model.planes3d.enabled()) s.points.visibleMask = 0;  // the Planes mode hides the spray
}

// the slide's layout and the Steps window's colours, as the window draws them
void slideBoxes(const Model& model, const UiState& ui, SvgScene& s) {
  const Palette& pal = paletteFor(model.settings.theme);
  const glm::dvec2 window = s.size;
  s.layout = ui.layout;
  s.page = pageOf(model, ui, window).page;
  const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
  s.panel = {bg.x, bg.y, bg.z, 0.9f};
  s.rounding = ImGui::GetStyle().WindowRounding;
  const SlideMetrics m = windowMetrics();
  s.layoutPadding = m.padding;
  s.layoutSpacing = m.spacing;
  s.itemSpacingX = ImGui::GetStyle().ItemSpacing.x;
  s.windowPaddingY = ImGui::GetStyle().WindowPadding.y;
  s.cellPadding = {ImGui::GetStyle().CellPadding.x, ImGui::GetStyle().CellPadding.y};
  s.highlight = pal.hoverEdge;
  // the Why O(1) window, its plots as the window draws them; a plots slide's from its layout
  const UiState::WhyPlots& why = ui.whyPlots;
  if (plotsSlide(model, ui) && ui.layout.plots) {
    const ScalingProgress p = model.scaling->snapshot();
    const PlotsLayout& l = *ui.layout.plots;
    const PlotStyle style = slidePlotStyle(model.settings.theme, l.fontPx);
    s.plotsSvg = svgPlots(
        slideDrawings(p.result, model.scaling->config(), style, l, model.whySolid, p.error),
        {0.0, 0.0}, l.fontPx,
        [px = static_cast<float>(l.fontPx)](std::string_view t) {
          const ImVec2 v =
              ImGui::GetFont()->CalcTextSizeA(px, FLT_MAX, 0.0f, t.data(), t.data() + t.size());
          return glm::dvec2(v.x, v.y);
        },
        ImGui::GetFont()->Ascent * l.fontPx / ImGui::GetFont()->FontSize);
  } else if (model.whyOpen && ui.whyWindow.hi.x > ui.whyWindow.lo.x) {
    s.window = ui.whyWindow;
    s.windowTitle = "Why O(1): cost against N";
    const ImVec4 bar = ImGui::GetStyleColorVec4(ImGuiCol_TitleBgActive);
    s.windowBar = {bar.x, bar.y, bar.z, 1.0f};
    s.windowBarHeight = ImGui::GetFrameHeight();
    if (why.fontPx > 0.0) {
      const ScalingProgress p = model.scaling->snapshot();
      const PlotStyle style = plotStyle(model.settings.theme, why.fontPx);
      s.windowSvg = svgPlots(
          scalingDrawings(p.result, model.scaling->config(), style, why.rect.size(), why.solid),
          why.rect.lo, why.fontPx);
    }
  }
  s.step = model.step();
  if (const std::optional<StepModel> steps = model.steps(); steps && ui.layout.steps) {
    const Location result = model.dim == Dim::Two ? model.scene2d.probe()->trace.result
                                                  : model.scene3d().probe()->trace.result;
    for (const Step& st : steps->steps)
      s.stepColours.push_back(stepColour(st, pal, textColourOf(pal, result)));
  }
}

}  // namespace

bool writeSceneSvg(const Model& model, const SceneView& view, const UiState& ui,
                   const std::string& path, std::string& error) {
  const Palette& pal = paletteFor(model.settings.theme);
  SvgScene s;
  s.size = model.dim == Dim::Two ? model.camera2d.viewport() : model.camera3d.viewport();
  s.background = pal.background;
  s.text = pal.text;
  s.scale = model.settings.drawScale();
  // ImGui sizes a font by its height from descent to ascent, SVG by its em: DejaVu Sans is
  // 1.164 em high, so the SVG's text takes the window's width at this size
  s.fontPixels = ImGui::GetFontSize() / 1.164;
  s.measure = measureText;
  s.advance = [](std::string_view t) {
    const ImVec2 v = ImGui::GetFont()->CalcTextSizeA(ImGui::GetFontSize(), FLT_MAX, 0.0f, t.data(),
                                                     t.data() + t.size());
    return glm::dvec2(v.x, v.y);
  };
  s.project = sceneProjection(model);
  s.figureRoom = figureRoomOf(model, ui);
  const ScreenRect area =
      s.figureRoom.hi.x > s.figureRoom.lo.x ? s.figureRoom : sceneArea(model, ui, s.size);
  s.labelArea = {area.lo, area.hi};  // the labels go where the window puts them
  s.keepOff = labelKeepOffs(ui);
  s.textMuted = pal.textMuted;
  slideBoxes(model, ui, s);
  // the legend where the window put it (the layout's corner, or where it was dragged); with
  // the panels shown (the legend in the right one), in the scene's lower right corner
  if (model.settings.showLegend) {
    s.legend = legendOf(model);
    s.legendScale = ui.layout.columnScale;
    if (ui.legendRect[2] > ui.legendRect[0]) {
      s.legendCorner = {ui.legendRect[2], ui.legendRect[3]};
      s.legendSize = {ui.legendRect[2] - ui.legendRect[0], ui.legendRect[3] - ui.legendRect[1]};
    } else {
      s.legendCorner = sceneArea(model, ui, s.size).hi - glm::dvec2(10.0);
    }
  }
  // the cube map's zoom inset, where the window draws it; the labels keep off it
  const std::optional<ScreenInset> inset = sceneInsetOver(model, ui);
  if (inset) {
    s.screen.push_back(&inset->list);
    for (const PixelBox& b : inset->keepOff()) s.keepOff.push_back(b);
  }
  if (model.dim == Dim::Two)
    scene2d(model, view, ui, s);
  else
    scene3d(model, view, s);
  return writeTextFile(path, sceneSvg(s), error);
}

}  // namespace convexloc::viewer
