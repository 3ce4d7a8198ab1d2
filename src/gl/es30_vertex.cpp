// The ES 3.0 stand-ins for the vertex-array calls (gl/es30.h): ES 3.0 has no separate attribute
// format and binding (glVertexAttribFormat is 3.1), so each attribute's format, binding and that
// binding's buffer are kept, and glVertexAttribPointer is called once all three are known.
#include <climits>
#include <cstdint>
#include <map>
#include <unordered_map>

#include "gl/es30.h"

namespace ps::gl {
namespace {

struct AttribFormat {
  bool has_format = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLboolean normalized = GL_FALSE;
  GLuint relative_offset = 0;
  GLuint binding = UINT_MAX;
};
struct VertexBinding {
  bool set = false;
  GLuint buffer = 0;
  GLintptr offset = 0;
  GLsizei stride = 0;
};
struct VertexArrayState {
  std::map<GLuint, AttribFormat> attribs;
  std::map<GLuint, VertexBinding> bindings;
};

std::unordered_map<GLuint, VertexArrayState> g_vertex_arrays;  // render thread only, as every GL call

GLint get_int(GLenum name) {
  GLint v = 0;
  glGetIntegerv(name, &v);
  return v;
}

class VertexArrayScope {
 public:
  explicit VertexArrayScope(GLuint vao)
      : vao_(get_int(GL_VERTEX_ARRAY_BINDING)), array_buffer_(get_int(GL_ARRAY_BUFFER_BINDING)) {
    glBindVertexArray(vao);
  }
  ~VertexArrayScope() {
    glBindVertexArray(static_cast<GLuint>(vao_));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer_));
  }
  VertexArrayScope(const VertexArrayScope&) = delete;
  VertexArrayScope& operator=(const VertexArrayScope&) = delete;

 private:
  GLint vao_, array_buffer_;
};

// glVertexAttribPointer once an attribute has its format, its binding and that binding's buffer.
void apply_attrib(GLuint vao, GLuint index) {
  const VertexArrayState& s = g_vertex_arrays[vao];
  const auto a = s.attribs.find(index);
  if (a == s.attribs.end() || !a->second.has_format) return;
  const auto b = s.bindings.find(a->second.binding);
  if (b == s.bindings.end() || !b->second.set) return;
  const VertexArrayScope scope(vao);
  glBindBuffer(GL_ARRAY_BUFFER, b->second.buffer);
  const auto offset = static_cast<std::uintptr_t>(b->second.offset) + a->second.relative_offset;
  glVertexAttribPointer(index, a->second.size, a->second.type, a->second.normalized, b->second.stride,
                        reinterpret_cast<const void*>(offset));
}

void APIENTRY create_vertex_arrays(GLsizei n, GLuint* vaos) {
  glGenVertexArrays(n, vaos);
  for (GLsizei i = 0; i < n; ++i) {
    const VertexArrayScope scope(vaos[i]);
    g_vertex_arrays[vaos[i]] = {};
  }
}
void APIENTRY enable_vertex_array_attrib(GLuint vao, GLuint index) {
  const VertexArrayScope scope(vao);
  glEnableVertexAttribArray(index);
}
void APIENTRY vertex_array_attrib_format(GLuint vao, GLuint index, GLint size, GLenum type, GLboolean normalized,
                                        GLuint relative_offset) {
  AttribFormat& a = g_vertex_arrays[vao].attribs[index];
  a.has_format = true;
  a.size = size;
  a.type = type;
  a.normalized = normalized;
  a.relative_offset = relative_offset;
  apply_attrib(vao, index);
}
void APIENTRY vertex_array_attrib_binding(GLuint vao, GLuint index, GLuint binding) {
  g_vertex_arrays[vao].attribs[index].binding = binding;
  apply_attrib(vao, index);
}
void APIENTRY vertex_array_vertex_buffer(GLuint vao, GLuint binding, GLuint buffer, GLintptr offset, GLsizei stride) {
  VertexArrayState& s = g_vertex_arrays[vao];
  s.bindings[binding] = {true, buffer, offset, stride};
  for (const auto& [index, a] : s.attribs)
    if (a.binding == binding) apply_attrib(vao, index);
}
void APIENTRY vertex_array_element_buffer(GLuint vao, GLuint buffer) {
  const VertexArrayScope scope(vao);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
}

}  // namespace

namespace detail {

void install_es30_vertex_arrays() {
  ps_glCreateVertexArrays = create_vertex_arrays;
  ps_glEnableVertexArrayAttrib = enable_vertex_array_attrib;
  ps_glVertexArrayAttribFormat = vertex_array_attrib_format;
  ps_glVertexArrayAttribBinding = vertex_array_attrib_binding;
  ps_glVertexArrayVertexBuffer = vertex_array_vertex_buffer;
  ps_glVertexArrayElementBuffer = vertex_array_element_buffer;
}

void reset_es30_vertex_arrays() { g_vertex_arrays.clear(); }

}  // namespace detail
}  // namespace ps::gl
