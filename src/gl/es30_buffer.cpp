// The ES 3.0 stand-ins for the buffer calls (gl/es30.h), written for WebGL2's rule on buffer kinds.
//
// WebGL2 (its specification, 5.1 "Buffer Object Binding") gives each buffer a kind at its first
// binding: "element array" when bound to GL_ELEMENT_ARRAY_BUFFER, "other data" when bound to any
// other target, COPY_READ/COPY_WRITE included when the kind is still undefined. An element-array
// buffer may later be bound to ELEMENT_ARRAY_BUFFER and the two copy targets only; an other-data
// buffer never to ELEMENT_ARRAY_BUFFER; any other such binding is refused (INVALID_OPERATION).
// OpenGL ES 3.0 has no such rule, so Mesa's ES context would not show a break of it.
//
// The desktop calls create a buffer and fill it before anything says what it is for
// (gl::make_buffer, then glVertexArrayElementBuffer for a mesh's indices). Binding it to
// COPY_WRITE to fill it would make every buffer "other data". So glNamedBufferStorage on a buffer
// of undefined kind keeps its data on the host, and the buffer's first real binding (glBindBuffer,
// glBindBufferBase, glBindBufferRange, also those the stand-ins make) gives the kind and uploads
// it there. The kinds are tracked here as WebGL tracks them, and a binding WebGL would refuse is
// counted (es30_webgl_buffer_conflicts), so the tests in Mesa's ES context can hold the renderer
// to the rule a browser enforces.
#include <cstddef>
#include <cstring>
#include <optional>
#include <unordered_map>
#include <vector>

#include "gl/es30.h"

