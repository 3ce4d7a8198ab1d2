// The ES 3.0 stand-ins for the desktop calls the host code makes (gl/es30.h). Render thread only,
// like every GL call; the state below belongs to the one current ES context.
#include "gl/es30.h"

#include <algorithm>
#include <array>
#include <unordered_map>

namespace ps::gl {
namespace {

constexpr GLuint kScratchUnit = 15;

struct EsState {
  Dialect dialect = Dialect::kCore45;
  std::unordered_map<GLuint, std::vector<GLenum>> draw_buffers;  // per framebuffer, as the host set them
  std::array<bool, 8> color_on{true, true, true, true, true, true, true, true};  // glColorMaski
  std::unordered_map<GLuint, std::pair<GLint, GLint>> texture_sizes;             // level 0
  std::unordered_map<GLuint, std::unordered_map<GLint, std::string>> uniform_names;
  GLuint read_fbo = 0;  // glGetTextureSubImage's framebuffer
  // The ES entry points the stand-ins replace in their own slots.
  PFNGLBINDFRAMEBUFFERPROC bind_framebuffer = nullptr;
  PFNGLENABLEPROC enable = nullptr;
  PFNGLDISABLEPROC disable = nullptr;
  PFNGLISENABLEDPROC is_enabled = nullptr;
};
EsState g;

GLint get_int(GLenum name) {
  GLint v = 0;
  glGetIntegerv(name, &v);
  return v;
}

// ---- scopes: bind for an edit, put the binding back ----

class TextureScope {  // on the scratch unit
 public:
  explicit TextureScope(GLuint texture) : active_(get_int(GL_ACTIVE_TEXTURE)) {
    glActiveTexture(GL_TEXTURE0 + kScratchUnit);
    glBindTexture(GL_TEXTURE_2D, texture);
  }
  ~TextureScope() {
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(static_cast<GLenum>(active_));
  }
  TextureScope(const TextureScope&) = delete;
  TextureScope& operator=(const TextureScope&) = delete;

 private:
  GLint active_;
};

class FramebufferScope {  // both bindings saved; `target` bound to `fbo`
 public:
  FramebufferScope(GLenum target, GLuint fbo)
      : draw_(get_int(GL_DRAW_FRAMEBUFFER_BINDING)), read_(get_int(GL_READ_FRAMEBUFFER_BINDING)) {
    g.bind_framebuffer(target, fbo);
  }
  ~FramebufferScope() {
    g.bind_framebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_));
    g.bind_framebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_));
  }
  FramebufferScope(const FramebufferScope&) = delete;
  FramebufferScope& operator=(const FramebufferScope&) = delete;

 private:
  GLint draw_, read_;
};

class ProgramScope {
 public:
  explicit ProgramScope(GLuint program) : previous_(get_int(GL_CURRENT_PROGRAM)) { glUseProgram(program); }
  ~ProgramScope() {
    // A program deleted while current lives until another is used: by now it may be gone, and
    // using a deleted name is GL_INVALID_VALUE.
    const auto p = static_cast<GLuint>(previous_);
    glUseProgram(p != 0 && glIsProgram(p) ? p : 0);
  }
  ProgramScope(const ProgramScope&) = delete;
  ProgramScope& operator=(const ProgramScope&) = delete;

 private:
  GLint previous_;
};

// The host's draw-buffer list of `fbo` with the masked attachments left out, into the bound
// draw framebuffer (which must be `fbo`).
void apply_draw_buffers(GLuint fbo) {
  const auto it = g.draw_buffers.find(fbo);
  if (it == g.draw_buffers.end()) return;
  std::vector<GLenum> list = it->second;
  for (size_t i = 0; i < list.size() && i < g.color_on.size(); ++i)
    if (!g.color_on[i]) list[i] = GL_NONE;
  glDrawBuffers(static_cast<GLsizei>(list.size()), list.data());
}

// ---- the stand-ins, in the desktop slots ----

