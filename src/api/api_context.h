// The API's GL context: one per process, shared by every pseudoshadow::Renderer alive.
// src/gl keeps one table of GL entry points per process and a context's destruction clears it
// (gl/gl_loader.cpp), so two contexts alive at once would leave one of them without GL.
#pragma once

#include <memory>

#include "gl/context.h"
#include "pseudoshadow/pseudoshadow.h"

namespace pseudoshadow::api {

// The live context if one is (it must be of `backend`, or `backend` must be auto; and on the
// display `gpu` names, or `gpu` must be "" or "auto"), else a new one. Throws Error: no context
// ("no OpenGL 4.5 context: egl: ...; osmesa: ..."), a bad or missing `gpu`, or another backend
// or display already open.
std::shared_ptr<ps::gl::Context> acquire_context(Backend backend, const std::string& gpu);

}  // namespace pseudoshadow::api
