// A study with `pseudoshadow maze` (docs/maze.md, "Planning a study"): `maze plan` writes the
// plan; `maze --plan FILE --participant ID` runs its row; before any session the study folder
// (the --out directory's parent) is checked for a participant ID or seed already used, and a
// scripted device written for another seed is warned about.
#pragma once

#include <cstdint>
#include <string>

#include "core/result.h"
#include "devices/device_spec.h"

namespace ps {

// `pseudoshadow maze plan ...` (argv[0] is "plan").
int run_maze_plan(int argc, char** argv);

// Refuses a session whose participant (in the same session number) or seed (of another
// participant) a session log in a sibling directory of out_dir already has; the message names
// that log and --force.
Status check_study_folder(const std::string& out_dir, const std::string& participant, int session, std::uint64_t seed);

// A trajectory written by `maze script` says its seed in its header: a warning on stderr when it
// is not the session's (that device would walk another route and end as device_ended).
void warn_device_seed(const DeviceSpec& device, std::uint64_t seed);

}  // namespace ps
