#pragma once
// Owning handles for the few OpenGL objects the renderer makes, and shader compilation with readable errors.

#include <GL/gl.h>  // with GL_GLEXT_PROTOTYPES: the 3.3 core entry points, exported by libOSMesa

#include <cstddef>
#include <initializer_list>

namespace physltl::render {

class GlProgram {
 public:
  GlProgram(const char* vertex_source, const char* fragment_source);  // throws with the compiler log
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  void use() const { glUseProgram(id_); }
  GLint uniform(const char* name) const;  // throws when the shader has no such uniform

 private:
  GLuint id_ = 0;
};

// A vertex array with one vertex buffer of interleaved floats.
class GlMesh {
 public:
  // components: floats per attribute, e.g. {3, 3} for position + normal.
  explicit GlMesh(std::initializer_list<int> components);
  ~GlMesh();
  GlMesh(const GlMesh&) = delete;
  GlMesh& operator=(const GlMesh&) = delete;

  void upload(const float* data, std::size_t floats, GLenum usage = GL_STREAM_DRAW);
  void draw(GLenum mode) const;  // every uploaded vertex

 private:
  GLuint vao_ = 0;
  GLuint vbo_ = 0;
  int stride_ = 0;  // floats per vertex
  GLsizei vertices_ = 0;
};

}  // namespace physltl::render
