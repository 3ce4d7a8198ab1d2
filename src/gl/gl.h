// The GL API for the whole project. Every gl* call goes through a pointer table generated at
// build time from <GL/glcorearb.h> (tools/gen_gl_loader.cmake) and filled by the backend's
// GetProcAddress. Why not libepoxy/libOpenGL: libepoxy aborts under OSMesa, and linking
// libOpenGL next to libOSMesa makes GL calls silently do nothing under OSMesa.
#pragma once

#include "gl/gl_loader_generated.h"  // GL types, enums and `#define glFoo ps_glFoo` macros

namespace ps::gl {

using ProcLoader = void* (*)(const char* name);

// Fills the table; returns the number of core entry points that stayed null.
int load_gl(ProcLoader loader);

// True once load_gl has been called with a working loader (glGetString resolved).
bool gl_loaded();

}  // namespace ps::gl
