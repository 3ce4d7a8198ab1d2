// pseudoshadow's C++ API: open a scene, place the probe, render frames headless, read the colour
// image, the AOVs and the stats, change any scene value by its path. docs/api.md.
//
//   find_package(pseudoshadow CONFIG REQUIRED)
//   target_link_libraries(app PRIVATE pseudoshadow::pseudoshadow)
//
//   pseudoshadow::Renderer r = pseudoshadow::Renderer::open_file("scene.toml");
//   r.set("materials.wood.lambda_min", "0.4");
//   pseudoshadow::Frame f = r.render({.probe = pseudoshadow::Vec3{2, 0, 7.5},
//                                     .velocity = pseudoshadow::Vec3{0, 150, 0}, .aovs = {"distance"}});
//   // f.color: RGB8, f.aov("distance"): float mm, f.stats.max_penetration_mm
//
// Failures (a scene error, an unknown key, no GL context, a missing shader) throw
// pseudoshadow::Error whose what() is the CLI's message for the same mistake ("file:line: ...",
// "--set KEY: ..."). A Renderer owns a headless OpenGL 4.5 context (EGL or OSMesa) and makes it
// current on the calling thread for each call: use one Renderer from one thread at a time.
// This header depends on the C++ standard library only.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#if defined(PSEUDOSHADOW_BUILDING_SHARED)
#define PSEUDOSHADOW_API __attribute__((visibility("default")))
#else
#define PSEUDOSHADOW_API
#endif

namespace pseudoshadow {

// The one-line message of a failed call, as the CLI prints it.
class PSEUDOSHADOW_API Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// auto: EGL surfaceless, then OSMesa (the CLI's --backend); both give byte-identical images.
enum class Backend { kAuto, kEgl, kOsmesa };

using Vec3 = std::array<double, 3>;

// How a Renderer is opened. Every field is optional: the default is the built-in default scene
// on the auto backend.
struct OpenDesc {
  Backend backend = Backend::kAuto;
  // The EGL display (the CLI's --gpu): "" (Mesa's surfaceless platform), "auto" (a hardware EGL
  // device, else surfaceless, else OSMesa), "software" (Mesa's software EGL device) or "N" (EGL
  // device N). Like the backend, one per process while a renderer is open.
  std::string gpu;
  // "KEY=VALUE" scene overrides applied when the scene is parsed, as the CLI's --set
  // (e.g. "render.size=[64,64]"); the same as calling set() afterwards, but without a rebuild.
  std::vector<std::string> set;
  // More folders the scene may read files from (the CLI's --allow-path). A scene may read only
  // files in its own folder tree and the shipped data, so a scene from someone else cannot read
  // the user's other files; values given in `set` are the caller's and are not confined.
  std::vector<std::string> allow_paths;
};

// One render call: where the probe is, how fast it moves, how many frames.
struct RenderDesc {
  std::optional<Vec3> probe;     // probe position, mm (the CLI's --probe); unset: unchanged
  std::optional<Vec3> velocity;  // probe velocity, mm/s (--velocity); unset: unchanged
  // Frames to render (--frames); the probe moves by each frame's displacement. 0: the scene's
  // render.frames (1 unless the scene says), as the CLI without --frames.
  int frames = 0;
  // The AOVs to read back into Frame::aovs (names of aov_names()); empty: none. All of them:
  // aov_names().
  std::vector<std::string> aovs;
};

// An AOV's pixels: width x height x channels floats, top row first, interleaved.
struct Aov {
  std::string name;
  int channels = 0;
  std::vector<float> pixels;
};

// The stats of the last frame (the CLI's --stats JSON, same names).
struct Stats {
  std::string backend;      // "egl" or "osmesa"
  std::string gl_renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string egl_device;   // "surfaceless", "device N (name)" or "none" (OSMesa)
  int frames = 0;           // frames rendered by this render() call
  Vec3 reference_normal{0.0, 0.0, 1.0};
  Vec3 displacement{0.0, 0.0, 0.0};  // applied to the probe by the last frame, mm
  double max_penetration_mm = 0.0;
  Vec3 probe_position{0.0, 0.0, 0.0};  // after the last frame's displacement, mm
  double speed_gain = 0.0;             // of the first shadowed material
  unsigned shadow_pixels = 0, penetrating_pixels = 0;
  std::vector<std::pair<std::string, double>> timings_ms;  // per pass, the last frame
  // GPU time per pass (GL_TIME_ELAPSED) of the newest frame whose timer queries came back
  // (gpu_timings_lag frames before the last; -1 and empty: none yet).
  std::vector<std::pair<std::string, double>> gpu_timings_ms;
  int gpu_timings_lag = -1;
  std::vector<std::string> skipped;                        // work the plan skipped, and why
  // All of the above and the Gabor bake's times: the text the CLI writes with --stats FILE.
  std::string json;
};

// The touchable surface nearest to a point (Renderer::nearest_surface).
struct SurfacePoint {
  // mm from the point to the surface; +infinity where no surface is within the asked distance
  // (then point and normal are 0).
  double distance_mm = 0.0;
  Vec3 point{0.0, 0.0, 0.0};   // the nearest surface point, mm
  Vec3 normal{0.0, 0.0, 0.0};  // the surface's outward normal there (unit)
};

// What render() returns: the last frame.
struct PSEUDOSHADOW_API Frame {
  int width = 0, height = 0;
  std::vector<unsigned char> color;  // width x height x 3, RGB8, top row first: the CLI's PNG bytes
  std::vector<Aov> aovs;             // in the order asked for
  Stats stats;

