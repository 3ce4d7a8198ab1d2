// Private to src/gl: per-backend factories and the shared "load GL and check 4.5 core" step.
// Backend files that include platform headers pulling in <GL/gl.h> (osmesa.h) must not include
// gl/gl.h as well: its `#define glFoo ps_glFoo` macros would rename gl.h's prototypes.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/result.h"
#include "gl/context.h"

namespace ps::gl::detail {

using Loader = void* (*)(const char* name);

// Fills the GL table with `loader`, then checks every core entry point resolved and that the
// current context is 4.5 core; reads GL_RENDERER / GL_VERSION. Error text has no backend prefix.
Status load_gl_and_query(Loader loader, std::string& renderer, std::string& version);
// The same for an OpenGL ES 3.0 (or later) context: the table holds ES 3.0 entry points only, and
// the desktop calls the host code makes get their stand-ins (gl/es30.h).
Status load_gles_and_query(Loader loader, std::string& renderer, std::string& version);
// Nulls the table; called by each context's destructor before the context goes away.
void unload_gl();

// Each returns an error message without the "no OpenGL 4.5 context: <backend>: " prefix.
// desc.gpu picks the display: kDefault = surfaceless; kSoftware / kIndex = that EGL device.
Result<std::unique_ptr<Context>> create_egl_context(const ContextDesc& desc);
// eglQueryDevicesEXT's list (EGLDeviceEXT handles as void*, so this header needs no EGL).
Result<std::vector<void*>> query_egl_devices();
Result<std::unique_ptr<Context>> create_osmesa_context(const ContextDesc& desc);
Result<std::unique_ptr<Context>> create_glfw_context(const ContextDesc& desc);

}  // namespace ps::gl::detail
