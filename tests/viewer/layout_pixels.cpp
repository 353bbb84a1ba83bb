// viewer_layout_pixels — checks a slide's PNG against the boxes its layout.json gives:
//
//   viewer_layout_pixels FILE --background RRGGBB [--allow X,Y,W,H]... [--shape X,Y,W,H]
//
// Boxes are in the image's pixels ([x, y, width, height] from the top left). Prints
//   stray N X Y      pixels outside every --allow box that differ from the background by
//                    more than 24 on a channel (N), and the first of them (X Y; -1 -1: none)
//   shape L T R B    for each side of the --shape box (left, top, right, bottom), the pixels
//                    not of the background within 3 pixels of that side, along it
// Exit 0 when it could read the image, 2 on bad usage or an unreadable file.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <stb_image.h>

namespace {

struct Box {
  double x = 0, y = 0, w = 0, h = 0;
  bool holds(int px, int py) const {
    return px + 0.5 >= x && px + 0.5 <= x + w && py + 0.5 >= y && py + 0.5 <= y + h;
  }
};

struct Image {
  int w = 0, h = 0;
  unsigned char* px = nullptr;  // RGB
  const unsigned char* at(int x, int y) const {
    return px + 3 * (static_cast<std::size_t>(y) * w + x);
  }
};

int usage(const std::string& why) {
  std::fprintf(stderr, "viewer_layout_pixels: %s\n", why.c_str());
  return 2;
}

// more than 24 away from `bg` on some channel
bool drawn(const unsigned char* p, const std::array<int, 3>& bg) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(p[c] - bg[c]) > 24) return true;
  return false;
}

// the drawn pixels within 3 pixels of the segment from (x0, y0) to (x1, y1), which runs
// along an axis
long nearSide(const Image& img, const std::array<int, 3>& bg, double x0, double y0, double x1,
              double y1) {
  long n = 0;
  const int lx = static_cast<int>(x0) - 3, hx = static_cast<int>(x1) + 3;
  const int ly = static_cast<int>(y0) - 3, hy = static_cast<int>(y1) + 3;
  for (int y = std::max(0, ly); y <= std::min(img.h - 1, hy); ++y)
    for (int x = std::max(0, lx); x <= std::min(img.w - 1, hx); ++x) n += drawn(img.at(x, y), bg);
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) return usage("usage: viewer_layout_pixels FILE --background RRGGBB [...]");
  std::array<int, 3> bg{0, 0, 0};
  std::vector<Box> allowed;
  Box shape;
  bool withShape = false;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    Box b;
    if (a == "--background") {
      const unsigned rgb = static_cast<unsigned>(std::strtoul(v.c_str(), nullptr, 16));
      bg = {static_cast<int>(rgb >> 16), static_cast<int>((rgb >> 8) & 0xff),
            static_cast<int>(rgb & 0xff)};
    } else if (std::sscanf(v.c_str(), "%lf,%lf,%lf,%lf", &b.x, &b.y, &b.w, &b.h) != 4) {
      return usage(a + " needs X,Y,W,H, not " + v);
    } else if (a == "--allow") {
      allowed.push_back(b);
    } else if (a == "--shape") {
      shape = b;
      withShape = true;
    } else {
      return usage("unknown option " + a);
    }
  }
  Image img;
  int channels = 0;
  img.px = stbi_load(argv[1], &img.w, &img.h, &channels, 3);
  if (!img.px) return usage(std::string(argv[1]) + ": cannot be read as an image");
  long stray = 0;
  int fx = -1, fy = -1;
  for (int y = 0; y < img.h; ++y)
    for (int x = 0; x < img.w; ++x) {
      bool inside = false;
      for (const Box& b : allowed) inside = inside || b.holds(x, y);
      if (inside || !drawn(img.at(x, y), bg)) continue;
      if (stray++ == 0) fx = x, fy = y;
    }
  std::printf("stray %ld %d %d\n", stray, fx, fy);
  if (withShape) {
    const double r = shape.x + shape.w, b = shape.y + shape.h;
    std::printf("shape %ld %ld %ld %ld\n", nearSide(img, bg, shape.x, shape.y, shape.x, b),
                nearSide(img, bg, shape.x, shape.y, r, shape.y),
                nearSide(img, bg, r, shape.y, r, b), nearSide(img, bg, shape.x, b, r, b));
  }
  stbi_image_free(img.px);
  return 0;
}
