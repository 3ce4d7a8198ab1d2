// OSMesa backend: software context rendering into a client buffer. OSMesa cannot be current
// without a buffer, so the context owns a 1x1 RGBA8 one; the renderer draws into FBOs anyway.
// Only <GL/osmesa.h> here (it pulls in <GL/gl.h>), never gl/gl.h: see context_internal.h.
#include <GL/osmesa.h>

#include <array>
#include <cstdint>

#include "gl/context_internal.h"

namespace ps::gl::detail {
namespace {

void* osmesa_loader(const char* name) {
  return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

class OsmesaContext final : public Context {
 public:
  explicit OsmesaContext(OSMesaContext context) : context_(context) {}
  ~OsmesaContext() override {
    unload_gl();
    // Destroying the current context leaves no context current (Mesa's _mesa_make_current(NULL)).
    OSMesaDestroyContext(context_);
  }
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  Backend backend() const override { return Backend::kOsmesa; }
  void make_current() override {
    OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1);
  }

  Status init() {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      return make_error("OSMesaMakeCurrent failed on a 1x1 RGBA8 buffer");
    }
    return load_gl_and_query(osmesa_loader, renderer_, version_);
  }

 private:
  OSMesaContext context_;
  std::array<std::uint8_t, 4> buffer_{};  // 1x1 RGBA8 target that OSMesaMakeCurrent requires
};

}  // namespace

Result<std::unique_ptr<Context>> create_osmesa_context(const ContextDesc& /*desc*/) {
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                         OSMESA_DEPTH_BITS, 24,
                         OSMESA_STENCIL_BITS, 8,
                         OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 4,
                         OSMESA_CONTEXT_MINOR_VERSION, 5,
                         0};
  OSMesaContext raw = OSMesaCreateContextAttribs(attribs, nullptr);
  if (raw == nullptr) {
    // OSMesa has no error query; the usual cause is a Mesa without 4.5 core for OSMesa.
    return make_error("OSMesaCreateContextAttribs failed (4.5 core profile, RGBA8)");
  }
  auto context = std::make_unique<OsmesaContext>(raw);
  if (Status s = context->init(); !s) return s.error();
  return std::unique_ptr<Context>(std::move(context));
}

}  // namespace ps::gl::detail
