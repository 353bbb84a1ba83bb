// convexloc-viewer — layout.json.
#include "logic/teach/slide_record.hpp"

#include <cmath>
#include <cstdio>
#include <initializer_list>

namespace convexloc::viewer {
namespace {

// a number to a hundredth, without trailing zeros ("12.5", "640")
std::string number(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2f", std::round(v * 100.0) / 100.0 + 0.0);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? std::string("0") : s;
}

// "[a, b, ...]"
std::string list(std::initializer_list<double> values) {
  std::string out = "[";
  for (const double v : values) {
    if (out.size() > 1) out.append(", ");
    out.append(number(v));
  }
  out.push_back(']');
  return out;
}

std::string pair(glm::dvec2 p) {
  return list({p.x, p.y});
}

std::string rect(const ScreenRect& r) {
  return list({r.lo.x, r.lo.y, r.size().x, r.size().y});
}

// one slide's object, on one line
std::string slideJson(const SlideRecord& r) {
  std::string out = "{\"slide\": ";
  out.append(std::to_string(r.slide)).append(", \"kind\": \"").append(kindName(r.kind));
  out.append("\", \"page\": ").append(pair(r.page)).append(", \"boxes\": {");
  for (std::size_t i = 0; i < r.boxes.size(); ++i) {
    out += i ? ", \"" : "\"";
    out += r.boxes[i].first;
    out += "\": ";
    out += rect(r.boxes[i].second);
  }
  out.append("}, \"min_text_px\": ").append(number(r.minTextPx));
  if (r.query3d) {
    out.append(", \"query3d\": {\"x_T\": ").append(pair(r.query3d->centre));
    out.append(", \"x\": ").append(pair(r.query3d->point));
    out.append(", \"hit_face\": ").append(pair(r.query3d->hitFace)).append("}");
  }
  out.push_back('}');
  return out;
}

}  // namespace

void SlideRecord::add(const std::string& name, ScreenRect box, glm::dvec2 pageLo) {
  if (!(box.hi.x > box.lo.x && box.hi.y > box.lo.y)) return;
  boxes.emplace_back(name, ScreenRect{box.lo - pageLo, box.hi - pageLo});
}

const char* kindName(SlideKind kind) {
  switch (kind) {
    case SlideKind::Title: return "title";
    case SlideKind::Figure2D: return "figure2d";
    case SlideKind::Figure3D: return "figure3d";
    case SlideKind::Plots: return "plots";
  }
  return "figure2d";
}

std::string layoutJson(std::span<const SlideRecord> slides) {
  std::string out = "{\"slides\": [";
  for (std::size_t i = 0; i < slides.size(); ++i) {
    out += i ? ",\n  " : "\n  ";
    out += slideJson(slides[i]);
  }
  return out + "\n]}\n";
}

}  // namespace convexloc::viewer
