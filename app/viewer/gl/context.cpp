// convexloc-viewer — the GL context's own calls.
#include "gl/context.hpp"

#include "gl/gl.hpp"

#ifndef CONVEXLOC_GLES
#define CONVEXLOC_GLES 0
#endif

namespace convexloc::viewer {
namespace {

// the string GL reports for `name`, or "" when it reports none
std::string glText(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

bool loadGlFunctions(GlLoader loader) {
#if CONVEXLOC_GLES
  (void)loader;  // WebGL's functions are there without a loader
  return true;
#else
  return gladLoadGL(loader) != 0;
#endif
}

GlInfo queryGl() {
  GlInfo info;
  info.renderer = glText(GL_RENDERER);
  info.version = glText(GL_VERSION);
  info.software = info.renderer.find("llvmpipe") != std::string::npos ||
                  info.renderer.find("softpipe") != std::string::npos ||
                  info.renderer.find("SWR") != std::string::npos;
  GLint samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &samples);
  info.maxSamples = static_cast<int>(samples);
  return info;
}

void enableMultisample() {
#if !CONVEXLOC_GLES  // GL ES resolves multisampled targets with anti-aliasing always
  glEnable(GL_MULTISAMPLE);
#endif
}

void enableShaderPointSize() {
#if !CONVEXLOC_GLES
  glEnable(GL_PROGRAM_POINT_SIZE);
#endif
}

void clearWindow(int width, int height, Rgba background) {
  glViewport(0, 0, width, height);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glDepthMask(GL_TRUE);  // a clear honours the depth mask
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

std::vector<unsigned char> readWindowRgb(int width, int height, std::string& problem) {
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  // GL ES promises RGBA reads only: read those and drop the alpha
  constexpr std::size_t kRead = CONVEXLOC_GLES ? 4 : 3;
  std::vector<unsigned char> rgb(pixels * kRead);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, kRead == 4 ? GL_RGBA : GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  if (GLenum e = glGetError(); e != GL_NO_ERROR) {
    problem = "glReadPixels failed (GL error " + std::to_string(e) + ")";
    return {};
  }
  if (kRead == 4) {
    for (std::size_t i = 0; i < pixels; ++i)
      for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = rgb[i * 4 + c];
    rgb.resize(pixels * 3);
  }
  return rgb;
}

void finishGl() {
  glFinish();
}

}  // namespace convexloc::viewer
