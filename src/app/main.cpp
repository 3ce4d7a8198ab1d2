// pseudoshadow: makes touch visible. Entry point: dispatches to the subcommands.
#include <cstdio>
#include <cstring>

#include "app/commands.h"

namespace {

constexpr const char* kHelp = R"(usage: pseudoshadow <command> [options]

Draws the pseudo-shadow of a probe on virtual surfaces: a translucent shadow-like projection
whose opacity shows proximity, whose Gabor texture shows the surface's tactile texture
(amplitude following probe speed), and whose displacement pushes the probe out of the surface.

commands:
  render    render a scene headless and write the image, AOVs and stats
  compare   compare two images pixel by pixel (exit 0 pass, 1 fail, 2 error)
  run       interactive window: move the probe with a device, 1 kHz haptic loop
  replay    render a recorded or scripted device session headless, deterministically
  bench-haptics  measure the haptic loop's rate, jitter and latency while rendering
  bench     sweep accuracy knobs: time vs error CSV + plot, skip ratios, peak RSS
  tune      parameter sweeps into a labelled contact sheet, or a scripted console session

Run `pseudoshadow <command> --help` for the options of a command.
Units: lengths in mm, speeds in mm/s, frequencies in Hz (docs/scene-format.md).
)";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "--help") ||
      !std::strcmp(argv[1], "help")) {
    std::fputs(kHelp, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::puts("pseudoshadow " PS_VERSION);
    return 0;
  }
  const char* cmd = argv[1];
  if (!std::strcmp(cmd, "render")) return ps::run_render(argc - 1, argv + 1);
  if (!std::strcmp(cmd, "compare")) return ps::run_compare(argc - 1, argv + 1);
  if (!std::strcmp(cmd, "run")) return ps::run_window(argc - 1, argv + 1);
  if (!std::strcmp(cmd, "replay")) return ps::run_replay(argc - 1, argv + 1);
  if (!std::strcmp(cmd, "bench-haptics")) return ps::run_bench_haptics(argc - 1, argv + 1);
  if (!std::strcmp(cmd, "bench")) return ps::run_bench(argc - 1, argv + 1);
  if (!std::strcmp(cmd, "tune")) return ps::run_tune(argc - 1, argv + 1);
  std::fprintf(stderr, "pseudoshadow: unknown command '%s' (commands: render, compare, run, replay, bench, bench-haptics, tune; see --help)\n", cmd);
  return 2;
}
