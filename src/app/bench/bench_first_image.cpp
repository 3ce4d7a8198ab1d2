#include "app/bench/bench_first_image.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "scene/scene_io.h"

namespace ps::bench {

namespace {

constexpr double kTarget = 1.15;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[(v.size() - 1) / 2];
}

// --set materials.NAME.gabor_strategy="S" for every textured material of the scene.
std::vector<std::string> force_strategy(const Scene& scene, const std::string& strategy) {
  std::vector<std::string> out;
  for (const Material& m : scene.materials) {
    if (!m.textured) continue;
    out.push_back("--set");
    out.push_back("materials." + m.name + ".gabor_strategy=\"" + strategy + "\"");
  }
  return out;
}

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The stroke of tests/haptics/data/stroke.traj (the default scene's plank, 33.8 mm/s, 1.6 s):
// written here so an installed bench needs no source tree. 1.6 s at 187.5 fps: 301 frames.
constexpr const char* kStroke =
    "0.0 -16.9 0 16 0\n0.3 -16.9 0 6 1\n1.3 16.9 0 6 1\n1.6 16.9 0 16 0\n";
constexpr const char* kReplayFps = "187.5";

}  // namespace

double FirstImageRow::ratio() const {
  const double best = std::min(naive_s, baked_s);
  return best > 0.0 ? auto_s / best : 0.0;
}

Result<ChildTimes> run_self(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  std::string name = "pseudoshadow";
  argv.push_back(name.data());
  std::vector<std::string> copy = args;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) return make_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) {
      dup2(null, STDOUT_FILENO);
      dup2(null, STDERR_FILENO);
    }
    execv("/proc/self/exe", argv.data());
    _exit(127);
  }
  int status = 0;
  struct rusage ru {};
  if (wait4(pid, &status, 0, &ru) < 0) return make_error(std::string("wait4: ") + std::strerror(errno));
  ChildTimes t;
  t.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t.cpu_s = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
            1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string line = "pseudoshadow";
    for (const std::string& a : args) line += " " + a;
    return make_error("bench --first-image: `" + line + "` failed (run it to see why)");
  }
  return t;
}

namespace {

// The shipped scenes (*.toml) in `dir`, in name order.
Result<std::vector<std::filesystem::path>> shipped_scenes(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<fs::path> scenes;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.is_regular_file() && e.path().extension() == ".toml") scenes.push_back(e.path());
  if (ec || scenes.empty()) return make_error(dir + ": no shipped scenes (*.toml) to time");
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

// One scene rendered o.reps times per strategy (auto, naive, baked): the median CPU seconds of each.
Result<FirstImageRow> time_scene(const FirstImageOptions& o, const std::filesystem::path& path, const std::string& out) {
  auto scene = load_scene(path.string());
  if (!scene) return scene.error();
  FirstImageRow row;
  row.name = path.stem().string();
  if (o.progress) o.progress("first image: " + row.name + " ...");
  const std::vector<std::string> base = concat({"render", "--scene", path.string(), "--out", out, "-q"}, o.gl_args);
  const std::vector<std::string> variants[3] = {base, concat(base, force_strategy(scene.value(), "naive")),
                                                concat(base, force_strategy(scene.value(), "baked"))};
  std::vector<double> t[3];
  for (int r = 0; r < o.reps; ++r)
    for (int k = 0; k < 3; ++k) {  // alternating, so a change of load hits all three alike
      auto c = run_self(variants[k]);
      if (!c) return c.error();
      t[k].push_back(c->cpu_s);
    }
  row.auto_s = median(t[0]);
  row.naive_s = median(t[1]);
  row.baked_s = median(t[2]);
  return row;
}

// A 301-frame replay of the default scene, once per strategy (auto, naive, baked).
Result<FirstImageRow> time_replay(const FirstImageOptions& o) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const std::string traj = o.work_dir + "/stroke.traj", frames = o.work_dir + "/replay_frames";
  std::ofstream(traj) << kStroke;
  auto def = load_scene_or_default("");
  if (!def) return def.error();
  FirstImageRow row;
  row.name = "replay, 301 frames (default)";
  if (o.progress) o.progress("first image: a 301-frame replay ...");
  const std::vector<std::string> base = concat({"replay", "--log", "trajectory:" + traj, "--fps", kReplayFps,
                                                "--out", frames, "-q"}, o.gl_args);
  double* slots[3] = {&row.auto_s, &row.naive_s, &row.baked_s};
  const char* strategy[3] = {nullptr, "naive", "baked"};
  for (int k = 0; k < 3; ++k) {
    fs::remove_all(frames, ec);
    auto c = run_self(strategy[k] ? concat(base, force_strategy(def.value(), strategy[k])) : base);
    if (!c) return c.error();
    *slots[k] = c->cpu_s;
  }
  fs::remove_all(frames, ec);
  fs::remove(traj, ec);
  return row;
}

}  // namespace

Result<std::vector<FirstImageRow>> run_first_image(const FirstImageOptions& o) {
  auto scenes = shipped_scenes(o.scenes_dir);
  if (!scenes) return scenes.error();
  std::error_code ec;
  std::filesystem::create_directories(o.work_dir, ec);
  const std::string out = o.work_dir + "/first_image.png";
  std::vector<FirstImageRow> rows;
  for (const std::filesystem::path& path : scenes.value()) {
    auto row = time_scene(o, path, out);
    if (!row) return row.error();
    rows.push_back(row.value());
  }
  if (o.replay) {
    auto row = time_replay(o);
    if (!row) return row.error();
    rows.push_back(row.value());
  }
  std::filesystem::remove(out, ec);
  return rows;
}

std::string first_image_markdown(const std::vector<FirstImageRow>& rows, int reps) {
  std::string md = "| scene | auto | naive | baked | auto / min(naive, baked) | target |\n| --- | --- | --- | --- | --- | --- |\n";
  char buf[256];
  for (const FirstImageRow& r : rows) {
    const bool replay = r.name.rfind("replay", 0) == 0;
    const std::string target = replay ? "at the baked speed" : "<= 1.15";
    const bool met = replay ? r.auto_s <= r.baked_s * kTarget : r.ratio() <= kTarget;
    std::snprintf(buf, sizeof buf, "| %s | %.2f | %.2f | %.2f | %.2f | %s %s |\n", r.name.c_str(), r.auto_s, r.naive_s,
                  r.baked_s, r.ratio(), target.c_str(), met ? "(met)" : "(**missed**)");
    md += buf;
  }
  std::snprintf(buf, sizeof buf,
                "\nCPU seconds (user + sys) of the whole process; one-frame renders: median of %d alternating "
                "runs; the replay: one run each.\n",
                reps);
  return md + buf;
}

}  // namespace ps::bench
