// The C++ API (include/pseudoshadow/pseudoshadow.h) over the one render path: the scene loader
// with its --set overrides (src/scene), a headless context (src/gl) and ps::Renderer
// (src/render), used exactly as `pseudoshadow render` uses them, so a first render() equals the
// CLI's image byte for byte. Error values become pseudoshadow::Error here, at the boundary.
#include "prepare/prepare.h"
#include "pseudoshadow/pseudoshadow.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>

#include "api/api_context.h"
#include "image/image.h"
#include "render/renderer.h"
#include "render/scene_frames.h"
#include "scene/scene_io.h"
#include "world/haptic_scene.h"

namespace pseudoshadow {

namespace {

Vec3 to_vec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
glm::dvec3 to_dvec3(const Vec3& v) { return {v[0], v[1], v[2]}; }

template <class T>
T value_or_throw(ps::Result<T> r) {
  if (!r) throw Error(r.error().message);
  return std::move(r.value());
}
void ok_or_throw(const ps::Status& s) {
  if (!s) throw Error(s.error().message);
}

std::string trimmed(std::string_view s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  const size_t e = s.find_last_not_of(" \t");
  return std::string(s.substr(b, e - b + 1));
}

// The same rounding as the PNG writer (src/image/png_io.cpp, quantize_8bit), so Frame::color is
// the bytes of the CLI's PNG.
std::vector<unsigned char> to_rgb8(const ps::Image& image) {
  std::vector<unsigned char> bytes(image.pixels.size());
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const float v = std::isnan(image.pixels[i]) ? 0.0f : std::clamp(image.pixels[i], 0.0f, 1.0f);
    bytes[i] = static_cast<unsigned char>(v * 255.0f + 0.5f);
  }
  return bytes;
}

Stats to_stats(const ps::FrameStats& s, const ps::gl::Context& context, int frames) {
  Stats out;
  out.backend = ps::gl::backend_name(context.backend());
  out.gl_renderer = context.renderer();
  out.egl_device = context.egl_device();
  out.frames = frames;
  out.reference_normal = to_vec3(s.reference_normal);
  out.displacement = to_vec3(s.displacement);
  out.max_penetration_mm = s.max_penetration_mm;
  out.probe_position = to_vec3(s.probe_position);
  out.speed_gain = s.speed_gain;
  out.shadow_pixels = s.shadow_pixels;
  out.penetrating_pixels = s.penetrating_pixels;
  out.timings_ms = s.timings_ms;
  out.gpu_timings_ms = s.gpu_timings_ms;
  out.gpu_timings_lag = s.gpu_timings_lag;
  out.skipped = s.skipped;
  out.json = ps::stats_json(s, out.backend, out.egl_device, out.gl_renderer, frames);
  return out;
}

}  // namespace

using SceneParser = std::function<ps::Result<ps::Scene>(const std::vector<std::string>&)>;

struct Renderer::Impl {
  // Declared first so it is destroyed last: the GL objects of `renderer` need it current.
  std::shared_ptr<ps::gl::Context> context;
  SceneParser parse;  // the scene source (file, text or the default) with the overrides so far
  std::vector<std::string> overrides;
  ps::Scene scene;                         // as parsed, with the probe where the user put it
  std::unique_ptr<ps::Renderer> renderer;  // null until render(); dropped by set()
  // The touchable geometry of `scene` (nearest_surface); built at its first call, dropped by set().
  mutable std::optional<ps::world::HapticScene> haptic;

  ~Impl() {
    if (renderer && context) context->make_current();
  }
  // Where the probe is now: pushed by the frames rendered so far (the renderer's view), or as set.
  const ps::Probe& probe() const { return renderer ? renderer->probe() : scene.probe; }
};

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

Renderer::Impl& Renderer::impl(const char* function) const {
  if (!impl_) throw Error(std::string("pseudoshadow::Renderer::") + function + ": this renderer was moved from");
  return *impl_;
}

