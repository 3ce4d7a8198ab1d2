#include "prepare/picture_cache.h"

#include <cstdlib>
#include <filesystem>

#include <unistd.h>

namespace ps {

std::string picture_cache_dir() {
  std::string dir;
  if (const char* d = std::getenv("PSEUDOSHADOW_CACHE_DIR"); d != nullptr && *d != '\0') dir = std::string(d) + "/pictures";
  else if (const char* x = std::getenv("XDG_CACHE_HOME"); x != nullptr && *x != '\0') dir = std::string(x) + "/pseudoshadow/pictures";
  else if (const char* h = std::getenv("HOME"); h != nullptr && *h != '\0') dir = std::string(h) + "/.cache/pseudoshadow/pictures";
  std::error_code ec;
  if (!dir.empty() && (std::filesystem::create_directories(dir, ec), !ec) && access(dir.c_str(), W_OK) == 0) return dir;
  const std::string tmp = (std::filesystem::temp_directory_path(ec) / ("pseudoshadow-" + std::to_string(getuid()))).string() +
                          "/pictures";
  std::filesystem::create_directories(tmp, ec);
  return tmp;
}

}  // namespace ps
