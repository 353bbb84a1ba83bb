// convexloc-viewer — the paper's figures as the viewer's options.
#include "logic/teach/figures.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

namespace convexloc::viewer {
namespace {

// Every figure is a clean slide: the light theme, no panels, no spray, one probe whose
// trace shows the method's steps; the shape is the same random octagon where the figure
// compares methods, so that the slides read as one story. Polar's query runs as the paper's
// (no radius filter) in four slabs an octant, so that each cell reads; uniform's 16 slabs
// mostly list their two edges, so that the slabs a vertex falls in stand out.
constexpr Figure kFigures[kFigureCount] = {
    {"Fig. 1  Half-planes: O(N)",
     "x is inside iff F_i(x) >= 0 for every edge i: N edge tests, one per edge.",
     "--generate random --n 8 --seed 3 --method halfplane --probe -0.3,-0.45 --spray 0 "
     "--theme light --font-scale 2 --hide-ui"},
    {"Fig. 2  Wedges from a reference point: O(lg N)",
     "A binary search over the wedges from x0 finds the one holding x; one edge test decides.",
     "--generate random --n 8 --seed 3 --method wedge --probe -0.3,-0.45 --spray 0 --theme light "
     "--font-scale 2 "
     "--hide-ui"},
    {"Fig. 3  Slabs with active edges: O(lg N) per query",
     "Slabs through every vertex; a binary search on y finds the slab, its two active edges "
     "decide.",
     "--generate random --n 8 --seed 3 --method slab --probe -0.3,-0.45 --spray 0 --theme light "
     "--font-scale 2 "
     "--hide-ui"},
    {"Fig. 4  Uniform slabs: O(1)",
     "Equal slabs: the index i = floor((y - ymin) / dy) (eq. 4) needs no search.",
     "--generate random --n 8 --seed 3 --method uniform --resolution 16 --probe -0.3,-0.45 "
     "--spray 0 --theme light --font-scale 2 --hide-ui"},
    {"Fig. 5  The slab thickness is set by the smallest y-gap",
     "The paper's slabs are as thin as the smallest y-gap: (ymax - ymin) / gap of them. "
     "convexloc bounds the count; crowded slabs list extra edges.",
     "--preset small-gap --method uniform --y-gap --spray 0 --theme light --font-scale 2 "
     "--hide-ui"},
    {"Fig. 6  Polar slabs: O(1)",
     "From x_T the octant and the slab follow from the direction to x; one edge test decides.",
     "--generate random --n 8 --seed 3 --method polar --resolution 4 --probe -0.05,-0.47 "
     "--paper --spray 0 --theme light --font-scale 2 --hide-ui"},
    {"Fig. 7  Spherical subdivision of a polyhedron",
     "Cells around x_T on the bounding cube: a typical cell lists one face, a cell where "
     "edges meet lists several.",
     "--3d --method cubemap --slice none --cell auto --spray 0 --theme light --font-scale 2 "
     "--hide-ui"},
};

}  // namespace

const Figure& figure(int n) {
  if (n < 1 || n > kFigureCount)
    throw std::out_of_range("the paper has figures 1 to " + std::to_string(kFigureCount) +
                            ", not " + std::to_string(n));
  return kFigures[n - 1];
}

std::vector<std::string> figureArgs(int n) {
  std::istringstream in{std::string(figure(n).args)};
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

}  // namespace convexloc::viewer
