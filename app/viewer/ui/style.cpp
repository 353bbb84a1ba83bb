// convexloc-viewer — the panels' theme and font.
#include "ui/style.hpp"

#include <cmath>
#include <filesystem>
#include <vector>

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "logic/base/glyphs.hpp"

namespace convexloc::viewer {
namespace {

ImVec4 im(Rgba c) {
  return {c.r, c.g, c.b, c.a};
}

// a colour of ImGui's style the themes set: the dark theme's, and the light theme's where
// it sets one (alpha below 0: the light theme keeps ImGui's own)
struct ThemeColour {
  ImGuiCol what;
  ImVec4 dark, light;
};
const ImVec4 kImGuis{0.0f, 0.0f, 0.0f, -1.0f};

// the window, frame, header, button and separator colours
const ThemeColour kThemeColours[] = {
    {ImGuiCol_WindowBg, {0.105f, 0.115f, 0.135f, 0.94f}, {0.965f, 0.965f, 0.96f, 0.96f}},
    {ImGuiCol_ChildBg, {0.0f, 0.0f, 0.0f, 0.0f}, kImGuis},
    {ImGuiCol_PopupBg, {0.12f, 0.13f, 0.155f, 0.98f}, kImGuis},
    {ImGuiCol_FrameBg, {0.17f, 0.185f, 0.215f, 1.0f}, {1.0f, 1.0f, 1.0f, 1.0f}},
    {ImGuiCol_FrameBgHovered, {0.22f, 0.24f, 0.28f, 1.0f}, kImGuis},
    {ImGuiCol_FrameBgActive, {0.26f, 0.29f, 0.34f, 1.0f}, kImGuis},
    {ImGuiCol_Header, {0.17f, 0.19f, 0.23f, 1.0f}, {0.88f, 0.89f, 0.91f, 1.0f}},
    {ImGuiCol_HeaderHovered, {0.22f, 0.25f, 0.30f, 1.0f}, {0.83f, 0.86f, 0.90f, 1.0f}},
    {ImGuiCol_HeaderActive, {0.26f, 0.30f, 0.36f, 1.0f}, {0.78f, 0.83f, 0.89f, 1.0f}},
    {ImGuiCol_Button, {0.20f, 0.23f, 0.28f, 1.0f}, {0.88f, 0.90f, 0.93f, 1.0f}},
    {ImGuiCol_Separator, {0.25f, 0.27f, 0.31f, 1.0f}, kImGuis},
};

// places a font may be installed (Debian's fonts-dejavu-core first)
// the font's height at scale 1, in points
constexpr float kBaseFontPixels = 16.0f;

constexpr const char* kFontFiles[] = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
};

}  // namespace

