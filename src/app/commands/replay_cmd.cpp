// `pseudoshadow replay`: renders a recorded or scripted device session headless at a fixed
// frame rate, deterministically (fake clock, no threads), and writes the frames.
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <unistd.h>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/commands.h"
#include "app/session/replay_events.h"
#include "app/session/session.h"
#include "core/output_set.h"
#include "devices/device_spec.h"
#include "devices/sample_log.h"
#include "gl/context.h"
#include "haptics/session_driver.h"
#include "image/text.h"
#include "prepare/prepare.h"
#include "scene/scene_io.h"
#include "vibration/track.h"

namespace ps {

namespace {

constexpr const char* kDescription =
    "Renders the frames of a device session (a recording made with `run --record`, or a scripted\n"
    "trajectory) headless at a fixed frame rate. Deterministic: the haptic loop runs on a fake\n"
    "clock, so the same log and scene always give byte-identical images.";

struct ReplayArgs {
  cli::SceneArgs scene;
  cli::GlArgs gl_opts;
  std::string log, out_dir, sheet, record;
  std::string events, audio;  // docs/sound.md
  std::string vibration;      // docs/vibration.md
  long long every = 1;
  double fps = 30.0;
  bool quiet = false, show_probe = false, show_device = false, show_path = false;
  bool no_incremental = false;  // RendererOptions::incremental off
};

void declare(cli::Command& cmd, ReplayArgs& a) {
  CLI::App& app = cmd.app();
  cli::add_scene_options(app, a.scene);
  cli::add_image_options(app, a.scene);
  app.add_option("--log", a.log,
                 "device log, lines 'time_s x y z buttons'; KIND playback (sample-and-hold, exact; the "
                 "default) or trajectory (linear interpolation; the default for a .traj file), or pointer: "
                 "lines 'time_s x_px y_px height_mm buttons' mapped through the scene camera like run's "
                 "mouse (required)")
      ->type_name("[KIND:]FILE");
  cli::add_int(app, "--every", "N", a.every, 1, 1'000'000, "write every N-th frame (default 1)");
  cli::add_positive(app, "--fps", "F", a.fps, 10000.0, "30", "frames per second of session time (default 30)");
  cli::add_gl_options(app, a.gl_opts);
  app.add_option("--out", a.out_dir, std::string("writes DIR/frame_00000.png ... (required). ") + cli::kOutputRule)->type_name("DIR")->group(cli::kOutputGroup);
  cli::add_output(app, "--contact-sheet", a.sheet, "FILE",
                  "also one labelled sheet of the written frames (PNG)");
  cli::add_output(app, "--record", a.record, "FILE",
                  "record the device stream the loop read (a playback log)");
  cli::add_output(app, "--events", a.events, "FILE",
                  "the JSON-lines event log (contact start/end, buttons, impacts, ...; default DIR/events.jsonl)");
  cli::add_output(app, "--audio", a.audio, "FILE.wav",
                  "the events' sound track: WAV, 48 kHz mono 16-bit, as long as the replay");
  cli::add_output(app, "--vibration", a.vibration, "FILE.wav",
                  "the vibrotactile texture under the probe (docs/vibration.md): WAV, 48 kHz mono 16-bit, as long "
                  "as the replay");
  app.add_flag("--show-probe", a.show_probe, "also draw the probe itself (the haptic proxy) in the frames");
  app.add_flag("--show-device", a.show_device,
               "also draw the device's own position faintly (the gap to the proxy is the pseudo-haptic feedback)");
  app.add_flag("--show-path", a.show_path,
               "on a surface embedded in 4D, also draw the probe's path coloured by its 4D depth (docs/fourd.md)");
  app.add_flag("--no-incremental", a.no_incremental,
               "redraw every pixel of every frame (default: while only the probe moves, only its shadow's "
               "rectangles; the same images)");
  cli::add_quiet_option(app, a.quiet, "no progress");
  cmd.usage("pseudoshadow replay --log FILE --out DIR [options]");
}

Image thumbnail(const Image& im, int width) {
  Image t;
  t.width = std::min(width, im.width);
  t.height = std::max(1, t.width * im.height / im.width);
  t.channels = 3;
  t.pixels.resize(static_cast<size_t>(t.width) * t.height * 3);
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x)
      for (int c = 0; c < 3; ++c) t.at(x, y, c) = im.at(x * im.width / t.width, y * im.height / t.height, c);
  return t;
}

struct ReplayGl {  // context first: the renderers' GL objects die before it
  std::unique_ptr<gl::Context> ctx;
  std::unique_ptr<Renderer> renderer;
  std::vector<std::unique_ptr<Renderer>> switched;  // scenes a button switched to, in order
};

// A renderer of `scene` with a fresh view of it (the first scene's, or a button's switch).
Result<std::unique_ptr<Renderer>> make_renderer(const ReplayArgs& a, const Scene& scene, int frames) {
  auto view = make_view(scene, ViewFlags{a.show_probe, a.show_path, a.show_device});
  if (!view) return view.error();
  RendererOptions options;
  options.expected_frames = frames;  // a short replay skips a tile bake it would not repay
  options.incremental = !a.no_incremental;
  options.view = view.value();
  return open_renderer(scene, options);
}

Result<ReplayGl> open_renderer(const ReplayArgs& a, const Scene& scene, int frames) {
  auto ctx = cli::open_context(a.gl_opts);
  if (!ctx) return ctx.error();
  auto renderer = make_renderer(a, scene, frames);
  if (!renderer) return renderer.error();
  return ReplayGl{std::move(ctx.value()), std::move(renderer.value()), {}};
}

// A button's scene action: the file loaded as a scene (the replay's --set options do not
// apply to it), a renderer for it in the replay's context and its haptic scene.
Result<SceneSwitch> switch_scene(const ReplayArgs& a, ReplayGl& gl_state, int frames, PointerLogDevice* pointer,
                                 const std::string& path) {
  auto scene = load_scene(path, {}, cli::switch_allow_paths(a.scene));
  if (!scene) return make_error("button action: " + scene.error().message);
  auto renderer = make_renderer(a, scene.value(), frames);
  if (!renderer) return renderer.error();
  auto haptic = world::HapticScene::build(scene.value());
  if (!haptic) return haptic.error();
  gl_state.switched.push_back(std::move(renderer.value()));
  Renderer* r = gl_state.switched.back().get();
  if (pointer != nullptr) pointer->set_view(pointer_view(*r, pointer_plane(*r)));
  return SceneSwitch{r, std::make_shared<const world::HapticScene>(std::move(haptic.value()))};
}

std::string frame_path(const ReplayArgs& a, int i) {
  char name[32];
  std::snprintf(name, sizeof name, "/frame_%05d.png", i);
  return a.out_dir + name;
}

// Checked before the session: frames and sheet are published together at the end, or not at
// all. The --record log streams to its own "<FILE>.partial" (SampleRecorder) and is published
// by the session when it ends; only its directory is checked here.
Status add_outputs(const ReplayArgs& a, OutputSet& out) {
  if (Status s = out.add(frame_path(a, 0)); !s) return s;
  if (!a.sheet.empty())
    if (Status s = out.add(a.sheet); !s) return s;
  if (!a.record.empty())
    if (Status s = prepare_output_dir(a.record); !s) return s;
  if (!a.audio.empty())
    if (Status s = out.add(a.audio); !s) return s;
  if (!a.vibration.empty())
    if (Status s = out.add(a.vibration); !s) return s;
  return ok_status();
}

// The event log goes next to the frames unless --events names it (docs/sound.md).
ReplayEventsDesc events_desc(const ReplayArgs& a, double duration_s) {
  ReplayEventsDesc d;
  d.log_path = a.events.empty() ? a.out_dir + "/events.jsonl" : a.events;
  d.audio_path = a.audio;
  d.duration_s = duration_s;
  return d;
}

// --log [KIND:]FILE. No KIND: a .traj file is a scripted trajectory (interpolated; read as a
// recording its keyframes would jump and be rejected), anything else a recording.
Result<LogDeviceSpec> open_log(const std::string& log) {
  if (log.find(':') == std::string::npos)
    return open_device_log(DeviceSpec{log.ends_with(".traj") ? DeviceKind::kTrajectory : DeviceKind::kPlayback, log});
  auto spec = parse_device_spec(log, kLogDeviceKinds);
  if (!spec) return spec.error();
  return open_device_log(spec.value());
}

// Every --every-th frame staged as DIR/frame_NNNNN.png and, with --contact-sheet, its labelled
// thumbnail kept for the sheet.
struct FrameSink {
  const ReplayArgs& a;
  OutputSet& outputs;
  std::vector<Image> thumbs;
  std::vector<std::string> labels;
  int written = 0;

