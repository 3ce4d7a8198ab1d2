// `pseudoshadow maze`: the haptic cue maze of Sepulveda-Cervantes et al. as an experiment,
// docs/maze.md.
//   maze --participant ID --seed N --cues on|off [--device trajectory:FILE|playback:FILE] [--out DIR]
//   maze summarize LOG|DIR... --out DIR
//   maze script --seed N --out FILE.traj [--errors K]
// With a log device the session runs headless and deterministically (maze/maze_session.h);
// without one it opens the window (app/maze/maze_window.cpp).
#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/cli/stop_signal.h"
#include "app/commands.h"
#include "app/maze/maze_plan_cmd.h"
#include "app/maze/maze_summarize_cmd.h"
#include "app/maze/maze_window.h"
#include "app/session/session.h"
#include "core/file_io.h"
#include "gl/context.h"
#include "maze/maze_frames.h"
#include "maze/maze_plan.h"
#include "maze/maze_screen.h"
#include "maze/maze_script.h"
#include "maze/maze_session.h"
#include "render/renderer.h"
#include "scene/scene_io.h"

namespace ps {

namespace {

constexpr const char* kDescription =
    "The haptic cue maze of Sepulveda-Cervantes et al., \"Haptic Cues for Effective Learning in 3D\n"
    "Maze Navigation\" (docs/maze.md, docs/references.md): a learning room, then five rooms of one\n"
    "shape whose only difference is a haptic cue (texture, viscosity, elastic walls, a hidden sphere,\n"
    "an external force); each has an entrance and three exits, one of them correct. The route and the\n"
    "room order come from the seed. Writes DIR/session.jsonl (the session log), DIR/device.log (the\n"
    "device stream) and a score picture per pass. With --device trajectory:FILE or playback:FILE the\n"
    "session runs headless and deterministically; without --device it opens a window.\n"
    "Also: `maze summarize LOGS|DIRS... --out DIR`, `maze script --seed N --out FILE.traj`, `maze plan --participants N\n"
    "--out plan.csv` (then `maze --plan plan.csv --participant P03`) and `maze --resume DIR`.";

std::string default_maze() { return default_scene_base_dir() + "/maze/maze.toml"; }

// The devices a maze session takes.
constexpr std::initializer_list<DeviceKind> kMazeDevices = {DeviceKind::kMouse, DeviceKind::kGamepad,
                                                            DeviceKind::kTrajectory, DeviceKind::kPlayback};

DeviceSpec parsed_device(const std::string& text) {
  auto d = parse_device_spec(text, kMazeDevices);
  if (!d) throw cli::UsageError("--device: " + d.error().message);
  return d.value();
}

struct MazeArgs {
  std::string maze = default_maze(), participant, cues, out_dir, write_scene, resume, plan;
  std::optional<DeviceSpec> device;  // none: --device not given (mouse, or a resumed session's)
  long long seed = -1, every = 0, session = 1;
  double fps = 30.0, pace = 0.0;
  cli::GlArgs gl_opts;
  bool quiet = false, window = false, no_clutch = false, hide_hand = false, force = false, practice = false;
  double clutch_mm = MazeWindowParams{}.clutch_mm;
  cli::LiveLoopArgs live;  // the window's haptic thread and renderer: --render-threads, --spare-cpu
};

// The headless session's frames and pace.
void declare_headless(CLI::App& app, MazeArgs& a) {
  cli::add_int(app, "--every", "N", a.every, 0LL, 1'000'000LL,
               "headless: also write every N-th frame as DIR/frames/frame_NNNNN.png (default 0: none)");
  cli::add_positive(app, "--fps", "F", a.fps, 1000.0, "30", "headless frames per second of session time (default 30)");
  cli::add_positive(app, "--pace", "X", a.pace, 1000.0, "1",
                    "headless: run the session at X times real time (1: as long as it lasts live; default: "
                    "as fast as it computes)");
}

// The live window's own options (app/maze/maze_window.h).
void declare_window(CLI::App& app, MazeArgs& a) {
  app.add_flag("--window", a.window, "open the window also for a trajectory:/playback: device (played in real time)");
  cli::add_positive(app, "--clutch", "MM", a.clutch_mm, 1000.0, "6",
                    "window: a hand run on past a wall by more than MM along the floor is put back under the probe, "
                    "logged as `clutch` (default 6, the probe's radius)");
  app.add_flag("--no-clutch", a.no_clutch, "window: never put the hand back (it stays where the mouse took it)");
  app.add_flag("--hide-hand", a.hide_hand, "window: no faint ring where the hand is while a wall holds the probe");
  app.add_flag("--practice", a.practice,
               "window, mouse or gamepad: one unscored practice pass after the instructions, on a route of its own "
               "(another seed), logged to DIR/practice/; Space or Enter ends it early");
}

void declare(cli::Command& cmd, MazeArgs& a) {
  CLI::App& app = cmd.app();
  app.add_option("--maze", a.maze, "the maze description (default: the shipped scenes/maze/maze.toml)")->type_name("FILE");
  app.add_option("--participant", a.participant, "the participant's id, written into the log (required)")->type_name("ID");
  cli::add_int(app, "--seed", "N", a.seed, 0LL, 9'007'199'254'740'991LL,
               "the participant's seed: correct exits and room orders (required)");
  cli::add_int(app, "--session", "K", a.session, 1LL, 1000LL,
               "which session of this participant (default 1; 2: a retest with the same seed, as in "
               "Sepulveda-Cervantes et al. §VII)");
  cli::add_choice(app, "--cues", "on|off", a.cues, {"on", "off"}, "on",
                  "on: haptic cues, labels hidden; off: no cues, rooms labelled on screen (required)");
  app.add_option_function<std::string>("--device", [&a](const std::string& v) { a.device = parsed_device(v); },
                                       "trajectory:FILE or playback:FILE runs headless (a scripted or recorded "
                                       "participant); mouse (the default) or gamepad opens the window")->type_name("DEVICE");
  cli::add_output(app, "--out", a.out_dir, "DIR",
                  "where the log, device stream and scores go (default maze-ID); it must exist, or only its last "
                  "component may be missing (it is created). The log is written as the session goes, whole lines, "
                  "each synced: a killed session leaves every line written so far");
  declare_headless(app, a);
  cli::add_output(app, "--write-scene", a.write_scene, "FILE",
                  "write pass 1's generated scene for --seed and --cues (a scene file `run`, `render` and `replay` "
                  "take) and exit without a session");
  app.add_option("--plan", a.plan,
                 "run the row of --participant (and --session) of a study plan (`maze plan`): its seed, condition "
                 "and counterbalanced room orders")
      ->type_name("FILE.csv");
  app.add_flag("--force", a.force,
               "run even when the study folder (--out's parent) already has this participant's session or this seed");
  app.add_option("--resume", a.resume,
                 "continue the interrupted session in DIR (killed, crashed, quit) at its next unfinished trial: "
                 "participant, seed, condition and maze from its log, which gets a `resumed` line; the device "
                 "stream goes to DIR/device_resumed_N.log. A log device is played on from where the session stopped")
      ->type_name("DIR");
  declare_window(app, a);
  cli::add_gl_options(app, a.gl_opts);
  cli::add_live_loop_options(app, a.live);
  cli::add_quiet_option(app, a.quiet);
  cmd.usage("pseudoshadow maze --participant ID --seed N --cues on|off [--device trajectory:FILE] [--out DIR]");
  app.footer(std::string(cli::kExitStatusHelp) + cli::kExitSignalHelp);
}

// --every N: the GL context and the frame writer (none without --every).
struct HeadlessFrames {
  std::unique_ptr<gl::Context> ctx;
  std::unique_ptr<maze::FrameWriter> writer;
  maze::FrameFn on_frame() {
    if (!writer) return {};
    return [this](const maze::FrameView& v) { return writer->on_frame(v); };
  }
};

Status open_frames(const MazeArgs& a, const maze::MazeDesc& desc, HeadlessFrames& f) {
  if (a.every <= 0) return ok_status();  // GL only when frames are asked for: a session alone needs none
  if (Status s = prepare_output_dir(a.out_dir + "/frames/frame_00000.png"); !s) return s;
  auto c = cli::open_context(a.gl_opts);
  if (!c) return c.error();
  f.ctx = std::move(c.value());
  f.writer = std::make_unique<maze::FrameWriter>(desc, a.out_dir + "/frames", static_cast<int>(a.every));
  return ok_status();
}

int run_headless(const cli::Command& cmd, const MazeArgs& a, const maze::SessionOptions& base, maze::EndReason& ended) {
  auto device = open_device_log(*a.device);
  if (!device) return cmd.fail(make_error("--device: " + device.error().message));
  maze::SessionOptions o = base;
  o.pace = a.pace;
  o.fps = a.every > 0 ? a.fps : 0.0;
  HeadlessFrames frames;
  if (Status s = open_frames(a, o.desc, frames); !s) return cmd.fail(s.error());
  auto on_score = [&](const maze::PassScore& s) -> Status {
    if (!a.quiet) std::printf("pass %d: %d of 6 rooms right\n", s.pass + 1, s.correct());
    return write_image(a.out_dir + "/score_pass_" + std::to_string(s.pass + 1) + ".png", maze::score_image(s, o.info.cues));
  };
  auto r = maze::run_session(*device->device, o, frames.on_frame(), on_score);
  if (!r) return cmd.fail(r.error());
  ended = r->reason;
  if (r->reason == maze::EndReason::kDeviceEnded && r->branches == 0)
    std::fprintf(stderr, "pseudoshadow maze: warning: %s ended before the first branch: is it this session's (seed %llu)?\n",
                 a.device->text().c_str(), static_cast<unsigned long long>(o.route.seed));
  if (!a.quiet)
    std::printf("maze: %s after %d pass%s (%s), %.2f s of session; log %s\n", a.participant.c_str(), r->passes,
                r->passes == 1 ? "" : "es", maze::end_reason_name(r->reason), r->time_s, o.log_path.c_str());
  return cli::kExitOk;
}

// --write-scene: pass 1's scene as a file `run`, `render` and the goldens take; no session.
int write_scene(const cli::Command& cmd, const MazeArgs& a, const maze::MazeDesc& desc) {
  if (a.seed < 0 || a.cues.empty())
    return cmd.usage_error(make_error("--write-scene needs --seed N and --cues on|off (e.g. --seed 7 --cues on)"));
  auto scene = maze::generate_scene(desc, maze::draw_route(static_cast<std::uint64_t>(a.seed)), a.cues == "on", 0);
  if (!scene) return cmd.fail(scene.error());
  if (Status s = prepare_output_dir(a.write_scene); !s) return cmd.fail(s.error());
  if (Status s = write_file_atomic(a.write_scene, scene->text); !s) return cmd.fail(s.error());
  return cli::kExitOk;
}

bool opens_window(const MazeArgs& a) {
  return a.window || !a.device || !a.device->is_log();
}

// After a signal (app/cli/stop_signal.h): where the log is and how to go on; 128 + the signal.
int report_stop(const cli::StopSignals& stop, const maze::SessionOptions& o, maze::EndReason ended) {
  const std::string dir = std::filesystem::path(o.log_path).parent_path().string();
  const std::string next = maze::completes_session(ended)
                               ? std::string("the session had ended (") + maze::end_reason_name(ended) + "): nothing to resume"
                               : "resume with: pseudoshadow maze --resume " + (dir.empty() ? "." : dir);
  std::fprintf(stderr, "%s\n", cli::stop_line("maze", stop, "log", o.log_path, next).c_str());
  return stop.exit_code();
}

int run_session_of(const cli::Command& cmd, const MazeArgs& a, const maze::SessionOptions& options) {
  const bool live = !a.device || !a.device->is_log();
  if (a.practice && !live)
    return cmd.usage_error(make_error("--practice: a practice pass is for a participant at the window; give "
                                      "--device mouse or gamepad (or none), not a log"));
  if (a.practice && options.resume)
    return cmd.usage_error(make_error("--practice: a resumed session goes on where it stopped, without practice"));
  // SIGTERM, SIGINT, SIGHUP: the session ends as `terminated` through its normal end.
  const cli::StopSignals stop;
  maze::SessionOptions o = options;
  o.stop = stop.predicate();
  maze::EndReason ended = maze::EndReason::kQuit;
  int rc = cli::kExitOk;
  if (opens_window(a)) {
    const MazeWindowParams wp{a.no_clutch ? 0.0 : a.clutch_mm, !a.hide_hand, a.practice};
    rc = run_maze_window(cmd, o, a.device.value_or(DeviceSpec{}), a.live, wp, &ended);
  } else {
    rc = run_headless(cmd, a, o, ended);
  }
  return rc == cli::kExitOk && stop.requested() ? report_stop(stop, o, ended) : rc;
}

// --resume DIR: the session in DIR's log goes on where it stopped (maze/maze_resume.h).
int resume_main(const cli::Command& cmd, const MazeArgs& a) {
  if (!a.participant.empty() || a.seed >= 0 || !a.cues.empty())
    return cmd.usage_error(make_error("--resume DIR takes the participant, seed and cues from DIR's log: give none of them"));
  const std::string log = a.resume + "/session.jsonl";
  auto r = maze::read_resume_point(log);
  if (!r) return cmd.fail(r.error());
  if (!r->torn.empty())
    std::fprintf(stderr, "warning: %s; it goes to %s.torn and the session goes on from the line before\n", r->torn.c_str(),
                 log.c_str());
  auto desc = maze::load_maze_desc(r->info.maze_path);
  if (!desc) return cmd.fail(desc.error());
  if (!r->ended && static_cast<int>(r->done.size()) >= desc->max_passes)  // its session_end line missing
    return cmd.fail(make_error(log + ": the session ended (max_passes: " + std::to_string(r->done.size()) +
                               " passes; its session_end line is missing): nothing to resume"));
  MazeArgs args = a;
  args.out_dir = a.resume;
  args.participant = r->info.participant;
  if (!args.device) {  // the device the session ran with: a log plays on, mouse and gamepad open the window
    auto logged = parse_device_spec(r->info.device, kMazeDevices);
    if (!logged) return cmd.fail(make_error(log + ": " + logged.error().message));
    if (logged->kind != DeviceKind::kMouse) args.device = logged.value();
  }
  maze::SessionOptions o;
  o.desc = desc.value();
  o.route = maze::draw_route(r->info.seed);
  o.route.planned = r->planned;
  o.info = r->info;
  o.info.device = args.device.value_or(DeviceSpec{}).text();
  o.info.device_log = "device_resumed_" + std::to_string(r->resumes + 1) + ".log";
  o.log_path = log;
  o.record_path = a.resume + "/" + o.info.device_log;
  o.haptics.start_time_s = r->time_s;  // the loop's clock, the device and the fields go on from there
  o.resume = std::move(r.value());
  if (!a.quiet)
    std::printf("maze: resuming %s at pass %d, room %d, %.3f s of session\n", args.participant.c_str(),
                o.resume->current.pass + 1, static_cast<int>(o.resume->current.trials.size()) + 1, o.resume->time_s);
  return run_session_of(cmd, args, o);
}

int maze_main(const cli::Command& cmd, const MazeArgs& a) {
  if (!a.resume.empty()) return resume_main(cmd, a);
  auto desc = maze::load_maze_desc(a.maze);
  if (!desc) return cmd.fail(desc.error());
  if (!a.write_scene.empty()) return write_scene(cmd, a, desc.value());
  MazeArgs args = a;
  std::vector<maze::RoomOrder> planned;
  if (!a.plan.empty()) {  // the row's seed, condition and room orders
    if (a.participant.empty() || a.seed >= 0 || !a.cues.empty())
      return cmd.usage_error(make_error("--plan FILE takes --participant ID (and --session K); the seed and cues come from the plan"));
    auto row = maze::load_plan_row(a.plan, a.participant, static_cast<int>(a.session));
    if (!row) return cmd.fail(row.error());
    args.seed = static_cast<long long>(row->seed);
    args.cues = row->cues ? "on" : "off";
    planned = row->orders;
  }
  if (args.participant.empty() || args.seed < 0 || args.cues.empty())
    return cmd.usage_error(make_error("--participant ID, --seed N and --cues on|off are required (e.g. --participant P01 --seed 7 --cues on)"));
  if (args.out_dir.empty()) args.out_dir = "maze-" + a.participant;
  const auto seed = static_cast<std::uint64_t>(args.seed);
  if (!a.force)
    if (Status s = check_study_folder(args.out_dir, args.participant, static_cast<int>(a.session), seed); !s)
      return cmd.fail(s.error());
  if (a.device) warn_device_seed(*a.device, seed);
  if (Status s = prepare_output_dir(args.out_dir + "/session.jsonl"); !s) return cmd.fail(s.error());
  maze::SessionOptions o;
  o.desc = desc.value();
  o.route = maze::draw_route(seed);
  o.route.planned = planned;
  o.info = {a.participant, args.cues == "on", o.route.seed, a.maze, a.device.value_or(DeviceSpec{}).text(), "device.log",
            o.desc.max_passes, static_cast<int>(a.session)};
  o.log_path = args.out_dir + "/session.jsonl";
  o.record_path = args.out_dir + "/device.log";
  return run_session_of(cmd, args, o);
}

// --- maze script ------------------------------------------------------------------------------

struct ScriptArgs {
  std::string maze = default_maze(), out, plan, participant;
  long long session = 1;
  long long seed = -1, errors = 0, passes = 0;
  double speed = 100.0, height = -1.0;
};

void declare_script(cli::Command& cmd, ScriptArgs& a) {
  CLI::App& app = cmd.app();
  app.add_option("--maze", a.maze, "the maze description (default: the shipped one)")->type_name("FILE");
  cli::add_int(app, "--seed", "N", a.seed, 0LL, 9'007'199'254'740'991LL, "the participant's seed (required)");
  cli::add_int(app, "--errors", "K", a.errors, 0LL, 5LL,
               "wrong exits in each pass before the last (rooms 2..K+1 of the pass; default 0)");
  cli::add_int(app, "--passes", "P", a.passes, 0LL, 100LL,
               "passes to walk; the last takes every correct exit (default: 1, or 2 with --errors)");
  cli::add_positive(app, "--speed", "MM_S", a.speed, 10000.0, "100", "walking speed in mm/s (default 100)");
  cli::add_positive(app, "--height", "MM", a.height, 1000.0, "5.5",
                    "the probe centre's height over the floor (default: probe radius + 1, no contact; below the "
                    "radius it presses into the floor, so the floor's feel shows in the log)");
  app.add_option("--plan", a.plan, "walk the plan row of --participant (and --session): its seed and room orders")
      ->type_name("FILE.csv");
  app.add_option("--participant", a.participant, "with --plan: whose row")->type_name("ID");
  cli::add_int(app, "--session", "K", a.session, 1LL, 1000LL, "with --plan: which session's row (default 1)");
  cli::add_output(app, "--out", a.out, "FILE.traj", "the trajectory file to write (required)");
  cmd.usage("pseudoshadow maze script --seed N --out FILE.traj [--errors K] [--passes P]");
}

int script_main(const cli::Command& cmd, const ScriptArgs& a) {
  if ((a.seed < 0) == a.plan.empty() || a.out.empty())
    return cmd.usage_error(make_error("--seed N (or --plan FILE --participant ID) and --out FILE.traj are required"));
  auto desc = maze::load_maze_desc(a.maze);
  if (!desc) return cmd.fail(desc.error());
  maze::Route route = maze::draw_route(static_cast<std::uint64_t>(std::max(0LL, a.seed)));
  if (!a.plan.empty()) {
    auto row = maze::load_plan_row(a.plan, a.participant, static_cast<int>(a.session));
    if (!row) return cmd.fail(row.error());
    route = maze::draw_route(row->seed);
    route.planned = row->orders;
  }
  const int passes = a.passes > 0 ? static_cast<int>(a.passes) : a.errors > 0 ? 2 : 1;
  std::vector<maze::PassChoices> choices;
  for (int p = 0; p < passes; ++p)
    choices.push_back(p + 1 < passes ? maze::choices_with_errors(route, p, static_cast<int>(a.errors))
                                     : maze::correct_choices(route, p));
  if (Status s = prepare_output_dir(a.out); !s) return cmd.fail(s.error());
  // The seed in the header: `maze` warns when the trajectory is run with another one.
  const std::string header = "# pseudoshadow maze script --seed " + std::to_string(route.seed) + "\n";
  if (Status s = write_file_atomic(a.out, header + maze::script_trajectory(desc.value(), choices, a.speed, a.height)); !s)
    return cmd.fail(s.error());
  return cli::kExitOk;
}

}  // namespace

int run_maze(int argc, char** argv) {
  const std::string_view sub = argc >= 2 ? argv[1] : "";
  if (sub == "summarize") return run_maze_summarize(argc - 1, argv + 1);
  if (sub == "plan") return run_maze_plan(argc - 1, argv + 1);
  if (sub == "script")
    return cli::run_command<ScriptArgs>(argc - 1, argv + 1, "maze script",
                                        "Writes a scripted participant: a trajectory through the maze taking the "
                                        "seed's correct exits (or some wrong ones first).",
                                        declare_script, script_main);
  return cli::run_command<MazeArgs>(argc, argv, "maze", kDescription, declare, maze_main);
}

}  // namespace ps
