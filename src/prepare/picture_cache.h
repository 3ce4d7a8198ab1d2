// The picture cache: button pictures (prepare/button_pictures.h) and field maps
// (prepare/field_map.h) as PNG files in the user's cache directory ($PSEUDOSHADOW_CACHE_DIR,
// else $XDG_CACHE_HOME/pseudoshadow, else ~/.cache/pseudoshadow; subdirectory pictures/).
#pragma once

#include <string>

namespace ps {

// The cache directory's pictures/, created if need be. When it cannot be created (no HOME, a
// read-only home) a directory of this user's under the system's temporary directory is used
// instead, so a scene with pictures still renders (they are then made again after a reboot).
std::string picture_cache_dir();

}  // namespace ps
