// EGL devices (EGL_EXT_device_enumeration + EGL_EXT_platform_device): the way to a GPU on a
// machine without a display. The proprietary NVIDIA driver offers only this headless path (no
// EGL_MESA_platform_surfaceless); Mesa offers it too, with a software device (llvmpipe).
#pragma once

#include <string>
#include <vector>

#include "core/result.h"

namespace ps::gl {

struct EglDeviceInfo {
  int index = 0;            // position in eglQueryDevicesEXT's list: what --gpu N names
  std::string name;         // vendor / driver, e.g. "NVIDIA", "Mesa software (llvmpipe)"
  std::string render_node;  // DRM render node ("/dev/dri/renderD128"); empty when none
  bool software = false;    // EGL_MESA_device_software: llvmpipe, not a GPU
};

// Every EGL device, in the driver's order. Error when EGL cannot enumerate devices
// (no EGL_EXT_device_enumeration in the client extensions).
Result<std::vector<EglDeviceInfo>> list_egl_devices();

// One line per device: "0  Mesa software (llvmpipe)  software  -" (index, name, kind, node).
std::string format_egl_devices(const std::vector<EglDeviceInfo>& devices);

}  // namespace ps::gl
