// convexloc-viewer — the GL context's own calls.
#include "gl/context.hpp"

#include "gl/gl.hpp"

namespace convexloc::viewer {
namespace {

// the string GL reports for `name`, or "" when it reports none
std::string glText(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

bool loadGlFunctions(GlLoader loader) {
  return gladLoadGL(loader) != 0;
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
  glEnable(GL_MULTISAMPLE);
}

void clearWindow(int width, int height, Rgba background) {
  glViewport(0, 0, width, height);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glDepthMask(GL_TRUE);  // a clear honours the depth mask
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

std::vector<unsigned char> readWindowRgb(int width, int height, std::string& problem) {
  std::vector<unsigned char> rgb(static_cast<std::size_t>(width) *
                                 static_cast<std::size_t>(height) * 3);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  if (GLenum e = glGetError(); e != GL_NO_ERROR) {
    problem = "glReadPixels failed (GL error " + std::to_string(e) + ")";
    return {};
  }
  return rgb;
}

void finishGl() {
  glFinish();
}

}  // namespace convexloc::viewer
