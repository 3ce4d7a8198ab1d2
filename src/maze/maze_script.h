// Scripted participants: a trajectory (docs/haptics.md, "Devices": `trajectory:FILE`) that
// walks the probe through the maze taking given exits, for tests and demonstrations
// (`pseudoshadow maze script`). No GL.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "maze/maze.h"

namespace ps::maze {

using PassChoices = std::array<Exit, kRoomsPerPass>;  // per room of a pass, in its order

// The correct exits of pass `pass`.
PassChoices correct_choices(const Route& route, int pass);
// `wrong` rooms of the pass (the first ones after the dummy room) take the next exit round
// (left -> straight -> right -> left) instead of the correct one.
PassChoices choices_with_errors(const Route& route, int pass, int wrong);

// Waypoints at constant speed with the probe's centre `height_mm` over the floor (default: 1 mm
// above it, no contact; below the probe radius the probe presses into the floor all the way):
// start corridor, then for each pass and room: into the room, out by the chosen exit (round the
// hidden sphere's default place), along the channel to the hall and on to the next room.
// Lines "time_s x y z 0".
std::string script_trajectory(const MazeDesc& desc, const std::vector<PassChoices>& passes, double speed_mm_s,
                              double height_mm = -1.0);

}  // namespace ps::maze
