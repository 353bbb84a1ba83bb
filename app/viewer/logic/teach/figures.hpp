// convexloc-viewer — the paper's figures 1-7, each a set of the viewer's own options (shape,
// method, resolution, probe, camera, what is drawn), so that `--figure N`, the gallery and
// a lecture's `figure N` set up the same slide.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace convexloc::viewer {

// how many figures the paper has
inline constexpr int kFigureCount = 7;

// one of the paper's figures as a slide
struct Figure {
  std::string_view title;    // "Fig. 4  Uniform slabs, O(1)"
  std::string_view caption;  // one sentence: the idea the figure shows
  std::string_view args;     // the viewer's options that draw it, space separated
};

// figure n (1..kFigureCount); std::out_of_range for another number (callers check it)
const Figure& figure(int n);

// figure n's options as a command line (without the program name)
std::vector<std::string> figureArgs(int n);

}  // namespace convexloc::viewer
