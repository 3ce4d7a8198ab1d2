// The host code on OpenGL ES 3.0 (the API WebGL2 exposes) under its desktop names.
//
// The renderer and its passes are written against OpenGL 4.5 core with direct state access
// (glNamedFramebufferTexture, glTextureParameteri, glProgramUniform1f ...). ES 3.0 has none of
// those. On an ES context (ContextDesc::es) the pointer table is filled with ES 3.0 entry points
// only (the names in GLES3/gl3.h, even where Mesa's context would give 3.2, so what runs here
// is what a WebGL2 page has), and each desktop call the host code makes gets a stand-in in the
// same slot: bind, make the classic call, put the binding back. The call sites stay as they are,
// and on a 4.5 context nothing of this runs. docs/web.md has the table of calls and stand-ins.
//
// What the stand-ins use:
//   - texture unit 15 and GL_COPY_WRITE_BUFFER as scratch binding points (the passes use texture
//     units 0-2 and never bind COPY_WRITE); left unbound afterwards;
//   - glCreateBuffers + glNamedBufferStorage as glGenBuffers, the data kept on the host until the
//     buffer's first binding, which uploads it: WebGL2 fixes a buffer's kind (index or other data)
//     at its first binding, and an index buffer must not have been bound elsewhere first
//     (es30_buffer.cpp);
//   - framebuffer, vertex array, renderbuffer and program bindings saved and restored (the
//     vertex-array stand-ins are in es30_vertex.cpp);
//   - glColorMaski(i, all false) as draw buffer i set to GL_NONE in the bound framebuffer's list
//     (an attachment left out is not written, as a masked one is not); a mask with some channels
//     on and some off is taken as on (the host code masks whole attachments only);
//   - glProgramUniform* as glUseProgram + glUniform* at the location of the uniform's name: ES
//     3.00 has no `layout(location = N)` on uniforms, so build_program records each program's
//     names for their desktop locations (es30_name_uniforms);
//   - glGetTextureSubImage as a framebuffer on the texture and glReadPixels;
//   - glGetTextureLevelParameteriv (width, height) from the sizes given to glTextureStorage2D;
//   - glPolygonMode: nothing (a wireframe is drawn filled);
//   - glEnable/glDisable(GL_FRAMEBUFFER_SRGB): nothing (ES has no such switch), and
//     glIsEnabled(GL_FRAMEBUFFER_SRGB) is false.
// Compute shaders, storage buffers and timer queries have no stand-in: on ES the renderer uses
// the fragment reductions and no GPU timers (render/renderer.cpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "gl/gl.h"

namespace ps::gl {

enum class Dialect { kCore45, kEs30 };
// The API the current pointer table holds (kCore45 when none is loaded).
Dialect dialect();

// ES only (a no-op on 4.5): `program`'s loose uniforms, as (name, desktop location) pairs from
// to_glsl_es, so glProgramUniform*(program, location, ...) finds them by name. Replaces what was
// recorded for the same program id before.
void es30_name_uniforms(GLuint program, const std::vector<std::pair<std::string, int>>& locations);

// ES only: how many bindings so far WebGL2 would have refused for the buffer's kind (an index
// buffer bound to a target other than ELEMENT_ARRAY/COPY_*, another buffer bound as indices).
// Mesa's ES 3.0 has no such rule; the tests check the renderer keeps it.
int es30_webgl_buffer_conflicts();

namespace detail {
// After the table was filled with ES 3.0 entry points: puts the stand-ins in the desktop slots
// and sets dialect() to kEs30. reset_es30() forgets every recorded object (the context is gone).
void install_es30();
void reset_es30();
// The vertex-array part of both (gl/es30_vertex.cpp).
void install_es30_vertex_arrays();
void reset_es30_vertex_arrays();
// The buffer part (gl/es30_buffer.cpp).
void install_es30_buffers();
void reset_es30_buffers();
}  // namespace detail

}  // namespace ps::gl

// tools/gen_gl_loader.cmake: true when `name` is an OpenGL ES 3.0 entry point (GLES3/gl3.h); how
// many of those `loader` returns null for (the first one's name in *first_missing).
bool ps_gl_is_es30(const char* name);
int ps_gl_es30_missing(void* (*loader)(const char*), const char** first_missing);
