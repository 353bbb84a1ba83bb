// convexloc-viewer — PNG files from pixels (stb_image_write, deflated by zlib when found).
#pragma once

namespace convexloc::viewer {

// Writes `rgb` (width x height pixels, 3 bytes each, rows top to bottom unless
// `bottomUp`) to `path` as a PNG. Returns false when the file cannot be written.
bool writePngRgb(const char* path, int width, int height, const unsigned char* rgb, bool bottomUp);

}  // namespace convexloc::viewer
