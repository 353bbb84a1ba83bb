// viewer_png_check — asserts what a viewer screenshot shows: its size, and that colours are
// present where the scene must draw them.
//
//   viewer_png_check FILE [--size WxH] [--tolerance T]
//                    [--expect LABEL:RRGGBB:X0,Y0,X1,Y1:MIN]... [--not-uniform X0,Y0,X1,Y1]...
//
// A region is given in fractions of the image (0,0 top left; 1,1 bottom right). --expect
// needs at least MIN pixels within T (default 24) of the colour on every channel there;
// --not-uniform needs the region to hold more than one colour. Exit 0 when every check
// holds, 1 otherwise, 2 on bad usage.
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include <stb_image.h>

namespace {

struct Region {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
};

bool parseRegion(const std::string& s, Region& r) {
  return std::sscanf(s.c_str(), "%lf,%lf,%lf,%lf", &r.x0, &r.y0, &r.x1, &r.y1) == 4 &&
         r.x0 < r.x1 && r.y0 < r.y1;
}

struct Image {
  int w = 0, h = 0;
  unsigned char* px = nullptr;  // RGB
  const unsigned char* at(int x, int y) const {
    return px + 3 * (static_cast<std::size_t>(y) * w + x);
  }
};

// calls f(pixel) for every pixel of the region
template <class F>
void forRegion(const Image& img, const Region& r, F f) {
  const int x0 = static_cast<int>(r.x0 * img.w), x1 = static_cast<int>(r.x1 * img.w);
  const int y0 = static_cast<int>(r.y0 * img.h), y1 = static_cast<int>(r.y1 * img.h);
  for (int y = std::max(0, y0); y < std::min(img.h, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(img.w, x1); ++x) f(img.at(x, y));
}

int usage(const char* why) {
  std::fprintf(stderr, "viewer_png_check: %s\n", why);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2)
    return usage(
        "usage: viewer_png_check FILE [--size WxH] [--expect L:RRGGBB:X0,Y0,X1,Y1:MIN]...");
  Image img;
  int channels = 0;
  img.px = stbi_load(argv[1], &img.w, &img.h, &channels, 3);
  if (!img.px) {
    std::fprintf(stderr, "viewer_png_check: %s: cannot be read as an image (%s)\n", argv[1],
                 stbi_failure_reason());
    return 1;
  }
  int tolerance = 24;
  bool ok = true;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return usage(("missing value after " + a).c_str());
    const std::string v = argv[++i];
    if (a == "--tolerance") {
      tolerance = std::atoi(v.c_str());
    } else if (a == "--size") {
      int w = 0, h = 0;
      if (std::sscanf(v.c_str(), "%dx%d", &w, &h) != 2) return usage("--size needs WxH");
      const bool good = w == img.w && h == img.h;
      std::printf("%s size %dx%d (expected %dx%d)\n", good ? "ok  " : "FAIL", img.w, img.h, w, h);
      ok &= good;
    } else if (a == "--expect") {
      char label[64];
      unsigned rgb = 0;
      char region[128];
      long minimum = 0;
      if (std::sscanf(v.c_str(), "%63[^:]:%x:%127[^:]:%ld", label, &rgb, region, &minimum) != 4)
        return usage("--expect needs LABEL:RRGGBB:X0,Y0,X1,Y1:MIN");
      Region r;
      if (!parseRegion(region, r)) return usage("a region is X0,Y0,X1,Y1 with X0 < X1, Y0 < Y1");
      const int want[3] = {static_cast<int>(rgb >> 16), static_cast<int>((rgb >> 8) & 0xff),
                           static_cast<int>(rgb & 0xff)};
      long count = 0;
      forRegion(img, r, [&](const unsigned char* p) {
        bool near = true;
        for (int c = 0; c < 3; ++c) near &= std::abs(p[c] - want[c]) <= tolerance;
        count += near;
      });
      const bool good = count >= minimum;
      std::printf("%s %-10s #%06X in %s: %ld pixels (at least %ld)\n", good ? "ok  " : "FAIL",
                  label, rgb, region, count, minimum);
      ok &= good;
    } else if (a == "--not-uniform") {
      Region r;
      if (!parseRegion(v, r)) return usage("a region is X0,Y0,X1,Y1 with X0 < X1, Y0 < Y1");
      std::set<unsigned> colours;
      forRegion(img, r, [&](const unsigned char* p) {
        if (colours.size() < 64) colours.insert((p[0] << 16) | (p[1] << 8) | p[2]);
      });
      const bool good = colours.size() > 8;
      std::printf("%s %zu+ distinct colours in %s\n", good ? "ok  " : "FAIL", colours.size(),
                  v.c_str());
      ok &= good;
    } else {
      return usage(("unknown option " + a).c_str());
    }
  }
  stbi_image_free(img.px);
  return ok ? 0 : 1;
}