void APIENTRY create_textures(GLenum target, GLsizei n, GLuint* textures) {
  glGenTextures(n, textures);
  (void)target;  // the host creates GL_TEXTURE_2D only (gl/objects.cpp)
  for (GLsizei i = 0; i < n; ++i) const TextureScope scope(textures[i]);  // a name becomes a texture when first bound
}
void APIENTRY texture_storage_2d(GLuint texture, GLsizei levels, GLenum format, GLsizei w, GLsizei h) {
  const TextureScope scope(texture);
  glTexStorage2D(GL_TEXTURE_2D, levels, format, w, h);
  g.texture_sizes[texture] = {w, h};
}
void APIENTRY texture_sub_image_2d(GLuint texture, GLint level, GLint x, GLint y, GLsizei w, GLsizei h,
                                   GLenum format, GLenum type, const void* pixels) {
  const TextureScope scope(texture);
  glTexSubImage2D(GL_TEXTURE_2D, level, x, y, w, h, format, type, pixels);
}
void APIENTRY texture_parameter_i(GLuint texture, GLenum name, GLint value) {
  const TextureScope scope(texture);
  glTexParameteri(GL_TEXTURE_2D, name, value);
}
void APIENTRY generate_texture_mipmap(GLuint texture) {
  const TextureScope scope(texture);
  glGenerateMipmap(GL_TEXTURE_2D);
}
void APIENTRY bind_texture_unit(GLuint unit, GLuint texture) {
  const GLint active = get_int(GL_ACTIVE_TEXTURE);
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture);
  glActiveTexture(static_cast<GLenum>(active));
}
void APIENTRY get_texture_level_parameter_iv(GLuint texture, GLint level, GLenum name, GLint* value) {
  const auto it = g.texture_sizes.find(texture);
  const std::pair<GLint, GLint> size = it == g.texture_sizes.end() ? std::pair<GLint, GLint>{0, 0} : it->second;
  if (name == GL_TEXTURE_WIDTH) *value = std::max(1, size.first >> level);
  else if (name == GL_TEXTURE_HEIGHT) *value = std::max(1, size.second >> level);
  else *value = 0;
}
void APIENTRY get_texture_sub_image(GLuint texture, GLint level, GLint x, GLint y, GLint /*z*/, GLsizei w,
                                    GLsizei h, GLsizei /*depth*/, GLenum format, GLenum type,
                                    GLsizei /*size*/, void* pixels) {
  if (g.read_fbo == 0) glGenFramebuffers(1, &g.read_fbo);
  const FramebufferScope scope(GL_READ_FRAMEBUFFER, g.read_fbo);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, level);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(x, y, w, h, format, type, pixels);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
}

void APIENTRY create_framebuffers(GLsizei n, GLuint* fbos) {
  glGenFramebuffers(n, fbos);
  for (GLsizei i = 0; i < n; ++i) const FramebufferScope scope(GL_DRAW_FRAMEBUFFER, fbos[i]);
}
void APIENTRY named_framebuffer_texture(GLuint fbo, GLenum attachment, GLuint texture, GLint level) {
  const FramebufferScope scope(GL_DRAW_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture, level);
}
void APIENTRY named_framebuffer_renderbuffer(GLuint fbo, GLenum attachment, GLenum target, GLuint rb) {
  const FramebufferScope scope(GL_DRAW_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, attachment, target, rb);
}
void APIENTRY named_framebuffer_draw_buffers(GLuint fbo, GLsizei n, const GLenum* buffers) {
  g.draw_buffers[fbo].assign(buffers, buffers + n);
  const FramebufferScope scope(GL_DRAW_FRAMEBUFFER, fbo);
  apply_draw_buffers(fbo);
}
void APIENTRY named_framebuffer_draw_buffer(GLuint fbo, GLenum buffer) {
  named_framebuffer_draw_buffers(fbo, 1, &buffer);
}
void APIENTRY named_framebuffer_read_buffer(GLuint fbo, GLenum buffer) {
  const FramebufferScope scope(GL_READ_FRAMEBUFFER, fbo);
  glReadBuffer(buffer);
}
GLenum APIENTRY check_named_framebuffer_status(GLuint fbo, GLenum target) {
  const GLenum t = target == GL_READ_FRAMEBUFFER ? GL_READ_FRAMEBUFFER : GL_DRAW_FRAMEBUFFER;
  const FramebufferScope scope(t, fbo);
  return glCheckFramebufferStatus(t);
}
void APIENTRY clear_named_framebuffer_fv(GLuint fbo, GLenum buffer, GLint draw_buffer, const GLfloat* value) {
  const FramebufferScope scope(GL_DRAW_FRAMEBUFFER, fbo);
  glClearBufferfv(buffer, draw_buffer, value);
}
void APIENTRY blit_named_framebuffer(GLuint read, GLuint draw, GLint sx0, GLint sy0, GLint sx1, GLint sy1,
                                     GLint dx0, GLint dy0, GLint dx1, GLint dy1, GLbitfield mask,
                                     GLenum filter) {
  const FramebufferScope scope(GL_READ_FRAMEBUFFER, read);
  g.bind_framebuffer(GL_DRAW_FRAMEBUFFER, draw);
  glBlitFramebuffer(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter);
}
void APIENTRY bind_framebuffer(GLenum target, GLuint fbo) {
  g.bind_framebuffer(target, fbo);
  // The masks are global on the desktop; here they live in each framebuffer's list.
  if (target != GL_READ_FRAMEBUFFER && fbo != 0) apply_draw_buffers(fbo);
}
void APIENTRY color_mask_i(GLuint index, GLboolean r, GLboolean gr, GLboolean b, GLboolean a) {
  if (index >= g.color_on.size()) return;
  g.color_on[index] = r || gr || b || a;
  if (const auto fbo = static_cast<GLuint>(get_int(GL_DRAW_FRAMEBUFFER_BINDING)); fbo != 0) apply_draw_buffers(fbo);
}

