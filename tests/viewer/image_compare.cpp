// viewer_image_compare — whether two pictures of one slide look alike: both are resampled to
// a small common size (the mean of the pixels each small pixel covers) and compared by
// their mean absolute difference per channel, in 0..255; or, with --max-rmse, at full size by
// their root mean square difference over all channels, in 0..1 (ImageMagick's normalised RMSE).
//
//   viewer_image_compare A.png B.png [--size WxH] [--max-mean M | --max-rmse R]
//
// Prints the difference; exit 0 when it is at most M (default 12) or R, 1 when it is larger,
// the sizes differ (RMSE) or an image cannot be read, 2 on bad usage. An image with an alpha
// channel is composited on white first (rsvg-convert's output).
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
  std::fprintf(
      stderr,
      "usage: viewer_image_compare A.png B.png [--size WxH] [--max-mean M | --max-rmse R]\n");
  return 2;
}

// the images as full-size RGB, each on white; their RMSE in 0..1, or -1 when either cannot
// be read or their sizes differ
double fullRmse(const char* a, const char* b) {
  int w[2] = {0, 0}, h[2] = {0, 0}, n = 0;
  unsigned char* px[2] = {stbi_load(a, &w[0], &h[0], &n, 4), stbi_load(b, &w[1], &h[1], &n, 4)};
  double rmse = -1.0;
  if (px[0] && px[1] && w[0] == w[1] && h[0] == h[1]) {
    double sum = 0.0;
    const std::size_t count = static_cast<std::size_t>(w[0]) * static_cast<std::size_t>(h[0]);
    for (std::size_t k = 0; k < count; ++k)
      for (int c = 0; c < 3; ++c) {
        double v[2];
        for (int i = 0; i < 2; ++i) {
          const double alpha = px[i][4 * k + 3] / 255.0;
          v[i] = (alpha * px[i][4 * k + c] + (1.0 - alpha) * 255.0) / 255.0;
        }
        sum += (v[0] - v[1]) * (v[0] - v[1]);
      }
    rmse = std::sqrt(sum / static_cast<double>(3 * count));
  }
  for (unsigned char* p : px)
    if (p) stbi_image_free(p);
  return rmse;
}

int compareRmse(const char* a, const char* b, double most) {
  const double rmse = fullRmse(a, b);
  if (rmse < 0.0) {
    std::fprintf(stderr, "%s, %s: cannot be read, or their sizes differ\n", a, b);
    return 1;
  }
  std::printf("%s vs %s: RMSE %.4f at full size (at most %.4f)\n", a, b, rmse, most);
  return rmse <= most ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  int w = 480, h = 270;
  double most = 12.0, rmse = -1.0;
  for (int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--size" && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%dx%d", &w, &h) != 2 || w <= 0 || h <= 0) return usage();
    } else if (a == "--max-mean" && i + 1 < argc) {
      most = std::atof(argv[++i]);
    } else if (a == "--max-rmse" && i + 1 < argc) {
      rmse = std::atof(argv[++i]);
    } else {
      return usage();
    }
  }
  if (rmse >= 0.0) return compareRmse(argv[1], argv[2], rmse);
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
