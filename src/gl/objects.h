// Move-only RAII wrappers for GL objects (Magnum style: release() hands the name over).
// Raw GLuint names never leave src/gl/ except through id(), used by code that calls GL.
// Objects must be destroyed on the thread (and with the context) that created them.
#pragma once

#include <utility>

#include "gl/gl.h"

namespace ps::gl {

template <void (*Delete)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(other.release()) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) { reset(); id_ = other.release(); }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  GLuint release() { return std::exchange(id_, 0u); }
  void reset() { if (id_ != 0) { Delete(id_); id_ = 0; } }

 private:
  GLuint id_ = 0;
};

void delete_buffer(GLuint id);
void delete_texture(GLuint id);
void delete_framebuffer(GLuint id);
void delete_renderbuffer(GLuint id);
void delete_vertex_array(GLuint id);
void delete_program(GLuint id);
void delete_shader(GLuint id);

using Buffer = Handle<delete_buffer>;
using Texture = Handle<delete_texture>;
using Framebuffer = Handle<delete_framebuffer>;
using Renderbuffer = Handle<delete_renderbuffer>;
using VertexArray = Handle<delete_vertex_array>;
using Program = Handle<delete_program>;
using Shader = Handle<delete_shader>;

// DSA creation helpers (GL 4.5).
Buffer make_buffer(GLsizeiptr size, const void* data, GLbitfield flags);
// 2D texture with `levels` mip levels (levels = 0: full chain) and the given internal format.
Texture make_texture_2d(GLsizei width, GLsizei height, GLenum internal_format, GLsizei levels = 1);
Framebuffer make_framebuffer();
Renderbuffer make_renderbuffer(GLenum internal_format, GLsizei width, GLsizei height);
VertexArray make_vertex_array();

}  // namespace ps::gl
