// convexloc-viewer — text laid out in lines, GL-free: the window's text measure comes in as
// a callback, so that the window and the SVG break a text at the same spaces (a slide's
// boxes are laid out with it in logic/teach/slide_layout).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace convexloc::viewer {

// the size of a text in window pixels
using MeasureText = std::function<glm::dvec2(std::string_view)>;

// Breaks `text` into lines no wider than `width` pixels at spaces only, so that a number
// ("-0.2791048542272344") is never split; a word wider than the line gets a line alone.
// Lines continuing a paragraph start with `indent`. Every wrapped text of the viewer with
// numbers in it (trace, inspector, steps, toasts, notes) is broken by this rule.
std::vector<std::string> breakAtSpaces(std::string_view text, double width,
                                       const MeasureText& measure, std::string_view indent = {});

}  // namespace convexloc::viewer