  // The AOV called `name`; throws Error if it was not asked for.
  const Aov& aov(std::string_view name) const;
};

class PSEUDOSHADOW_API Renderer {
 public:
  // The scene file at `path` (relative files in it resolve against its directory).
  static Renderer open_file(const std::string& path, const OpenDesc& desc = {});
  // Scene text; `source_name` names it in messages ("<source_name>:<line>: ..."), relative files
  // resolve against `base_dir` (empty: the current directory).
  static Renderer open_string(const std::string& text, const std::string& source_name = "<string>",
                              const std::string& base_dir = "", const OpenDesc& desc = {});
  // The built-in default scene (the CLI's render without --scene).
  static Renderer open_default(const OpenDesc& desc = {});

  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;
  ~Renderer();

  // Changes one scene value by its path, as --set KEY=VALUE: VALUE is TOML ("0.4", "[1,2,3]",
  // "exact_max"). The scene is parsed again and the GL renderer rebuilt at the next render();
  // the probe keeps the position and velocity it had. A bad key or value throws Error with the
  // CLI's message and changes nothing.
  void set(std::string_view key, std::string_view value);
  void set(std::string_view key_equals_value);
  // Several "KEY=VALUE" at once, checked together (lambda_min <= lambda_max holds only for the
  // pair): one rebuild, and on an error none of them is applied.
  void set_all(const std::vector<std::string>& key_equals_values);
  // Moves the probe (position mm, velocity mm/s) without rendering.
  void set_probe(const Vec3& position, const Vec3& velocity);

  // Renders desc.frames frames and returns the last. The first render after opening or after
  // set() equals the CLI's `render` with the same scene, overrides, --probe, --velocity and
  // --frames byte for byte; later calls continue from where the probe was pushed to.
  Frame render(const RenderDesc& desc = {});

  // Image size of the current scene (render.size), pixels.
  std::pair<int, int> size() const;
  // The scene's current probe position and velocity.
  std::pair<Vec3, Vec3> probe() const;

  // For each of `points` (mm), the nearest point of the scene's touchable surfaces within
  // `max_distance_mm`: the geometry the probe feels (the haptic loop's closest-point query), as the
  // scene file places it (before any frame dents or moves it). Hidden surfaces count (they are
  // felt); a button is a hole in its face with its pocket behind. For placing things against the
  // surfaces, and with a ray marched by these distances, for what lies under a pixel. Needs no GL
  // context; the geometry is built at the first call after opening or set() (a mesh: its BVH).
  std::vector<SurfacePoint> nearest_surface(const std::vector<Vec3>& points, double max_distance_mm = 1000.0) const;

 private:
  struct Impl;
  explicit Renderer(std::unique_ptr<Impl> impl);
  static Renderer open(std::unique_ptr<Impl> impl, const OpenDesc& desc);
  Impl& impl(const char* function) const;
  std::unique_ptr<Impl> impl_;
};

// The AOV names render() accepts, in order: intensity, distance, texture, normal, displacement.
PSEUDOSHADOW_API std::vector<std::string> aov_names();

// Reads an image file with pseudoshadow's own reader (PNG, and EXR and others through
// OpenImageIO): width, height, channels and floats, top row first (8-bit files as k/255).
struct ImageData {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;
};
PSEUDOSHADOW_API ImageData read_image(const std::string& path);

}  // namespace pseudoshadow
