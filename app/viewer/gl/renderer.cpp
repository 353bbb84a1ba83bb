// convexloc-viewer — the GL backend.
#include "gl/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "gl/context.hpp"

namespace convexloc::viewer {
namespace {

// the layouts uploaded, as the shaders read them
struct GpuFill {
  float pos[3];
  float colour[4];
  float normal[3];
};
struct GpuSegment {
  float a[3];
  float b[3];
  float colour[4];
  float style[2];
};
struct GpuMarker {
  float pos[3];
  float colour[4];
  float sizeShape[2];
};

void put3(float* out, glm::dvec3 p, glm::dvec3 origin) {
  const glm::dvec3 l = p - origin;
  out[0] = static_cast<float>(l.x);
  out[1] = static_cast<float>(l.y);
  out[2] = static_cast<float>(l.z);
}
void put4(float* out, Rgba c) {
  out[0] = c.r;
  out[1] = c.g;
  out[2] = c.b;
  out[3] = c.a;
}
glm::vec4 vec(Rgba c) {
  return {c.r, c.g, c.b, c.a};
}

// a float attribute of `size` components at byte `offset`, advancing per vertex or instance
void attribute(GLuint index, GLint size, GLsizei stride, std::size_t offset, GLuint divisor) {
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(offset));
  glVertexAttribDivisor(index, divisor);
}

// the byte offset of a field in its record
template <class Record, class Field>
std::size_t offsetIn(Field Record::*field) {
  static const Record record{};
  return static_cast<std::size_t>(reinterpret_cast<const char*>(&(record.*field)) -
                                  reinterpret_cast<const char*>(&record));
}

// a new vertex array over a new buffer of Records, whose float-array fields are the
// attributes 0, 1, ... in order, advancing per vertex (divisor 0) or per instance (1)
template <class Record, class... Fields>
void makeArray(GLuint& vao, GLuint& vbo, GLuint divisor, Fields Record::*... fields) {
  glGenVertexArrays(1, &vao);
  glGenBuffers(1, &vbo);
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  GLuint index = 0;
  (attribute(index++, static_cast<GLint>(sizeof(Fields) / sizeof(float)), sizeof(Record),
             offsetIn(fields), divisor),
   ...);
}

template <class T>
void uploadBuffer(GLuint vbo, const std::vector<T>& data) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(T)),
               data.empty() ? nullptr : data.data(), GL_DYNAMIC_DRAW);
}

// converts each item to its GPU record with `convert`, uploads the records into `vbo`,
// and returns how many there are
template <class Gpu, class Item, class Convert>
GLsizei uploadAs(GLuint vbo, const std::vector<Item>& items, Convert convert) {
  std::vector<Gpu> records(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) convert(items[i], records[i]);
  uploadBuffer(vbo, records);
  return static_cast<GLsizei>(records.size());
}

void commonUniforms(ShaderProgram& p, const FrameParams& f) {
  p.use();
  p.set("uClipFromLocal", f.clipFromLocal);
  p.set("uPixelRatio", f.pixelRatio);
}

void blending(const FrameParams& f) {
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  if (f.depth) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glDepthMask(f.depthWrite ? GL_TRUE : GL_FALSE);
  if (f.offset) {
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
  } else {
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
}

}  // namespace

Renderer::~Renderer() {
  if (!created_) return;
  for (GpuLayer& l : layers_) {
    GLuint vaos[3] = {l.fillVao, l.segVao, l.markVao};
    GLuint vbos[3] = {l.fillVbo, l.segVbo, l.markVbo};
    glDeleteVertexArrays(3, vaos);
    glDeleteBuffers(3, vbos);
  }
  glDeleteVertexArrays(1, &pointVao_);
  GLuint vbos[2] = {pointVbo_, classVbo_};
  glDeleteBuffers(2, vbos);
  destroyTarget();
  if (blitVao_) glDeleteVertexArrays(1, &blitVao_);
}

void Renderer::destroyTarget() {
  if (msFbo_) glDeleteFramebuffers(1, &msFbo_);
  if (resolveFbo_) glDeleteFramebuffers(1, &resolveFbo_);
  GLuint rbs[3] = {msColour_, msDepth_, depth_};
  glDeleteRenderbuffers(3, rbs);
  if (texture_) glDeleteTextures(1, &texture_);
  msFbo_ = msColour_ = msDepth_ = resolveFbo_ = texture_ = depth_ = 0;
  targetW_ = targetH_ = 0;
}

