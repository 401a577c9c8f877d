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

// An offscreen framebuffer with an RGBA8 colour and a 24-bit depth texture.
class GlFramebuffer {
 public:
  GlFramebuffer(int width, int height);  // throws when the driver cannot complete it
  ~GlFramebuffer();
  GlFramebuffer(const GlFramebuffer&) = delete;
  GlFramebuffer& operator=(const GlFramebuffer&) = delete;

  GLuint id() const { return fbo_; }
  GLuint color_texture() const { return color_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void release();

  GLuint fbo_ = 0;
  GLuint color_ = 0;
  GLuint depth_ = 0;
  int width_;
  int height_;
};

// Copies `mask` (GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT) from one framebuffer to the whole of another,
// scaling with `filter`; throws when the driver refuses (e.g. depth formats that differ).
void copy_framebuffer(GLuint from, int from_width, int from_height, GLuint to, int to_width, int to_height,
                      GLbitfield mask, GLenum filter);

// Pixels [x0, x1) x [y0, y1) of a framebuffer, rows counted upwards as OpenGL does.
struct PixelArea {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};
// Copies `mask` of `area` from one framebuffer to the same place in another of the same size.
void copy_framebuffer_area(GLuint from, GLuint to, const PixelArea& area, GLbitfield mask);

}  // namespace physltl::render