void APIENTRY create_renderbuffers(GLsizei n, GLuint* rbs) {
  glGenRenderbuffers(n, rbs);
  const GLint previous = get_int(GL_RENDERBUFFER_BINDING);
  for (GLsizei i = 0; i < n; ++i) glBindRenderbuffer(GL_RENDERBUFFER, rbs[i]);
  glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(previous));
}
void APIENTRY named_renderbuffer_storage(GLuint rb, GLenum format, GLsizei w, GLsizei h) {
  const GLint previous = get_int(GL_RENDERBUFFER_BINDING);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, format, w, h);
  glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(previous));
}

// The ES location of `program`'s uniform at desktop `location` (-1: unknown, the call is ignored
// as GL ignores location -1).
GLint es_location(GLuint program, GLint location) {
  const auto p = g.uniform_names.find(program);
  if (p == g.uniform_names.end()) return -1;
  const auto n = p->second.find(location);
  return n == p->second.end() ? -1 : glGetUniformLocation(program, n->second.c_str());
}
void APIENTRY program_uniform_1f(GLuint program, GLint location, GLfloat v) {
  const ProgramScope scope(program);
  glUniform1f(es_location(program, location), v);
}
void APIENTRY program_uniform_1i(GLuint program, GLint location, GLint v) {
  const ProgramScope scope(program);
  glUniform1i(es_location(program, location), v);
}
void APIENTRY program_uniform_4i(GLuint program, GLint location, GLint x, GLint y, GLint z, GLint w) {
  const ProgramScope scope(program);
  glUniform4i(es_location(program, location), x, y, z, w);
}
void APIENTRY program_uniform_4f(GLuint program, GLint location, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  const ProgramScope scope(program);
  glUniform4f(es_location(program, location), x, y, z, w);
}

void APIENTRY polygon_mode(GLenum /*face*/, GLenum /*mode*/) {}
void APIENTRY enable(GLenum cap) {
  if (cap != GL_FRAMEBUFFER_SRGB) g.enable(cap);
}
void APIENTRY disable(GLenum cap) {
  if (cap != GL_FRAMEBUFFER_SRGB) g.disable(cap);
}
GLboolean APIENTRY is_enabled(GLenum cap) { return cap == GL_FRAMEBUFFER_SRGB ? GL_FALSE : g.is_enabled(cap); }

}  // namespace

Dialect dialect() { return g.dialect; }

void es30_name_uniforms(GLuint program, const std::vector<std::pair<std::string, int>>& locations) {
  if (g.dialect != Dialect::kEs30) return;
  auto& names = g.uniform_names[program];
  names.clear();
  for (const auto& [name, location] : locations) names[location] = name;
}

namespace detail {

void install_es30() {
  reset_es30();
  g.dialect = Dialect::kEs30;
  g.bind_framebuffer = ps_glBindFramebuffer;
  g.enable = ps_glEnable;
  g.disable = ps_glDisable;
  g.is_enabled = ps_glIsEnabled;
  ps_glBindFramebuffer = bind_framebuffer;
  ps_glEnable = enable;
  ps_glDisable = disable;
  ps_glIsEnabled = is_enabled;
  ps_glCreateTextures = create_textures;
  ps_glTextureStorage2D = texture_storage_2d;
  ps_glTextureSubImage2D = texture_sub_image_2d;
  ps_glTextureParameteri = texture_parameter_i;
  ps_glGenerateTextureMipmap = generate_texture_mipmap;
  ps_glBindTextureUnit = bind_texture_unit;
  ps_glGetTextureLevelParameteriv = get_texture_level_parameter_iv;
  ps_glGetTextureSubImage = get_texture_sub_image;
  ps_glCreateFramebuffers = create_framebuffers;
  ps_glNamedFramebufferTexture = named_framebuffer_texture;
  ps_glNamedFramebufferRenderbuffer = named_framebuffer_renderbuffer;
  ps_glNamedFramebufferDrawBuffers = named_framebuffer_draw_buffers;
  ps_glNamedFramebufferDrawBuffer = named_framebuffer_draw_buffer;
  ps_glNamedFramebufferReadBuffer = named_framebuffer_read_buffer;
  ps_glCheckNamedFramebufferStatus = check_named_framebuffer_status;
  ps_glClearNamedFramebufferfv = clear_named_framebuffer_fv;
  ps_glBlitNamedFramebuffer = blit_named_framebuffer;
  ps_glColorMaski = color_mask_i;
  ps_glCreateRenderbuffers = create_renderbuffers;
  ps_glNamedRenderbufferStorage = named_renderbuffer_storage;
  ps_glProgramUniform1f = program_uniform_1f;
  ps_glProgramUniform1i = program_uniform_1i;
  ps_glProgramUniform4i = program_uniform_4i;
  ps_glProgramUniform4f = program_uniform_4f;
  ps_glPolygonMode = polygon_mode;
  install_es30_vertex_arrays();
  install_es30_buffers();
}

void reset_es30() {
  g = EsState{};
  reset_es30_vertex_arrays();
  reset_es30_buffers();
}

}  // namespace detail
}  // namespace ps::gl