bool Renderer::ensureTarget(int width, int height, int samples) {
  if (width <= 0 || height <= 0) return false;
  if (resolveFbo_ && width == targetW_ && height == targetH_ && samples == targetSamples_)
    return true;
  destroyTarget();
  // the single-sampled target: a texture to composite from, and depth
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glGenFramebuffers(1, &resolveFbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  bool ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  // the multisampled target, resolved into the texture
  if (ok && samples > 0) {
    glGenRenderbuffers(1, &msColour_);
    glBindRenderbuffer(GL_RENDERBUFFER, msColour_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    glGenRenderbuffers(1, &msDepth_);
    glBindRenderbuffer(GL_RENDERBUFFER, msDepth_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
    glGenFramebuffers(1, &msFbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, msFbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msColour_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msDepth_);
    ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  if (!ok) {
    destroyTarget();
    return false;
  }
  if (!blitVao_) glGenVertexArrays(1, &blitVao_);
  targetW_ = width;
  targetH_ = height;
  targetSamples_ = samples;
  return true;
}

void Renderer::bindTarget() {
  glBindFramebuffer(GL_FRAMEBUFFER, msFbo_ ? msFbo_ : resolveFbo_);
  glViewport(0, 0, targetW_, targetH_);
}

void Renderer::finishTarget() {
  if (msFbo_) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msFbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbo_);
    glBlitFramebuffer(0, 0, targetW_, targetH_, 0, 0, targetW_, targetH_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::compositeTarget() {
  if (!texture_ || !blit_.ready()) return;
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  blit_.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_);
  blit_.set("uScene", 0);
  glBindVertexArray(blitVao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

bool Renderer::init(const std::string& dir) {
  dir_ = dir;
  if (!created_) {
    created_ = true;
    for (GpuLayer& l : layers_) {
      makeArray(l.fillVao, l.fillVbo, 0, &GpuFill::pos, &GpuFill::colour, &GpuFill::normal);
      // a segment is an instance: one record for its four corners
      makeArray(l.segVao, l.segVbo, 1, &GpuSegment::a, &GpuSegment::b, &GpuSegment::colour,
                &GpuSegment::style);
      makeArray(l.markVao, l.markVbo, 0, &GpuMarker::pos, &GpuMarker::colour,
                &GpuMarker::sizeShape);
    }
    glGenVertexArrays(1, &pointVao_);
    glGenBuffers(1, &pointVbo_);
    glGenBuffers(1, &classVbo_);
    glBindVertexArray(pointVao_);
    glBindBuffer(GL_ARRAY_BUFFER, pointVbo_);
    attribute(0, 3, 3 * sizeof(float), 0, 0);
    glBindBuffer(GL_ARRAY_BUFFER, classVbo_);
    glEnableVertexAttribArray(1);
    glVertexAttribIPointer(1, 1, GL_UNSIGNED_BYTE, 1, nullptr);
    glBindVertexArray(0);
  }
  return compileAll();
}

bool Renderer::reload() {
  return compileAll();
}

bool Renderer::compileAll() {
  log_.clear();
  bool ok = fill_.load(dir_, "fill", log_);
  ok = segments_.load(dir_, "segments", log_) && ok;
  ok = markers_.load(dir_, "markers", log_) && ok;
  ok = points_.load(dir_, "points", log_) && ok;
  ok = blit_.load(dir_, "blit", log_) && ok;
  return ok;
}

void Renderer::upload(Layer layer, const DrawList& list, glm::dvec3 origin) {
  GpuLayer& l = layers_[static_cast<int>(layer)];
  l.fills = uploadAs<GpuFill>(l.fillVbo, list.fills, [&](const FillVertex& v, GpuFill& g) {
    put3(g.pos, v.p, origin);
    put4(g.colour, v.colour);
    std::memcpy(g.normal, &v.normal[0], sizeof g.normal);
  });
  l.segments = uploadAs<GpuSegment>(l.segVbo, list.segments, [&](const Segment& s, GpuSegment& g) {
    put3(g.a, s.a, origin);
    put3(g.b, s.b, origin);
    put4(g.colour, s.colour);
    g.style[0] = s.width;
    g.style[1] = s.dash;
  });
  l.markers = uploadAs<GpuMarker>(l.markVbo, list.markers, [&](const Marker& m, GpuMarker& g) {
    put3(g.pos, m.p, origin);
    put4(g.colour, m.colour);
    g.sizeShape[0] = m.size;
    g.sizeShape[1] = static_cast<float>(m.shape);
  });
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

template <class P, class Put>
void Renderer::uploadOrdered(std::span<const P> points, std::span<const Location> classes,
                             Put put) {
  static_assert(sizeof(Location) == 1, "classes upload as bytes");
  const std::size_t n = std::min(points.size(), classes.size());
  // boundary points last, each part in the spray's (random) order
  std::vector<float> xyz(3 * n);
  std::vector<Location> cls(n);
  std::size_t front = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (classes[i] != Location::Boundary) front++;
  std::size_t a = 0, b = front;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = classes[i] != Location::Boundary ? a++ : b++;
    put(&xyz[3 * k], points[i]);
    cls[k] = classes[i];
  }
  glBindBuffer(GL_ARRAY_BUFFER, pointVbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(xyz.size() * sizeof(float)),
               xyz.empty() ? nullptr : xyz.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, classVbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(cls.size()),
               cls.empty() ? nullptr : cls.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  pointCount_ = n;
  boundaryStart_ = front;
}

void Renderer::uploadPoints(std::span<const Vec2> points, std::span<const Location> classes,
                            glm::dvec3 origin) {
  uploadOrdered(points, classes, [&](float* out, Vec2 p) {
    out[0] = static_cast<float>(p.x - origin.x);
    out[1] = static_cast<float>(p.y - origin.y);
    out[2] = 0.0f;
  });
}

void Renderer::uploadPoints(std::span<const Vec3> points, std::span<const Location> classes,
                            glm::dvec3 origin) {
  uploadOrdered(points, classes, [&](float* out, Vec3 p) { put3(out, {p.x, p.y, p.z}, origin); });
}

void Renderer::drawFills(Layer layer, const FrameParams& f, Cull cull) {
  const GpuLayer& l = layers_[static_cast<int>(layer)];
  if (!l.fills || !fill_.ready()) return;
  blending(f);
  if (cull == Cull::None) {
    glDisable(GL_CULL_FACE);
  } else {
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glCullFace(cull == Cull::Front ? GL_FRONT : GL_BACK);
  }
  commonUniforms(fill_, f);
  fill_.set("uEye", f.eyeLocal);
  glBindVertexArray(l.fillVao);
  glDrawArrays(GL_TRIANGLES, 0, l.fills);
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::drawSegments(Layer layer, const FrameParams& f) {
  const GpuLayer& l = layers_[static_cast<int>(layer)];
  if (!l.segments || !segments_.ready()) return;
  blending(f);
  commonUniforms(segments_, f);
  segments_.set("uPixelRatio", f.pixelRatio * f.lineScale);
  segments_.set("uViewport", f.framebuffer);
  glBindVertexArray(l.segVao);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, l.segments);
}

void Renderer::drawMarkers(Layer layer, const FrameParams& f) {
  const GpuLayer& l = layers_[static_cast<int>(layer)];
  if (!l.markers || !markers_.ready()) return;
  FrameParams flat = f;
  flat.depth = false;
  flat.offset = false;
  blending(flat);
  enableShaderPointSize();
  commonUniforms(markers_, f);
  markers_.set("uPixelRatio", f.pixelRatio * f.lineScale);
  glBindVertexArray(l.markVao);
  glDrawArrays(GL_POINTS, 0, l.markers);
}

void Renderer::drawPoints(const FrameParams& f, PointRange range) {
  if (!pointCount_ || !points_.ready()) return;
  blending(f);
  enableShaderPointSize();
  commonUniforms(points_, f);
  points_.set("uPointSize", f.pointSize);
  points_.set("uBoundaryScale", 1.7f);
  points_.set("uVisible", static_cast<int>(f.visibleMask));
  const glm::vec4 colours[3] = {vec(f.classColours[0]), vec(f.classColours[1]),
                                vec(f.classColours[2])};
  points_.setArray("uColours", colours, 3);
  points_.set("uRim", vec(f.rim));
  glBindVertexArray(pointVao_);
  // a subsample keeps the same share of each part
  const double share = f.maxPoints >= pointCount_
                           ? 1.0
                           : static_cast<double>(f.maxPoints) / static_cast<double>(pointCount_);
  auto part = [&](std::size_t first, std::size_t count) {
    const auto k = static_cast<GLsizei>(std::ceil(share * static_cast<double>(count)));
    if (k > 0) glDrawArrays(GL_POINTS, static_cast<GLint>(first), k);
  };
  if (range != PointRange::Boundary)
    part(0, range == PointRange::All ? pointCount_ : boundaryStart_);
  if (range == PointRange::Boundary) part(boundaryStart_, pointCount_ - boundaryStart_);
}

void Renderer::clipTo(ScreenRect rect, const FrameParams& f) {
  const double r = f.pixelRatio;
  glEnable(GL_SCISSOR_TEST);
  glScissor(static_cast<GLint>(std::lround(rect.lo.x * r)),
            static_cast<GLint>(std::lround(f.framebuffer.y - rect.hi.y * r)),
            static_cast<GLsizei>(std::lround(rect.size().x * r)),
            static_cast<GLsizei>(std::lround(rect.size().y * r)));
}

void Renderer::clearClip() {
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace convexloc::viewer