Renderer Renderer::open(std::unique_ptr<Impl> impl, const OpenDesc& desc) {
  impl->overrides = desc.set;
  // The scene first: its errors are the user's to fix and need no context.
  impl->scene = value_or_throw(impl->parse(impl->overrides));
  impl->context = api::acquire_context(desc.backend, desc.gpu);
  return Renderer(std::move(impl));
}

Renderer Renderer::open_file(const std::string& path, const OpenDesc& desc) {
  auto impl = std::make_unique<Impl>();
  impl->parse = [path, allow = desc.allow_paths](const std::vector<std::string>& sets) {
    return ps::load_scene(path, sets, allow);
  };
  return open(std::move(impl), desc);
}

Renderer Renderer::open_string(const std::string& text, const std::string& source_name,
                               const std::string& base_dir, const OpenDesc& desc) {
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::absolute(base_dir.empty() ? "." : base_dir, ec);
  auto impl = std::make_unique<Impl>();
  impl->parse = [text, source_name, dir = dir.lexically_normal().string(),
                 allow = desc.allow_paths](const std::vector<std::string>& sets) {
    return ps::parse_scene(text, source_name, dir, sets, allow);
  };
  return open(std::move(impl), desc);
}

Renderer Renderer::open_default(const OpenDesc& desc) {
  auto impl = std::make_unique<Impl>();
  impl->parse = [allow = desc.allow_paths](const std::vector<std::string>& sets) {
    return ps::load_scene_or_default("", sets, allow);
  };
  return open(std::move(impl), desc);
}

void Renderer::set(std::string_view key, std::string_view value) {
  set_all({trimmed(key) + "=" + std::string(value)});
}

void Renderer::set(std::string_view key_equals_value) {
  set_all({std::string(key_equals_value)});
}

void Renderer::set_all(const std::vector<std::string>& key_equals_values) {
  Impl& m = impl("set");
  std::vector<std::string> overrides = m.overrides;
  bool sets_position = false, sets_velocity = false;
  for (const std::string& kv : key_equals_values) {
    const size_t eq = kv.find('=');
    const std::string key = trimmed(std::string_view(kv).substr(0, eq));
    if (eq == std::string::npos || key.empty()) {
      throw Error("--set " + kv + ": expected KEY=VALUE, e.g. materials.wood.lambda_min=0.4");
    }
    sets_position |= key == "probe.position";
    sets_velocity |= key == "probe.velocity";
    overrides.push_back(key + "=" + kv.substr(eq + 1));
  }
  // The probe keeps its state unless these very keys set it.
  const glm::dvec3 position = m.probe().position, velocity = m.probe().velocity;
  ps::Scene scene = value_or_throw(m.parse(overrides));  // throws: nothing changed
  if (!sets_position) scene.probe.position = position;
  if (!sets_velocity) scene.probe.velocity = velocity;
  if (m.renderer) m.context->make_current();
  m.renderer.reset();
  m.haptic.reset();
  m.scene = std::move(scene);
  m.overrides = std::move(overrides);
}

void Renderer::set_probe(const Vec3& position, const Vec3& velocity) {
  Impl& m = impl("set_probe");
  if (m.renderer) {
    m.renderer->view().probe.position = to_dvec3(position);  // the view this session draws
    m.renderer->view().probe.velocity = to_dvec3(velocity);
  }
  m.scene.probe.position = to_dvec3(position);
  m.scene.probe.velocity = to_dvec3(velocity);
}

std::pair<int, int> Renderer::size() const {
  const Impl& m = impl("size");
  return {m.scene.render.width, m.scene.render.height};
}

std::pair<Vec3, Vec3> Renderer::probe() const {
  const Impl& m = impl("probe");
  return {to_vec3(m.probe().position), to_vec3(m.probe().velocity)};
}

