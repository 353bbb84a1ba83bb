// viewer_image_compare — whether two pictures of one slide look alike: both are resampled to
// a small common size (the mean of the pixels each small pixel covers) and compared by
// their mean absolute difference per channel, in 0..255.
//
//   viewer_image_compare A.png B.png [--size WxH] [--max-mean M]
//
// Prints the difference; exit 0 when it is at most M (default 12), 1 when it is larger or
// an image cannot be read, 2 on bad usage. An image with an alpha channel is composited on
// white first (rsvg-convert's output).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <stb_image.h>

namespace {

// an image resampled to w x h, RGB as doubles
struct Small {
  int w = 0, h = 0;
  std::vector<double> rgb;
};

// the area-weighted mean of the pixels under each small pixel (box filter), or empty when
// `path` cannot be read
Small resample(const char* path, int w, int h) {
  int iw = 0, ih = 0, n = 0;
  unsigned char* px = stbi_load(path, &iw, &ih, &n, 4);
  Small s;
  if (!px) return s;
  s.w = w, s.h = h;
  s.rgb.assign(static_cast<std::size_t>(3 * w * h), 0.0);
  std::vector<double> weight(static_cast<std::size_t>(w * h), 0.0);
  for (int y = 0; y < ih; ++y)
    for (int x = 0; x < iw; ++x) {
      const unsigned char* p = px + 4 * (static_cast<std::size_t>(y) * iw + x);
      const int sx = static_cast<int>(static_cast<long long>(x) * w / iw);
      const int sy = static_cast<int>(static_cast<long long>(y) * h / ih);
      const std::size_t k = static_cast<std::size_t>(sy * w + sx);
      const double a = p[3] / 255.0;
      for (int c = 0; c < 3; ++c) s.rgb[3 * k + c] += a * p[c] + (1.0 - a) * 255.0;
      weight[k] += 1.0;
    }
  for (std::size_t k = 0; k < weight.size(); ++k)
    for (int c = 0; c < 3; ++c) s.rgb[3 * k + c] /= weight[k] > 0.0 ? weight[k] : 1.0;
  stbi_image_free(px);
  return s;
}

int usage() {
  std::fprintf(stderr, "usage: viewer_image_compare A.png B.png [--size WxH] [--max-mean M]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  int w = 480, h = 270;
  double most = 12.0;
  for (int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--size" && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%dx%d", &w, &h) != 2 || w <= 0 || h <= 0) return usage();
    } else if (a == "--max-mean" && i + 1 < argc) {
      most = std::atof(argv[++i]);
    } else {
      return usage();
    }
  }
  const Small a = resample(argv[1], w, h), b = resample(argv[2], w, h);
  if (a.rgb.empty() || b.rgb.empty()) {
    std::fprintf(stderr, "%s: cannot be read\n", a.rgb.empty() ? argv[1] : argv[2]);
    return 1;
  }
  double sum = 0.0;
  for (std::size_t k = 0; k < a.rgb.size(); ++k) sum += std::abs(a.rgb[k] - b.rgb[k]);
  const double mean = sum / static_cast<double>(a.rgb.size());
  std::printf("%s vs %s: mean difference %.2f of 255 at %dx%d (at most %.2f)\n", argv[1], argv[2],
              mean, w, h, most);
  return mean <= most ? 0 : 1;
}
