// The `pseudoshadow` commands: one table, used by main() for dispatch, the top-level --help and
// the "did you mean" hint. Each entry's argv[0] is the command's name; it returns the exit status.
#pragma once

#include <span>
#include <string_view>

#include "app/commands/compare_cmd.h"

namespace ps {

int run_render(int argc, char** argv);         // src/app/commands/render_cmd.cpp
int run_window(int argc, char** argv);         // `run`, src/app/commands/run_cmd.cpp
int run_replay(int argc, char** argv);         // src/app/commands/replay_cmd.cpp
int run_bench_haptics(int argc, char** argv);  // src/app/bench/bench_haptics_cmd.cpp
int run_bench(int argc, char** argv);          // src/app/bench/bench_cmd.cpp
int run_tune(int argc, char** argv);           // src/app/commands/tune_cmd.cpp
int run_maze(int argc, char** argv);           // src/app/maze/maze_cmd.cpp
int run_calibrate(int argc, char** argv);      // src/app/calibrate/calibrate_cmd.cpp
int run_study(int argc, char** argv);          // src/app/study/study_cmd.cpp
int run_doctor(int argc, char** argv);         // src/app/commands/doctor_cmd.cpp

struct CommandInfo {
  std::string_view name;
  std::string_view summary;  // one line for the top-level --help
  int (*run)(int argc, char** argv);
};

inline constexpr CommandInfo kCommands[] = {
    {"render", "render a scene headless and write the image, AOVs and stats", run_render},
    {"compare", "compare two images pixel by pixel (exit 0 pass, 1 fail, 2 error)", run_compare},
    {"run", "interactive window: move the probe with a device, 1 kHz haptic loop", run_window},
    {"replay", "render a recorded or scripted device session headless, deterministically", run_replay},
    {"bench-haptics", "measure the haptic loop's rate, jitter and latency while rendering", run_bench_haptics},
    {"bench", "sweep accuracy knobs: time vs error CSV + plot, skip ratios, peak RSS", run_bench},
    {"tune", "parameter sweeps into a labelled contact sheet, or a scripted console session", run_tune},
    {"maze", "the haptic cue maze of Sepulveda-Cervantes et al.: run a participant, script one, summarize the logs", run_maze},
    {"calibrate", "2AFC staircases measure JNDs along a curve; write a lookup table of equal-looking steps", run_calibrate},
    {"study", "experiments from a file (thresholds, identification): plan, run, resume, summarize; simulate an observer", run_study},
    {"doctor", "check GL backends, display, audio, gamepads, real-time scheduling and data; how to fix each", run_doctor},
};

}  // namespace ps
