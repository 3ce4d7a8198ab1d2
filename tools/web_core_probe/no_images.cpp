// The core probe reads no images (tools/web_core_probe.sh): its scene has none. The page has its
// own reader (web/src/image_web.cpp).
#include "image/image.h"

namespace ps {
Result<Image> read_image(const std::string& p) { return make_error("web core probe: no image reader for " + p); }
}  // namespace ps