std::vector<SurfacePoint> Renderer::nearest_surface(const std::vector<Vec3>& points, double max_distance_mm) const {
  const Impl& m = impl("nearest_surface");
  if (!(max_distance_mm > 0.0) || !std::isfinite(max_distance_mm)) {
    std::ostringstream given;
    given << max_distance_mm;
    throw Error("nearest_surface: max_distance_mm must be a positive number of mm, not " + given.str());
  }
  if (!m.haptic) m.haptic = value_or_throw(ps::world::HapticScene::build(m.scene));
  std::vector<SurfacePoint> out;
  out.reserve(points.size());
  for (const Vec3& p : points) {
    const glm::dvec3 at = to_dvec3(p);
    SurfacePoint s;
    s.distance_mm = std::numeric_limits<double>::infinity();
    if (std::isfinite(at.x) && std::isfinite(at.y) && std::isfinite(at.z)) {
      // No hint: on a surface embedded in 4D a hint keeps the query to the hint's sheet.
      const ps::world::Contact c = m.haptic->closest(at, max_distance_mm);
      if (c.hit) s = SurfacePoint{c.distance_mm, to_vec3(c.point), to_vec3(c.normal)};
    }
    out.push_back(s);
  }
  return out;
}

Frame Renderer::render(const RenderDesc& desc) {
  Impl& m = impl("render");
  if (desc.frames < 0) {
    throw Error("--frames: " + std::to_string(desc.frames) +
                " is not a frame count; use 1 or more (or 0 for the scene's render.frames)");
  }
  const int frames = desc.frames > 0 ? desc.frames : m.scene.render.frames;
  std::vector<ps::Aov> aovs;
  for (const std::string& name : desc.aovs) aovs.push_back(value_or_throw(ps::parse_aov(name)));
  const ps::Probe& now = m.probe();
  const glm::dvec3 position = desc.probe ? to_dvec3(*desc.probe) : now.position;
  const glm::dvec3 velocity = desc.velocity ? to_dvec3(*desc.velocity) : now.velocity;
  m.context->make_current();
  if (!m.renderer) {
    // As `render --probe --velocity --frames N` builds it: the probe in the scene, the frame count
    // in render.frames and in expected_frames (which decides whether a tile bake pays off).
    m.scene.probe.position = position;
    m.scene.probe.velocity = velocity;
    m.scene.render.frames = frames;
    ps::RendererOptions options;
    options.expected_frames = frames;
    m.renderer = value_or_throw(ps::open_renderer(m.scene, options));
    ok_or_throw(ps::render_scene_frames(*m.renderer, frames));  // the CLI's frames, from the start view
  } else {
    const ps::FrameInput at = ps::probe_frame_input(position, velocity);
    for (int i = 0; i < frames; ++i) (void)value_or_throw(m.renderer->render(i == 0 ? at : ps::FrameInput{}));
  }

  Frame frame;
  const ps::Image color = m.renderer->read_color();
  frame.width = color.width;
  frame.height = color.height;
  frame.color = to_rgb8(color);
  for (size_t i = 0; i < aovs.size(); ++i) {
    ps::Image image = value_or_throw(m.renderer->read_aov(aovs[i]));
    frame.aovs.push_back(Aov{desc.aovs[i], image.channels, std::move(image.pixels)});
  }
  frame.stats = to_stats(m.renderer->stats(), *m.context, frames);
  return frame;
}

const Aov& Frame::aov(std::string_view name) const {
  for (const Aov& a : aovs)
    if (a.name == name) return a;
  std::string asked;
  for (const Aov& a : aovs) asked += (asked.empty() ? "" : ", ") + a.name;
  throw Error("AOV '" + std::string(name) + "' was not rendered (asked for: " +
              (asked.empty() ? "none" : asked) + "); name it in RenderDesc::aovs");
}

std::vector<std::string> aov_names() { return ps::aov_names(); }

ImageData read_image(const std::string& path) {
  ps::Image image = value_or_throw(ps::read_image(path));
  return ImageData{image.width, image.height, image.channels, std::move(image.pixels)};
}

}  // namespace pseudoshadow
