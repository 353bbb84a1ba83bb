// convexloc-viewer — the GL context's own calls: loading the functions, what the context
// is, clearing the window, reading its pixels back. With renderer.cpp, shader.cpp and
// scene_view.cpp, the only code that calls GL.
#pragma once

#include <string>
#include <vector>

#include "logic/base/colour.hpp"

namespace convexloc::viewer {

// a GL function's address, as a window system's loader returns it
using GlProc = void (*)();
using GlLoader = GlProc (*)(const char* name);

// Loads the GL 3.3 core functions through `loader` for the current context; false when
// the context cannot provide them.
bool loadGlFunctions(GlLoader loader);

// what the current context is
struct GlInfo {
  std::string renderer;   // "llvmpipe (LLVM 15.0.6, 256 bits)", a GPU's name
  std::string version;    // "4.5 (Core Profile) Mesa 22.3.6"
  bool software = false;  // a software renderer (llvmpipe, softpipe, SWR)
  int maxSamples = 0;     // the most multisamples a target may have
};
GlInfo queryGl();

// lets multisampled targets resolve with anti-aliasing
void enableMultisample();

// lets vertex shaders set the size of points (GL ES always does)
void enableShaderPointSize();

// clears the window's framebuffer (width x height pixels) to `background`, depth too
void clearWindow(int width, int height, Rgba background);

// Reads the window's back buffer (width x height), bottom row first, as RGB bytes; on a GL
// error returns an empty vector and says why in `problem`.
std::vector<unsigned char> readWindowRgb(int width, int height, std::string& problem);

// waits until the GL has done everything asked of it (for honest frame times)
void finishGl();

}  // namespace convexloc::viewer
