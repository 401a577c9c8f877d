#include "gl_objects.h"

#include <stdexcept>
#include <string>

namespace physltl::render {
namespace {

GLuint compile(GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("shader does not compile: ") + log);
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(const char* vertex_source, const char* fragment_source) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source);
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragment_source);
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(id_, sizeof log, nullptr, log);
    glDeleteProgram(id_);
    throw std::runtime_error(std::string("shader program does not link: ") + log);
  }
}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

GLint GlProgram::uniform(const char* name) const {
  const GLint location = glGetUniformLocation(id_, name);
  if (location < 0) throw std::runtime_error(std::string("shader has no uniform ") + name);
  return location;
}

GlMesh::GlMesh(std::initializer_list<int> components) {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  for (int c : components) stride_ += c;
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  GLuint index = 0;
  std::size_t offset = 0;
  for (int c : components) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, c, GL_FLOAT, GL_FALSE, stride_ * sizeof(float),
                          reinterpret_cast<const void*>(offset * sizeof(float)));
    ++index;
    offset += c;
  }
}

GlMesh::~GlMesh() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void GlMesh::upload(const float* data, std::size_t floats, GLenum usage) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, floats * sizeof(float), data, usage);
  vertices_ = static_cast<GLsizei>(floats / stride_);
}

void GlMesh::draw(GLenum mode) const {
  if (vertices_ == 0) return;
  glBindVertexArray(vao_);
  glDrawArrays(mode, 0, vertices_);
}

}  // namespace physltl::render
