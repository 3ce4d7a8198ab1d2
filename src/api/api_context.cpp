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

std::shared_ptr<ps::gl::Context> acquire_context(Backend backend) {
  static std::mutex mutex;
  static std::weak_ptr<ps::gl::Context> live;
  std::lock_guard<std::mutex> lock(mutex);
  const ps::gl::Backend wanted = to_gl(backend);
  if (std::shared_ptr<ps::gl::Context> context = live.lock()) {
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
  auto created = ps::gl::create_context(desc);
  if (!created) throw Error(created.error().message);
  std::shared_ptr<ps::gl::Context> context(std::move(created.value()));
  live = context;
  return context;
}

}  // namespace pseudoshadow::api
