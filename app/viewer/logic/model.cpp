// convexloc-viewer — the app's state.
#include "logic/model.hpp"

#include <algorithm>
#include <cmath>

#include "convexloc/generate2d.hpp"
#include "logic/presets.hpp"

namespace convexloc::viewer {
namespace {

// the extension of a path, lower case, with its dot ("" when none)
std::string extensionOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return ext;
}

constexpr std::size_t kMaxRecent = 8;

}  // namespace

float autoPointSize(std::size_t count, double areaPx) {
  if (count == 0) return 5.0f;
  const double spacing = std::sqrt(std::max(areaPx, 1.0) / static_cast<double>(count));
  return static_cast<float>(std::clamp(0.32 * spacing, 1.5, 5.5));
}

void Model::fail(std::string message) {
  error_ = std::move(message);
  ++errorSerial_;
}

void Model::collectErrors() {
  if (scene2d.errorSerial() != seen2d_) {
    seen2d_ = scene2d.errorSerial();
    if (!scene2d.error().empty()) fail(scene2d.error());
  }
}

void Model::remember(const std::string& path) {
  recent.erase(std::remove(recent.begin(), recent.end(), path), recent.end());
  recent.insert(recent.begin(), path);
  if (recent.size() > kMaxRecent) recent.resize(kMaxRecent);
}

bool Model::open(const std::string& path) {
  const std::string ext = extensionOf(path);
  if (ext == ".off" || ext == ".obj") {
    fail(path + ": polyhedra (.off, .obj) need core's 3D locators, which this build lacks");
    return false;
  }
  if (!scene2d.loadFile(path)) {
    collectErrors();
    return false;
  }
  dim = Dim::Two;
  remember(path);
  requestFit();
  return true;
}

bool Model::applyPreset(std::string_view name) {
  const Preset* p = findPreset(name);
  if (!p) {
    fail("no preset named '" + std::string(name) + "'");
    return false;
  }
  if (p->solid) {
    fail("the preset '" + std::string(name) + "' is a polyhedron; this build has no 3D core");
    return false;
  }
  const std::vector<Vec2> v = presetPolygon(name);
  if (!scene2d.setShape(v, std::string(p->title) + " (" + std::to_string(v.size()) + " input points)")) {
    collectErrors();
    return false;
  }
  if (p->method) scene2d.setMethod(*p->method);
  dim = Dim::Two;
  requestFit();
  return true;
}

std::string Model::apply(const Options& o) {
  std::string problem;
  auto note = [&](const std::string& s) {
    if (problem.empty()) problem = s;
    fail(s);
  };
  settings.theme = o.theme;
  settings.fontScale = o.fontScale;
  settings.showUi = !o.hideUi;
  if (o.method) {
    if (auto m = parseMethod2D(*o.method)) scene2d.setMethod(*m);
    else note("unknown method '" + *o.method + "' (halfplane, wedge, slab, uniform, polar)");
  }
  const std::uint64_t seed = o.seed.value_or(1);
  if (!o.shape.empty()) {
    if (!open(o.shape)) note(error_);
  } else if (o.preset) {
    if (!applyPreset(*o.preset)) note(error_);
  } else if (o.generate) {
    if (auto k = parsePolygonKind(*o.generate)) {
      if (!scene2d.generate(*k, o.n.value_or(16), seed)) {
        collectErrors();
        note(error_);
      }
    } else {
      note("unknown generator kind '" + *o.generate + "'");
    }
  }
  // the method again: a preset may have chosen one, the command line wins
  if (o.method) {
    if (auto m = parseMethod2D(*o.method)) scene2d.setMethod(*m);
  }
  if (o.resolution && !scene2d.setResolution(*o.resolution)) {
    collectErrors();
    note(error_);
  }
  if (o.spray || o.seed || o.nearBoundary) {
    SpraySettings s = scene2d.spraySettings();
    if (o.spray) s.count = *o.spray;
    if (o.seed) s.seed = *o.seed;
    s.nearBoundary = o.nearBoundary;
    scene2d.spray(s);
  }
  if (o.show) {
    if (*o.show == "inside") settings.visibleMask = classBit(Location::Inside) | classBit(Location::Boundary);
    else if (*o.show == "outside") settings.visibleMask = classBit(Location::Outside) | classBit(Location::Boundary);
    else if (*o.show == "boundary") settings.visibleMask = classBit(Location::Boundary);
    else settings.visibleMask = kAllClasses;
  }
  if (o.probe) scene2d.place(*o.probe);
  if (o.hover) scene2d.hover(*o.hover);
  collectErrors();
  requestFit();
  return problem;
}

void Model::fit(ScreenRect area) {
  if (dim == Dim::Two) camera2d.fit(scene2d.polygon().bounds(), area);
}

}  // namespace convexloc::viewer
