// Device enumeration and the per-device strings; context_egl.cpp opens a display on one.
#include "gl/egl_device.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>

#include "gl/context_internal.h"

namespace ps::gl {

namespace detail {

Result<std::vector<void*>> query_egl_devices() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (client == nullptr || std::strstr(client, "EGL_EXT_device_enumeration") == nullptr)
    return make_error("EGL_EXT_device_enumeration not offered by this EGL (no EGL devices)");
  auto query = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (query == nullptr) return make_error("eglQueryDevicesEXT not available");
  EGLint count = 0;
  if (!query(0, nullptr, &count)) return make_error("eglQueryDevicesEXT failed");
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (count > 0 && !query(count, devices.data(), &count)) return make_error("eglQueryDevicesEXT failed");
  devices.resize(static_cast<std::size_t>(count));
  return std::vector<void*>(devices.begin(), devices.end());
}

}  // namespace detail

namespace {

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + n, name))
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

std::string device_string(EGLDeviceEXT device, EGLint what) {
  auto query = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  const char* s = query != nullptr ? query(device, what) : nullptr;
  eglGetError();  // an unsupported name is EGL_BAD_PARAMETER: not an error for a listing
  return s != nullptr ? s : "";
}

// Vendor and renderer where the driver names them (EGL_EXT_device_query_name: NVIDIA, newer
// Mesa), else the driver's name (EGL_EXT_device_persistent_id), else what the kind implies.
std::string device_name(EGLDeviceEXT device, const char* ext, bool software) {
  std::string name;
  if (has_extension(ext, "EGL_EXT_device_query_name")) {
    name = device_string(device, EGL_VENDOR);
    const std::string renderer = device_string(device, EGL_RENDERER_EXT);
    if (!renderer.empty()) name += (name.empty() ? "" : " ") + renderer;
  }
  if (name.empty() && has_extension(ext, "EGL_EXT_device_persistent_id"))
    name = device_string(device, EGL_DRIVER_NAME_EXT);
  if (name.empty()) name = software ? "Mesa software (llvmpipe)" : "unnamed EGL device";
  return name;
}

}  // namespace

Result<std::vector<EglDeviceInfo>> list_egl_devices() {
  auto devices = detail::query_egl_devices();
  if (!devices) return devices.error();
  std::vector<EglDeviceInfo> out;
  for (std::size_t i = 0; i < devices->size(); ++i) {
    auto device = static_cast<EGLDeviceEXT>((*devices)[i]);
    const std::string ext = device_string(device, EGL_EXTENSIONS);
    EglDeviceInfo info;
    info.index = static_cast<int>(i);
    info.software = has_extension(ext.c_str(), "EGL_MESA_device_software");
    info.name = device_name(device, ext.c_str(), info.software);
    if (has_extension(ext.c_str(), "EGL_EXT_device_drm_render_node"))
      info.render_node = device_string(device, EGL_DRM_RENDER_NODE_FILE_EXT);
    if (info.render_node.empty() && has_extension(ext.c_str(), "EGL_EXT_device_drm"))
      info.render_node = device_string(device, EGL_DRM_DEVICE_FILE_EXT);  // the primary node
    out.push_back(std::move(info));
  }
  return out;
}

std::string format_egl_devices(const std::vector<EglDeviceInfo>& devices) {
  std::string out;
  for (const EglDeviceInfo& d : devices)
    out += std::to_string(d.index) + "  " + d.name + "  " + (d.software ? "software" : "hardware") + "  " +
           (d.render_node.empty() ? "-" : d.render_node) + "\n";
  return out;
}

}  // namespace ps::gl
