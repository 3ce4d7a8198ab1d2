// The keys and mouse actions of `pseudoshadow run`, in one table: the help overlay in the
// window (app/window/hud.h) and the `run --help` footer (app/commands/run_cmd.cpp) are both generated from it,
// so they cannot disagree. Changing a key binding (app/window/window_input.cpp, devices/glfw_input.cpp)
// means changing its row here.
#pragma once

#include <span>
#include <string>

namespace ps {

struct RunKey {
  const char* keys;    // as a person reads them: "Shift+scroll, PgUp/PgDn"
  const char* action;  // short, lower case: it is one line of the help overlay
};

std::span<const RunKey> run_keys();

// What the pseudo-shadow shows, for a first-time user: the last lines of the help overlay.
std::span<const char* const> shadow_legend();

// The table as aligned text lines "KEYS  action" (keys padded to the widest), in `columns`
// side by side (the rows in order down the first, then the next), each line prefixed with
// `indent`: one column for the --help footer, two for the help overlay.
std::string run_keys_text(const std::string& indent, int columns);

}  // namespace ps
