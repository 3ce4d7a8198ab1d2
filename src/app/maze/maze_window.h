// `pseudoshadow maze` in a window (docs/maze.md, "Running a participant"): the haptic loop on its
// own thread at 1 kHz, the mouse captured (relative motion moves the probe over the floor), the
// camera following the probe, the room label on screen with cues off, a score screen after each
// pass. The session log and the device stream are written as in the headless session.
#pragma once

#include <string>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "devices/device_spec.h"
#include "maze/maze_session.h"

namespace ps {

// The live window's own settings (docs/maze.md, "A hand a wall has stopped").
struct MazeWindowParams {
  // The clutch: once the hand has run on past a wall by more than this along the floor, it is put
  // back under the probe (logged as a `clutch` line). 6 mm = the shipped probe's radius: the
  // shadow has then left the hand's place entirely. 0: no clutch.
  double clutch_mm = 6.0;
  bool show_hand = true;  // a faint ring where the hand is while a wall holds the probe away
  // One unscored practice pass before the session (docs/maze.md, "Practice"): a route of its own,
  // logged to DIR/practice/; Space or Enter ends it early. Live devices only.
  bool practice = false;
};

// `device`: mouse or gamepad, or a trajectory:/playback: log played in real time. `live`: how the
// renderer and the haptic thread share the cores (--render-threads, --spare-cpu).
// `ended` (optional): why the session ended, for the caller's message after a signal
// (options.stop ends the session as terminated).
int run_maze_window(const cli::Command& cmd, const maze::SessionOptions& options, const DeviceSpec& device,
                    const cli::LiveLoopArgs& live, const MazeWindowParams& params = {}, maze::EndReason* ended = nullptr);

}  // namespace ps