void applyStyle(Theme theme, float scale) {
  ImGuiStyle style;
  if (theme == Theme::Dark)
    ImGui::StyleColorsDark(&style);
  else
    ImGui::StyleColorsLight(&style);
  style.WindowRounding = 6.0f;
  style.FrameRounding = 4.0f;
  style.GrabRounding = 4.0f;
  style.PopupRounding = 4.0f;
  style.ScrollbarRounding = 6.0f;
  style.TabRounding = 4.0f;
  style.WindowBorderSize = 0.0f;
  style.FrameBorderSize = theme == Theme::Light ? 1.0f : 0.0f;
  style.WindowPadding = ImVec2(12.0f, 10.0f);
  style.FramePadding = ImVec2(7.0f, 4.0f);
  style.ItemSpacing = ImVec2(8.0f, 6.0f);
  style.IndentSpacing = 14.0f;

  const Palette& p = paletteFor(theme);
  ImVec4* c = style.Colors;
  const Rgba accent = theme == Theme::Dark ? hex(0x4f8fd6) : hex(0x2f6fb6);
  for (const ThemeColour& t : kThemeColours) {
    const ImVec4& colour = theme == Theme::Dark ? t.dark : t.light;
    if (colour.w >= 0.0f) c[t.what] = colour;
  }
  if (theme == Theme::Dark) {
    c[ImGuiCol_ButtonHovered] = im(withAlpha(accent, 0.75f));
    c[ImGuiCol_ButtonActive] = im(accent);
    c[ImGuiCol_TitleBg] = c[ImGuiCol_WindowBg];
    c[ImGuiCol_TitleBgActive] = c[ImGuiCol_WindowBg];
  } else {
    c[ImGuiCol_ButtonHovered] = im(withAlpha(accent, 0.35f));
    c[ImGuiCol_ButtonActive] = im(withAlpha(accent, 0.55f));
  }
  c[ImGuiCol_Text] = im(p.text);
  c[ImGuiCol_TextDisabled] = im(p.textMuted);
  c[ImGuiCol_CheckMark] = im(accent);
  c[ImGuiCol_SliderGrab] = im(accent);
  c[ImGuiCol_SliderGrabActive] = im(accent);
  c[ImGuiCol_PlotHistogram] = im(p.extraEdges);
  c[ImGuiCol_PlotHistogramHovered] = im(p.crowded);
  // ImGui floors the sizes it scales; the spacings a slide's layout is made of are kept
  // exact, so that a slide keeps its proportions at any page scale
  const ImVec2 window = style.WindowPadding, frame = style.FramePadding, item = style.ItemSpacing,
               inner = style.ItemInnerSpacing, cell = style.CellPadding;
  const float indent = style.IndentSpacing;
  style.ScaleAllSizes(scale);
  const auto times = [scale](ImVec2 v) { return ImVec2(v.x * scale, v.y * scale); };
  style.WindowPadding = times(window);
  style.FramePadding = times(frame);
  style.ItemSpacing = times(item);
  style.ItemInnerSpacing = times(inner);
  style.CellPadding = times(cell);
  style.IndentSpacing = indent * scale;
  ImGui::GetStyle() = style;
}

void loadFont(float pixels, bool recreateTexture) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  bool loaded = false;
  for (const char* path : kFontFiles) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) continue;
    ImFontConfig cfg;
    cfg.OversampleH = 2;
    cfg.OversampleV = 2;
    // at the exact size (not rounded): a slide's text keeps its width at any page scale;
    // the ranges the captions' glyphs are checked against (logic/base/glyphs.hpp)
    static const std::vector<ImWchar> ranges = [] {
      std::vector<ImWchar> r;
      for (const GlyphRange& g : fontGlyphRanges()) {
        r.push_back(static_cast<ImWchar>(g.first));
        r.push_back(static_cast<ImWchar>(g.last));
      }
      r.push_back(0);
      return r;
    }();
    if (io.Fonts->AddFontFromFileTTF(path, pixels, &cfg, ranges.data())) {
      loaded = true;
      break;
    }
  }
  if (!loaded) {
    // ImGui's built-in font is 13 pixels; scale it
    ImFontConfig cfg;
    cfg.SizePixels = std::round(pixels * 0.85f);
    io.Fonts->AddFontDefault(&cfg);
  }
  io.Fonts->Build();
  if (recreateTexture) {
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }
}

StyleKeeper::StyleKeeper(const Settings& settings, float dpi)
    : dpi_(dpi), theme_(settings.theme), scale_(settings.uiScale()) {
  loadFont(kBaseFontPixels * scale_ * dpi_, false);
  ImGui::GetIO().FontGlobalScale = 1.0f / dpi_;
  applyStyle(theme_, scale_);
}

bool StyleKeeper::update(Settings& settings, float& pendingFontScale) {
  if (pendingFontScale > 0.0f) {
    settings.fontScale = pendingFontScale;
    pendingFontScale = 0.0f;
  }
  const float scale = settings.uiScale();
  // the atlas is made again at the text's new pixel size (crisp, not a scaled bitmap); a
  // change under half a percent (a window dragged by a pixel) keeps the one there is
  const bool resized = std::abs(scale - scale_) > 0.005f * scale_;
  if (!resized && theme_ == settings.theme) return false;
  if (resized) {
    scale_ = scale;
    loadFont(kBaseFontPixels * scale_ * dpi_, true);
  }
  theme_ = settings.theme;
  applyStyle(theme_, scale_);
  return resized;
}

}  // namespace convexloc::viewer