namespace ps::gl {
namespace {

enum class Kind { kUndefined, kElementArray, kOther };

struct Pending {  // glNamedBufferStorage's arguments, until the first binding
  GLsizeiptr size = 0;
  std::vector<std::byte> data;  // empty: no data given (contents undefined, as glBufferData's)
  GLenum usage = GL_STATIC_DRAW;
};

struct BufferState {
  Kind kind = Kind::kUndefined;
  std::optional<Pending> pending;
};

struct Buffers {
  std::unordered_map<GLuint, BufferState> states;
  int conflicts = 0;
  // The ES entry points the stand-ins replace in their own slots.
  PFNGLBINDBUFFERPROC bind_buffer = nullptr;
  PFNGLBINDBUFFERBASEPROC bind_buffer_base = nullptr;
  PFNGLBINDBUFFERRANGEPROC bind_buffer_range = nullptr;
  PFNGLDELETEBUFFERSPROC delete_buffers = nullptr;
};
Buffers g_buffers;  // render thread only, as every GL call

bool is_copy_target(GLenum target) { return target == GL_COPY_READ_BUFFER || target == GL_COPY_WRITE_BUFFER; }

// WebGL2's kind rule for binding `buffer` to `target`; a refused binding is counted.
void take_kind(GLuint buffer, GLenum target) {
  if (buffer == 0) return;
  BufferState& s = g_buffers.states[buffer];
  const Kind wanted = target == GL_ELEMENT_ARRAY_BUFFER ? Kind::kElementArray : Kind::kOther;
  if (s.kind == Kind::kUndefined) {
    s.kind = wanted;
  } else if (s.kind != wanted && !(s.kind == Kind::kElementArray && is_copy_target(target))) {
    ++g_buffers.conflicts;
  }
}

// `buffer` is bound to `target`: its kept data goes up now.
void upload_pending(GLuint buffer, GLenum target) {
  const auto it = g_buffers.states.find(buffer);
  if (it == g_buffers.states.end() || !it->second.pending) return;
  const Pending& p = *it->second.pending;
  glBufferData(target, p.size, p.data.empty() ? nullptr : p.data.data(), p.usage);
  it->second.pending.reset();
}

void APIENTRY bind_buffer(GLenum target, GLuint buffer) {
  take_kind(buffer, target);
  g_buffers.bind_buffer(target, buffer);
  upload_pending(buffer, target);
}
void APIENTRY bind_buffer_base(GLenum target, GLuint index, GLuint buffer) {
  take_kind(buffer, target);
  if (buffer != 0 && g_buffers.states[buffer].pending) {
    g_buffers.bind_buffer(target, buffer);  // glBindBufferBase binds the generic point too
    upload_pending(buffer, target);
  }
  g_buffers.bind_buffer_base(target, index, buffer);
}
void APIENTRY bind_buffer_range(GLenum target, GLuint index, GLuint buffer, GLintptr offset, GLsizeiptr size) {
  take_kind(buffer, target);
  if (buffer != 0 && g_buffers.states[buffer].pending) {
    g_buffers.bind_buffer(target, buffer);
    upload_pending(buffer, target);
  }
  g_buffers.bind_buffer_range(target, index, buffer, offset, size);
}
void APIENTRY delete_buffers(GLsizei n, const GLuint* buffers) {
  for (GLsizei i = 0; i < n; ++i) g_buffers.states.erase(buffers[i]);
  g_buffers.delete_buffers(n, buffers);
}

void APIENTRY create_buffers(GLsizei n, GLuint* buffers) {
  glGenBuffers(n, buffers);  // the object comes with its first binding, its kind with it
  for (GLsizei i = 0; i < n; ++i) g_buffers.states[buffers[i]] = BufferState{};
}
void APIENTRY named_buffer_storage(GLuint buffer, GLsizeiptr size, const void* data, GLbitfield flags) {
  const GLenum usage = (flags & GL_DYNAMIC_STORAGE_BIT) ? GL_DYNAMIC_DRAW : GL_STATIC_DRAW;
  BufferState& s = g_buffers.states[buffer];
  if (s.kind == Kind::kUndefined) {
    Pending p{size, {}, usage};
    if (data != nullptr) {
      const auto* bytes = static_cast<const std::byte*>(data);
      p.data.assign(bytes, bytes + size);
    }
    s.pending = std::move(p);
    return;
  }
  bind_buffer(GL_COPY_WRITE_BUFFER, buffer);  // allowed for either kind once it has one
  glBufferData(GL_COPY_WRITE_BUFFER, size, data, usage);
  bind_buffer(GL_COPY_WRITE_BUFFER, 0);
}
void APIENTRY named_buffer_sub_data(GLuint buffer, GLintptr offset, GLsizeiptr size, const void* data) {
  BufferState& s = g_buffers.states[buffer];
  if (s.pending) {
    Pending& p = *s.pending;
    if (p.data.empty()) p.data.assign(static_cast<std::size_t>(p.size), std::byte{0});
    std::memcpy(p.data.data() + offset, data, static_cast<std::size_t>(size));
    return;
  }
  bind_buffer(GL_COPY_WRITE_BUFFER, buffer);
  glBufferSubData(GL_COPY_WRITE_BUFFER, offset, size, data);
  bind_buffer(GL_COPY_WRITE_BUFFER, 0);
}

}  // namespace

int es30_webgl_buffer_conflicts() { return g_buffers.conflicts; }

namespace detail {

void install_es30_buffers() {
  g_buffers.bind_buffer = ps_glBindBuffer;
  g_buffers.bind_buffer_base = ps_glBindBufferBase;
  g_buffers.bind_buffer_range = ps_glBindBufferRange;
  g_buffers.delete_buffers = ps_glDeleteBuffers;
  ps_glBindBuffer = bind_buffer;
  ps_glBindBufferBase = bind_buffer_base;
  ps_glBindBufferRange = bind_buffer_range;
  ps_glDeleteBuffers = delete_buffers;
  ps_glCreateBuffers = create_buffers;
  ps_glNamedBufferStorage = named_buffer_storage;
  ps_glNamedBufferSubData = named_buffer_sub_data;
}

void reset_es30_buffers() { g_buffers = Buffers{}; }

}  // namespace detail
}  // namespace ps::gl
