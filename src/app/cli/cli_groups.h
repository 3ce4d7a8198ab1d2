// The option groups shared by the commands: one function per concern, so every command that
// has the concern spells, checks and documents its options the same way.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/result.h"
#include "gl/context.h"
#include "haptics/spare_cpu.h"
#include "scene/scene.h"
#include "vibration/live.h"

namespace ps {
class HapticLoop;
}

namespace ps::cli {

// The scene a command renders: a file (or the built-in default) plus overrides, in the order
// the command line gave them (--set, --overrides lines, --probe, --velocity, --size, ...).
struct SceneArgs {
  struct Override {
    std::string text;    // "KEY=VALUE", as for parse_scene
    std::string option;  // the option that gave it: "--set", "--velocity", ... (for messages)
  };
  std::string path;  // empty: the built-in default scene
  std::vector<Override> overrides;
  std::vector<std::string> allow_paths;  // --allow-path: more folders the scene may read (scene/path_policy.h)

  void add(std::string text, std::string option) { overrides.push_back({std::move(text), std::move(option)}); }
  std::vector<std::string> lines() const;  // the KEY=VALUE texts, in order
};

// Help group names, in the order they appear in --help.
inline constexpr const char* kSceneGroup = "scene";
inline constexpr const char* kGlGroup = "GL";
inline constexpr const char* kOutputGroup = "output";
// Said in the help of every command that writes files (src/core/output_set.h does it).
inline constexpr const char* kOutputRule =
    "For every output file: its directory must exist, or only its last directory may be missing "
    "(it is created); all outputs are written, or none.";

// --scene FILE, --set KEY=VALUE, --overrides FILE, --allow-path DIR.
void add_scene_options(CLI::App& app, SceneArgs& scene);
// --probe X,Y,Z and --velocity VX,VY,VZ (probe.position / probe.velocity overrides).
void add_probe_options(CLI::App& app, SceneArgs& scene);
// --size WxH (render.size override); one limit for every command.
inline constexpr int kMaxSide = 8192;               // GL_MAX_TEXTURE_SIZE-safe on llvmpipe
inline constexpr long long kMaxPixels = 16'777'216;  // 4096^2: keeps the padded targets < 1.2 GiB
void add_image_options(CLI::App& app, SceneArgs& scene);
// --backend auto|egl|osmesa (headless commands; glfw is refused: it opens a window) and
// --gpu auto|list|software|N (docs/gl-stack.md, "EGL devices"). --gpu list prints the EGL devices
// and ends the command (exit 0, nothing written; exit 1 with one line when EGL has no devices).
struct GlArgs {
  gl::Backend backend = gl::Backend::kAuto;
  gl::GpuChoice gpu;
  // The words that give the same choice to a child `pseudoshadow` process.
  std::vector<std::string> argv() const;
};
void add_gl_options(CLI::App& app, GlArgs& args);
// The headless context the options ask for; with --gpu auto, one line on stderr says which
// display it took (unless `quiet`).
Result<std::unique_ptr<gl::Context>> open_context(const GlArgs& args, bool quiet = false);
// An option naming a file or folder the command writes (`value_name`: FILE, DIR, FILE.wav...),
// listed with the other outputs in --help.
CLI::Option* add_output(CLI::App& app, const std::string& name, std::string& path, const std::string& value_name,
                        const std::string& help);
// --stats FILE.json (the per-frame numbers of the last frame, Renderer's stats_json).
void add_stats_option(CLI::App& app, std::string& path);
// The options of the commands that run a live 1 kHz haptic loop beside the renderer (`run`,
// `bench-haptics`, `maze`'s window): how the machine's cores are shared (docs/haptics.md,
// "Keeping time without privileges").
struct LiveLoopArgs {
  // --render-threads N: llvmpipe's rasteriser threads. -1 (default): one fewer than the CPUs the
  // program runs on (the spare one left out; 0 on 2 cores); 0: llvmpipe's own default (every core).
  int render_threads = -1;
  // --spare-cpu auto|off|N: a CPU none of the program's threads use (haptics/spare_cpu.h).
  std::string spare_cpu = "auto";
  // --vibration-out none|sound[:DEVICE]|gamepad|both[:DEVICE]: where the vibrotactile texture
  // goes (docs/vibration.md); checked as it is read.
  vibration::OutputChoice vibration_out;
};
void add_live_loop_options(CLI::App& app, LiveLoopArgs& args);
// The live vibration for --vibration-out on `scene`, its tick feed given to `loop` (before the
// loop starts); each output that cannot open is one "warning: ..." line on stderr. Start it
// with start(), close() it after the loop stops; it must outlive the loop.
std::unique_ptr<vibration::LiveVibration> open_live_vibration(const LiveLoopArgs& args, const Scene& scene,
                                                             HapticLoop& loop);

struct LiveLoopSetup {
  std::string render_threads;  // what is in force, for the command's report
  SpareCpu spare;
  std::string report() const;  // "render threads 1 (...); spare CPU 1 (...)"
};
// Call first, before the GL context and the haptic thread exist: sets LP_NUM_THREADS (unless the
// user set it) and leaves a CPU spare, confining the calling thread and every thread it starts;
// large blocks are kept mapped (haptics/live_heap.h).
// The error (a bad --spare-cpu) is a usage error.
Result<LiveLoopSetup> apply_live_loop(const LiveLoopArgs& args);
// -q, --quiet.
void add_quiet_option(CLI::App& app, bool& quiet, const std::string& help = "no progress output");

// The scene file with its overrides, or the built-in default scene when no --scene was given.
// An error caused by the command line names the option that gave the value ("--velocity: ...",
// "--set KEY: ..."); scene_exit_code() maps it to 2, any other (the file's fault) to 1.
Result<Scene> load_scene_or_default(const SceneArgs& scene);
int scene_exit_code(const Error& e);

// The folders a scene reached by a button may read: --allow-path and the first scene's own
// folder tree (a world's scenes may refer to each other and to files beside the first).
std::vector<std::string> switch_allow_paths(const SceneArgs& scene);

// The name used in messages and saved files for a scene path ("" = the built-in default).
std::string scene_display_name(const std::string& path);

}  // namespace ps::cli
