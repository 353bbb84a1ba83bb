// convexloc-viewer — GLSL programs loaded from files, with their compile and link logs.
#pragma once

#include <string>
#include <unordered_map>

#include <glm/glm.hpp>

#include "gl/gl.hpp"
#include "gl/no_copy.hpp"

namespace convexloc::viewer {

// one linked GLSL program and its uniforms' locations
class ShaderProgram : NoCopy {
 public:
  ~ShaderProgram();

  // Compiles DIR/NAME.vert and DIR/NAME.frag and links them. On failure keeps the program
  // it had (if any), returns false and fills `log` with "NAME.frag: <compiler output>".
  bool load(const std::string& dir, const std::string& name, std::string& log);
  bool ready() const { return id_ != 0; }
  void use() const { glUseProgram(id_); }

  void set(const char* name, const glm::mat4& m);
  void set(const char* name, const glm::vec4& v);
  void set(const char* name, const glm::vec3& v);
  void set(const char* name, const glm::vec2& v);
  void set(const char* name, float v);
  void set(const char* name, int v);
  void setArray(const char* name, const glm::vec4* v, int count);

 private:
  GLint location(const char* name);
  GLuint id_ = 0;
  std::unordered_map<std::string, GLint> locations_;
};

}  // namespace convexloc::viewer
