// convexloc-viewer — the one place stb_image_write's code is compiled (as static functions,
// so they never clash with libstb's), built without our warning flags: it is third-party
// code. With zlib its deflate is zlib's at its default level 6: screenshots come out about a
// third smaller than with stb's own, and within 2% of zlib's level 9 in a sixth of its time
// (a 3840x2160 lecture's ten slides: 1.3 s against 8.1 s of deflating).
#include "writers/png_write.hpp"

#include <cstdlib>

#if CONVEXLOC_VIEWER_ZLIB
#include <zlib.h>

namespace {
// stb_image_write's compression hook: a buffer from malloc (stb frees it with free)
unsigned char* zlibCompress(unsigned char* data, int length, int* outLength, int /*quality*/) {
  uLongf size = compressBound(static_cast<uLong>(length));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (!out) return nullptr;
  if (compress2(out, &size, data, static_cast<uLong>(length), Z_DEFAULT_COMPRESSION) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *outLength = static_cast<int>(size);
  return out;
}
}  // namespace

#define STBIW_ZLIB_COMPRESS zlibCompress
#endif

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

namespace convexloc::viewer {

bool writePngRgb(const char* path, int width, int height, const unsigned char* rgb, bool bottomUp) {
  stbi_flip_vertically_on_write(bottomUp ? 1 : 0);
  stbi_write_png_compression_level = 9;
  return stbi_write_png(path, width, height, 3, rgb, width * 3) != 0;
}

}  // namespace convexloc::viewer
