// Backend selection: parse_backend, backend_name and create_context (kAuto = EGL, then OSMesa).
#include "gl/context.h"

#include <cassert>

#include "gl/context_internal.h"

namespace ps::gl {

Result<Backend> parse_backend(const std::string& name) {
  if (name == "auto") return Backend::kAuto;
  if (name == "egl") return Backend::kEgl;
  if (name == "osmesa") return Backend::kOsmesa;
  if (name == "glfw") return Backend::kGlfw;
  return make_error("unknown backend \"" + name + "\" (expected auto, egl, osmesa or glfw)");
}

const char* backend_name(Backend backend) {
  switch (backend) {
    case Backend::kAuto: return "auto";
    case Backend::kEgl: return "egl";
    case Backend::kOsmesa: return "osmesa";
    case Backend::kGlfw: return "glfw";
  }
  assert(false && "backend_name: Backend value out of range");
  return "?";
}

namespace {

Result<std::unique_ptr<Context>> create_one(Backend backend, const ContextDesc& desc) {
  switch (backend) {
    case Backend::kEgl: return detail::create_egl_context(desc);
    case Backend::kOsmesa: return detail::create_osmesa_context(desc);
    case Backend::kGlfw: return detail::create_glfw_context(desc);
    case Backend::kAuto: break;
  }
  assert(false && "create_one: kAuto must be expanded by create_context");
  return make_error("internal: create_one(kAuto)");
}

}  // namespace

Result<std::unique_ptr<Context>> create_context(const ContextDesc& desc) {
  const std::string prefix = "no OpenGL 4.5 context: ";
  if (desc.backend != Backend::kAuto) {
    auto context = create_one(desc.backend, desc);
    if (!context) {
      return make_error(prefix + backend_name(desc.backend) + ": " + context.error().message);
    }
    return context;
  }
  // Headless only: GLFW needs a display, so kAuto never tries it.
  std::string why;
  for (Backend backend : {Backend::kEgl, Backend::kOsmesa}) {
    auto context = create_one(backend, desc);
    if (context) return context;
    why += (why.empty() ? "" : "; ") + std::string(backend_name(backend)) + ": " +
           context.error().message;
  }
  return make_error(prefix + why);
}

}  // namespace ps::gl
