// `pseudoshadow maze` in a window (docs/maze.md, "Running a participant"): the haptic loop on its
// own thread at 1 kHz, the mouse captured (relative motion moves the probe over the floor), the
// camera following the probe, the room label on screen with cues off, a score screen after each
// pass. The session log and the device stream are written as in the headless session.
#pragma once

#include <string>

#include "app/cli.h"
#include "app/cli_groups.h"
#include "maze/maze_session.h"

namespace ps {

// `device`: "mouse" (or empty), or a trajectory:/playback: log played in real time. `live`: how the
// renderer and the haptic thread share the cores (--render-threads, --spare-cpu).
int run_maze_window(const cli::Command& cmd, const maze::SessionOptions& options, const std::string& device,
                    const cli::LiveLoopArgs& live);

}  // namespace ps
