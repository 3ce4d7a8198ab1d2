#include "api/api_context.h"

#include <mutex>

namespace pseudoshadow::api {

namespace {

ps::gl::Backend to_gl(Backend b) {
  switch (b) {
    case Backend::kEgl: return ps::gl::Backend::kEgl;
    case Backend::kOsmesa: return ps::gl::Backend::kOsmesa;
    case Backend::kAuto: break;
  }
  return ps::gl::Backend::kAuto;
}

}  // namespace

ps::gl::GpuChoice to_gpu(const std::string& gpu) {
  if (gpu.empty()) return {};
  auto choice = ps::gl::parse_gpu(gpu);
  if (!choice || choice->kind == ps::gl::GpuChoice::Kind::kList)
    throw Error("gpu \"" + gpu + "\": expected \"\", auto, software or a device number");
  return choice.value();
}

// Whether the open context is on the display `gpu` asks for: "" and auto take any.
bool same_display(const ps::gl::GpuChoice& gpu, const ps::gl::Context& context) {
  using Kind = ps::gl::GpuChoice::Kind;
  const std::string& on = context.egl_device();
  if (gpu.kind == Kind::kIndex) return on.rfind("device " + std::to_string(gpu.index) + " ", 0) == 0;
  if (gpu.kind == Kind::kSoftware) return on.rfind("device ", 0) == 0;
  return true;
}

std::shared_ptr<ps::gl::Context> acquire_context(Backend backend, const std::string& gpu_text) {
  static std::mutex mutex;
  static std::weak_ptr<ps::gl::Context> live;
  std::lock_guard<std::mutex> lock(mutex);
  const ps::gl::Backend wanted = to_gl(backend);
  const ps::gl::GpuChoice gpu = to_gpu(gpu_text);
  if (std::shared_ptr<ps::gl::Context> context = live.lock()) {
    if (!same_display(gpu, *context))
      throw Error("gpu " + gpu_text + ": a renderer on EGL display " + context->egl_device() +
                  " is open, and a process has one GL display at a time: close the other renderers first");
    if (wanted != ps::gl::Backend::kAuto && wanted != context->backend()) {
      throw Error(std::string("backend ") + ps::gl::backend_name(wanted) + ": a renderer on " +
                  ps::gl::backend_name(context->backend()) +
                  " is open, and a process has one GL backend at a time: close the other renderers "
                  "first, or open this one with backend auto or " +
                  ps::gl::backend_name(context->backend()));
    }
    context->make_current();
    return context;
  }
  ps::gl::ContextDesc desc;
  desc.backend = wanted;
  desc.gpu = gpu;
  auto created = ps::gl::create_context(desc);
  if (!created) throw Error(created.error().message);
  std::shared_ptr<ps::gl::Context> context(std::move(created.value()));
  live = context;
  return context;
}

}  // namespace pseudoshadow::api
