// Deleters and DSA (GL 4.5) creation helpers for the RAII handles in objects.h.
#include "gl/objects.h"

#include <algorithm>
#include <bit>
#include <cassert>

namespace ps::gl {

void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void delete_renderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }
void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
void delete_program(GLuint id) { glDeleteProgram(id); }
void delete_shader(GLuint id) { glDeleteShader(id); }

Buffer make_buffer(GLsizeiptr size, const void* data, GLbitfield flags) {
  assert(gl_loaded() && "make_buffer: no current GL context (create_context first)");
  assert(size > 0 && "make_buffer: size must be > 0 (immutable storage cannot be empty)");
  GLuint id = 0;
  glCreateBuffers(1, &id);
  glNamedBufferStorage(id, size, data, flags);
  return Buffer(id);
}

Texture make_texture_2d(GLsizei width, GLsizei height, GLenum internal_format, GLsizei levels) {
  assert(gl_loaded() && "make_texture_2d: no current GL context (create_context first)");
  assert(width > 0 && height > 0 && "make_texture_2d: width and height must be > 0");
  if (levels == 0) {  // full chain down to 1x1
    levels = static_cast<GLsizei>(std::bit_width(static_cast<unsigned>(std::max(width, height))));
  }
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, levels, internal_format, width, height);
  return Texture(id);
}

Framebuffer make_framebuffer() {
  assert(gl_loaded() && "make_framebuffer: no current GL context (create_context first)");
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return Framebuffer(id);
}

Renderbuffer make_renderbuffer(GLenum internal_format, GLsizei width, GLsizei height) {
  assert(gl_loaded() && "make_renderbuffer: no current GL context (create_context first)");
  assert(width > 0 && height > 0 && "make_renderbuffer: width and height must be > 0");
  GLuint id = 0;
  glCreateRenderbuffers(1, &id);
  glNamedRenderbufferStorage(id, internal_format, width, height);
  return Renderbuffer(id);
}

VertexArray make_vertex_array() {
  assert(gl_loaded() && "make_vertex_array: no current GL context (create_context first)");
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id);
}

}  // namespace ps::gl