  Status take(int i, double t, const HapticState& st, const Renderer& r) {
    if (i % a.every != 0) return ok_status();
    const Image img = r.read_color();
    if (Status s = stage_image(outputs, frame_path(a, i), img); !s) return s;
    ++written;
    if (!a.sheet.empty()) {
      char label[64];
      std::snprintf(label, sizeof label, "%d t=%.2f s v=%.0f mm/s", i, t, glm::length(st.velocity_mm_s));
      thumbs.push_back(thumbnail(img, 256));
      labels.emplace_back(label);
    }
    return ok_status();
  }
  Status stage_sheet() {
    if (a.sheet.empty()) return ok_status();
    return stage_image(outputs, a.sheet, contact_sheet(thumbs, labels));
  }
};

ReplayOptions replay_options(const ReplayArgs& a, const world::HapticScene& haptic_scene) {
  ReplayOptions opt;
  opt.fps = a.fps;
  opt.record_path = a.record;
  opt.haptic_scene = &haptic_scene;
  opt.progress = !a.quiet && isatty(STDERR_FILENO);
  return opt;
}

// A button's "scene:FILE" action: the new scene's renderer, and its materials for the vibration.
std::function<Result<SceneSwitch>(const std::string&)> scene_switcher(const ReplayArgs& a, ReplayGl& gl_state, int frames,
                                                                      PointerLogDevice* pointer,
                                                                      std::optional<vibration::SignalTrack>& vib) {
  return [&a, &gl_state, frames, pointer, &vib](const std::string& path) -> Result<SceneSwitch> {
    auto next = switch_scene(a, gl_state, frames, pointer, path);
    if (next && vib) vib->set_model(std::make_shared<const vibration::SignalModel>(next->renderer->scene()));
    return next;
  };
}

// --vibration: every tick through the signal.
void track_vibration(const ReplayArgs& a, const Scene& scene, std::optional<vibration::SignalTrack>& vib,
                     ReplayOptions& opt) {
  if (a.vibration.empty()) return;
  vib.emplace(std::make_shared<const vibration::SignalModel>(scene));
  opt.on_tick = [&vib](const TickSample& t) { vib->add_tick(t); };
}

// After the session: the event log (and its sound track), the vibration track and the contact
// sheet join the frames, and all of them appear together.
Status publish(const ReplayArgs& a, OutputSet& outputs, ReplayEvents& events,
               const std::optional<vibration::SignalTrack>& vib, double duration_s, FrameSink& frames) {
  if (Status s = events.finish(outputs); !s) return s;
  if (vib) {
    auto write = [&](const std::string& file) { return vibration::write_track_wav(file, *vib, duration_s, 48000); };
    if (Status s = outputs.stage(a.vibration, write); !s) return s;
  }
  if (Status s = frames.stage_sheet(); !s) return s;
  return outputs.publish();
}

int replay(const cli::Command& cmd, const ReplayArgs& a) {
  if (a.log.empty() || a.out_dir.empty())
    return cmd.usage_error(make_error("--log FILE and --out DIR are required (see --help)"));
  auto fail = [&cmd](const Error& e) { return cmd.fail(e); };
  OutputSet outputs;
  if (Status s = add_outputs(a, outputs); !s) return fail(s.error());
  auto device = open_log(a.log);
  if (!device) return fail(device.error());
  auto scene = cli::load_scene_or_default(a.scene);
  if (!scene) return cmd.fail(scene.error(), cli::scene_exit_code(scene.error()));
  // The frames the session will give (replay_session: one per 1/fps of the log, plus the first).
  const int frames = FrameSchedule{.fps = a.fps}.frames_in(device->device->duration_s());
  auto gl_state = open_renderer(a, scene.value(), frames);
  if (!gl_state) return fail(gl_state.error());
  auto haptic_scene = world::HapticScene::build(scene.value());  // what the proxy collides with
  if (!haptic_scene) return fail(haptic_scene.error());
  Renderer* renderer = gl_state->renderer.get();
  // A scripted pointer moves in a window the size of the image, through the scene's camera.
  if (device->pointer) device->pointer->set_view(pointer_view(*renderer, pointer_plane(*renderer)));
  ReplayOptions opt = replay_options(a, haptic_scene.value());
  auto events = ReplayEvents::open(events_desc(a, device->device->duration_s()));
  if (!events) return fail(events.error());
  opt.on_event = [&ev = *events.value()](const HapticEvent& e) { ev.dispatcher().dispatch(e); };
  std::optional<vibration::SignalTrack> vib;  // a button's scene switch hands it the new scene
  track_vibration(a, scene.value(), vib, opt);
  opt.switch_scene = scene_switcher(a, gl_state.value(), frames, device->pointer, vib);
  FrameSink frames_out{a, outputs, {}, {}, 0};
  auto sink = [&](int i, double t, const HapticState& st, const Renderer& r) { return frames_out.take(i, t, st, r); };
  auto result = replay_session(*renderer, *device->device, opt, sink);
  if (!result) return fail(result.error());
  if (Status s = publish(a, outputs, *events.value(), vib, device->device->duration_s(), frames_out); !s)
    return fail(s.error());
  if (!a.quiet)
    std::printf("replayed %d frames at %g fps, wrote %d images to %s; rejected device samples: %llu; "
                "events: %zu\n",
                result->frames, a.fps, frames_out.written, a.out_dir.c_str(),
                static_cast<unsigned long long>(result->rejected.total()), events.value()->count());
  return cli::kExitOk;
}

}  // namespace

int run_replay(int argc, char** argv) {
  return cli::run_command<ReplayArgs>(argc, argv, "replay", kDescription, declare, replay);
}

}  // namespace ps
