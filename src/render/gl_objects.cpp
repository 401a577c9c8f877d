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

GlFramebuffer::GlFramebuffer(int width, int height) : width_(width), height_(height) {
  glGenTextures(1, &color_);
  glBindTexture(GL_TEXTURE_2D, color_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGenTextures(1, &depth_);
  glBindTexture(GL_TEXTURE_2D, depth_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, width, height, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  for (GLuint texture : {color_, depth_}) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    throw std::runtime_error("the OpenGL driver cannot make a " + std::to_string(width) + "x" + std::to_string(height) +
                             " framebuffer (status " + std::to_string(status) + ")");
  }
}

GlFramebuffer::~GlFramebuffer() { release(); }

void GlFramebuffer::release() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(1, &color_);
  glDeleteTextures(1, &depth_);
  fbo_ = color_ = depth_ = 0;
}

namespace {

void blit(GLuint from, GLuint to, const PixelArea& source, const PixelArea& target, GLbitfield mask, GLenum filter) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
  glBlitFramebuffer(source.x0, source.y0, source.x1, source.y1, target.x0, target.y0, target.x1, target.y1, mask, filter);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw std::runtime_error("OpenGL refused to copy a framebuffer (error " + std::to_string(error) + ")");
}

}  // namespace

void copy_framebuffer(GLuint from, int from_width, int from_height, GLuint to, int to_width, int to_height,
                      GLbitfield mask, GLenum filter) {
  blit(from, to, {0, 0, from_width, from_height}, {0, 0, to_width, to_height}, mask, filter);
}

void copy_framebuffer_area(GLuint from, GLuint to, const PixelArea& area, GLbitfield mask) {
  blit(from, to, area, area, mask, GL_NEAREST);
}

}  // namespace physltl::render
