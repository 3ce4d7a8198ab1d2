// Backend selection: parse_backend, backend_name and create_context (kAuto = EGL, then OSMesa).
#include "gl/context.h"

#include <cassert>

#include "gl/context_internal.h"
#include "gl/egl_device.h"

namespace ps::gl {

Result<Backend> parse_backend(const std::string& name) {
  if (name == "auto") return Backend::kAuto;
  if (name == "egl") return Backend::kEgl;
  if (name == "osmesa") return Backend::kOsmesa;
  if (name == "glfw") return Backend::kGlfw;
  return make_error("unknown backend \"" + name + "\" (expected auto, egl, osmesa or glfw)");
}

Result<GpuChoice> parse_gpu(const std::string& text) {
  using Kind = GpuChoice::Kind;
  if (text == "auto") return GpuChoice{Kind::kAuto, -1};
  if (text == "list") return GpuChoice{Kind::kList, -1};
  if (text == "software") return GpuChoice{Kind::kSoftware, -1};
  if (!text.empty() && text.size() <= 4 && text.find_first_not_of("0123456789") == std::string::npos)
    return GpuChoice{Kind::kIndex, std::stoi(text)};
  return make_error("unknown GPU \"" + text + "\" (expected auto, list, software or a device number)");
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

namespace {

// --gpu auto: the first hardware EGL device, else the surfaceless platform, else (backend auto)
// OSMesa; the context's egl_device() says which and why.
Result<std::unique_ptr<Context>> create_auto_gpu(const ContextDesc& desc) {
  std::string why = "no hardware EGL device";
  if (auto devices = list_egl_devices(); devices) {
    for (const EglDeviceInfo& d : devices.value()) {
      if (d.software) continue;
      ContextDesc on_device = desc;
      on_device.gpu = {GpuChoice::Kind::kIndex, d.index};
      auto context = detail::create_egl_context(on_device);
      if (context) {
        context.value()->set_egl_device_note("gpu auto: the first hardware EGL device");
        return context;
      }
      why = "hardware EGL device " + std::to_string(d.index) + ": " + context.error().message;
      break;
    }
  } else {
    why = devices.error().message;
  }
  ContextDesc fallback = desc;
  fallback.gpu = {};
  auto context = create_context(fallback);
  if (context) context.value()->set_egl_device_note("gpu auto: " + why);
  return context;
}

}  // namespace

Result<std::unique_ptr<Context>> create_context(const ContextDesc& desc) {
  const std::string prefix = "no OpenGL 4.5 context: ";
  using Kind = GpuChoice::Kind;
  assert(desc.gpu.kind != Kind::kList && "create_context: --gpu list is the CLI's, not a context");
  if (desc.es) {
    if (desc.backend != Backend::kEgl && desc.backend != Backend::kAuto)
      return make_error(std::string("no OpenGL ES 3.0 context: ES needs the EGL backend (got ") +
                        backend_name(desc.backend) + ")");
    auto context = detail::create_egl_context(desc);
    if (!context) return make_error("no OpenGL ES 3.0 context: egl: " + context.error().message);
    return context;
  }
  if (desc.gpu.kind != Kind::kDefault && desc.backend != Backend::kEgl && desc.backend != Backend::kAuto)
    return make_error(prefix + "--gpu needs the EGL backend (got " + backend_name(desc.backend) + ")");
  if (desc.gpu.kind == Kind::kAuto) return create_auto_gpu(desc);
  // A device asked for by name is EGL only: falling back to OSMesa would hide a missing device.
  const Backend only = desc.gpu.kind == Kind::kDefault ? desc.backend : Backend::kEgl;
  if (only != Backend::kAuto) {
    auto context = create_one(only, desc);
    if (!context) {
      return make_error(prefix + backend_name(only) + ": " + context.error().message);
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
