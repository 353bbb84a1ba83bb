// convexloc-viewer — GLSL programs.
#include "gl/shader.hpp"

#include <fstream>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

namespace convexloc::viewer {
namespace {

// the whole file, or false
bool readFile(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  out = s.str();
  return true;
}

// the info log of a shader or a program, read with its own two getters
template <class GetInt, class GetLog>
std::string infoLog(GLuint id, GetInt getInt, GetLog getLog) {
  GLint length = 0;
  getInt(id, GL_INFO_LOG_LENGTH, &length);
  std::string info(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
  getLog(id, length, nullptr, info.data());
  return info.c_str();
}

// a compiled shader, or 0 with the log
GLuint compile(GLenum kind, const std::string& source, const std::string& label, std::string& log) {
  GLuint s = glCreateShader(kind);
  const char* text = source.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (ok) return s;
  log += label + ": " + infoLog(s, glGetShaderiv, glGetShaderInfoLog) + "\n";
  glDeleteShader(s);
  return 0;
}

}  // namespace

ShaderProgram::~ShaderProgram() {
  if (id_) glDeleteProgram(id_);
}

bool ShaderProgram::load(const std::string& dir, const std::string& name, std::string& log) {
  std::string vs, fs;
  const std::string vpath = dir + "/" + name + ".vert", fpath = dir + "/" + name + ".frag";
  if (!readFile(vpath, vs)) {
    log += vpath + ": cannot be read\n";
    return false;
  }
  if (!readFile(fpath, fs)) {
    log += fpath + ": cannot be read\n";
    return false;
  }
  GLuint v = compile(GL_VERTEX_SHADER, vs, name + ".vert", log);
  GLuint f = compile(GL_FRAGMENT_SHADER, fs, name + ".frag", log);
  if (!v || !f) {
    if (v) glDeleteShader(v);
    if (f) glDeleteShader(f);
    return false;
  }
  GLuint p = glCreateProgram();
  glAttachShader(p, v);
  glAttachShader(p, f);
  glLinkProgram(p);
  glDeleteShader(v);
  glDeleteShader(f);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    log += name + " (link): " + infoLog(p, glGetProgramiv, glGetProgramInfoLog) + "\n";
    glDeleteProgram(p);
    return false;
  }
  if (id_) glDeleteProgram(id_);
  id_ = p;
  locations_.clear();
  return true;
}

GLint ShaderProgram::location(const char* name) {
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  const GLint loc = glGetUniformLocation(id_, name);
  locations_.emplace(name, loc);
  return loc;
}

void ShaderProgram::set(const char* name, const glm::mat4& m) {
  glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(m));
}
void ShaderProgram::set(const char* name, const glm::vec4& v) {
  glUniform4fv(location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::vec3& v) {
  glUniform3fv(location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::vec2& v) {
  glUniform2fv(location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, float v) {
  glUniform1f(location(name), v);
}
void ShaderProgram::set(const char* name, int v) {
  glUniform1i(location(name), v);
}
void ShaderProgram::setArray(const char* name, const glm::vec4* v, int count) {
  glUniform4fv(location(name), count, glm::value_ptr(v[0]));
}

}  // namespace convexloc::viewer
