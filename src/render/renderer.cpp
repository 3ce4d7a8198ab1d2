#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/shader.h"
#include "passes/gabor_bake.h"
#include "reference/modulation.h"
#include "render/camera.h"
#include "scene/mesh.h"

namespace ps {

const std::vector<std::string>& aov_names() {
  static const std::vector<std::string> names = {"intensity", "distance", "texture", "normal",
                                                 "displacement"};
  return names;
}

namespace {

Aabb mesh_bounds(const Mesh& m) { return {m.bounds_min, m.bounds_max}; }

Result<gl::Texture> upload_albedo(const std::string& path) {
  auto img = read_image(path);
  if (!img) return img.error();
  const Image& im = img.value();
  std::vector<std::uint8_t> rgba(static_cast<size_t>(im.width) * im.height * 4, 255);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      for (int c = 0; c < 4; ++c) {
        const int src = std::min(c, im.channels - 1);
        const float v = (c == 3 && im.channels < 4) ? 1.0f : im.at(x, im.height - 1 - y, src);
        rgba[(static_cast<size_t>(y) * im.width + x) * 4 + c] =
            static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
      }
  const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(im.width, im.height))));
  gl::Texture t = gl::make_texture_2d(im.width, im.height, GL_RGBA8, levels);
  glTextureSubImage2D(t.id(), 0, 0, 0, im.width, im.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glGenerateTextureMipmap(t.id());
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  return t;
}

class PassTimer {
 public:
  PassTimer(bool enabled, FrameStats& stats) : enabled_(enabled), stats_(stats) { restart(); }
  void lap(const char* name) {
    if (!enabled_) return;
    glFinish();  // llvmpipe renders on flush: finishing makes the wall time the pass's time
    const auto now = std::chrono::steady_clock::now();
    stats_.timings_ms.emplace_back(name, std::chrono::duration<double, std::milli>(now - start_).count());
    start_ = now;
  }
  void restart() {
    if (enabled_) glFinish();
    start_ = std::chrono::steady_clock::now();
  }

 private:
  bool enabled_;
  FrameStats& stats_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

Result<std::unique_ptr<Renderer>> Renderer::create(const Scene& scene, const RendererOptions& options) {
  std::unique_ptr<Renderer> r(new Renderer());
  r->scene_ = scene;
  r->options_ = options;
  if (r->options_.glsl_root.empty()) r->options_.glsl_root = gl::default_glsl_root();
  r->frame_ = make_plane_frame(toward_viewer(scene.camera));
  if (Status s = r->load_scene_resources(); !s) return s.error();
  if (Status s = r->init_passes(); !s) return s.error();
  if (options.prime_reference_plane) {
    if (Status s = r->prime_reference_plane(); !s) return s.error();
  }
  r->stats_.reference_normal = r->frame_.n;
  r->stats_.probe_position = scene.probe.position;
  return r;
}

Status Renderer::load_scene_resources() {
  for (const Surface& s : scene_.surfaces) {
    auto mesh = build_surface_mesh(s);
    if (!mesh) return mesh.error();
    surface_bounds_.push_back(mesh_bounds(mesh.value()));
    surface_meshes_.push_back(GpuMesh::upload(mesh.value()));
  }
  if (scene_.probe.shape == ProbeShape::kMesh) {
    auto mesh = load_mesh_file(scene_.probe.mesh_file);
    if (!mesh) return mesh.error();
    transform_mesh(mesh.value(), scene_.probe.mesh_scale, glm::dvec3(0.0), glm::dvec3(0.0));
    probe_mesh_bounds_ = mesh_bounds(mesh.value());
    probe_mesh_ = GpuMesh::upload(mesh.value());
  }
  // The pseudo-shadow lives in a square window as wide as the probe's bounding diameter
  // (plan.cpp): a baked tile chosen by "auto" must be at least that long so no shadow shows a
  // repeat. (Editing the probe's size builds a new Renderer, so this is chosen again.)
  const double shadow_window_mm = 2.0 * current_probe_bounds().radius;
  for (const Material& m : scene_.materials) {
    gabor_setups_.push_back(make_gabor_setup(m.gabor));
    gl::Texture tex;
    if (!m.albedo_texture.empty()) {
      auto t = upload_albedo(m.albedo_texture);
      if (!t) return t.error();
      tex = std::move(t.value());
    }
    albedo_textures_.push_back(std::move(tex));
    // Strategy "baked": one tile per material, baked here, i.e. again only when the material
    // changes (every edit builds a new Renderer). Too fine for a tile: the naive sum is used.
    GaborBakePlan plan;
    std::shared_ptr<gl::Texture> tile;
    if (m.textured) {
      const GaborStrategyChoice choice = choose_gabor_tile(m.gabor, gabor_setups_.back(), scene_.render.seed,
                                                             shadow_window_mm);
      plan = choice.plan;
      if (m.gabor.strategy == GaborParams::Strategy::kAuto) {
        char note[200];
        if (plan.ok)
          std::snprintf(note, sizeof note, "material '%s': Gabor sum replaced by a baked %d^2 tile "
                        "(%s lookup, %.0f mm period, RMS %.4f sigma vs naive)", m.name.c_str(), plan.texels,
                        plan.linear ? "bilinear" : "Hermite", plan.period_mm, choice.rms_vs_naive);
        else if (choice.best_period_mm == 0.0)
          std::snprintf(note, sizeof note, "material '%s': naive Gabor sum (too fine for a %d^2 tile)",
                        m.name.c_str(), kMaxBakeTexels);
        else if (choice.best_period_mm < shadow_window_mm)
          std::snprintf(note, sizeof note, "material '%s': naive Gabor sum (a tile would repeat every "
                        "%.1f mm, inside the %.1f mm shadow)", m.name.c_str(), choice.best_period_mm,
                        shadow_window_mm);
        else
          std::snprintf(note, sizeof note, "material '%s': naive Gabor sum (no tile within %.0f %% "
                        "sigma of it: best %.4f)", m.name.c_str(), kAutoBakeSelectRms * 100.0, choice.rms_vs_naive);
        strategy_notes_.push_back(note);
      } else if (!plan.ok && (m.gabor.strategy == GaborParams::Strategy::kBaked ||
                              m.gabor.strategy == GaborParams::Strategy::kBakedLinear)) {
        strategy_notes_.push_back("material '" + m.name + "': too fine for a baked tile "
                                  "(lambda_max / lambda_min too large), naive Gabor used");
      }
      const Renderer* old = options_.reuse_tiles_from;
      if (plan.ok && old)
        for (size_t k = 0; k < old->scene_.materials.size() && !tile; ++k)
          if (old->gabor_tiles_[k] && old->scene_.materials[k].gabor == m.gabor &&
              old->scene_.render.seed == scene_.render.seed && old->bake_plans_[k].linear == plan.linear &&
              old->bake_plans_[k].texels == plan.texels && old->bake_plans_[k].period_cells == plan.period_cells)
            tile = old->gabor_tiles_[k];
      if (plan.ok && !tile) {
        const auto t0 = std::chrono::steady_clock::now();
        auto baked = bake_gabor_tile(options_.glsl_root, m.gabor, gabor_setups_.back(), plan,
                                     scene_.render.seed);
        if (!baked) return baked.error();
        tile = std::make_shared<gl::Texture>(std::move(baked.value()));
        glFinish();
        stats_.bake_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      }
    }
    bake_plans_.push_back(plan);
    gabor_tiles_.push_back(std::move(tile));
  }
  return ok_status();
}

Status Renderer::init_passes() {
  const RenderSettings& rs = scene_.render;
  if (Status s = probe_depth_.init(options_.glsl_root, {rs.depth_map_size}); !s) return s;
  if (Status s = surface_.init(options_.glsl_root, {rs.width, rs.height}); !s) return s;
  if (Status s = reductions_.init(options_.glsl_root, surface_); !s) return s;
  return probe_view_.init(options_.glsl_root, surface_);
}

Status Renderer::prime_reference_plane() {
  FramePlan plan = make_plan(scene_, surface_bounds_, current_probe_bounds(), frame_,
                             scene_.render.depth_map_size);
  plan.surface_shadow.assign(plan.surface_shadow.size(), false);
  plan.surface_textured.assign(plan.surface_textured.size(), false);
  if (Status s = surface_.run(surface_draws(plan), nullptr, scene_.render.background); !s) return s;
  const ReductionResult r = reductions_.run(surface_, {scene_.render.weight_exponent}, false);
  const double len = glm::length(r.normal_sum);
  if (len > 1e-6 * std::max(r.normal_coverage, 1e-30) && std::isfinite(len))
    frame_ = make_plane_frame(r.normal_sum / len);
  return ok_status();
}

void Renderer::set_probe_state(const glm::dvec3& position, const glm::dvec3& velocity) {
  scene_.probe.position = position;
  scene_.probe.velocity = velocity;
}

BoundingSphere Renderer::current_probe_bounds() const {
  const Probe& p = scene_.probe;
  return probe_bounds(p, probe_mesh_bounds_.min + p.position, probe_mesh_bounds_.max + p.position);
}

std::vector<SurfaceDraw> Renderer::surface_draws(const FramePlan& plan) {
  const double aspect = static_cast<double>(scene_.render.width) / scene_.render.height;
  SurfaceFrame fr;
  fr.view_proj = view_projection(scene_.camera, aspect);
  fr.plane = frame_;
  fr.window_center_uv = plan.window.center_uv;
  fr.window_half_mm = plan.window.half_size_mm;
  fr.depth_map_size = scene_.render.depth_map_size;
  fr.light = &scene_.light;
  fr.contrast_sigmas = options_.contrast_sigmas;
  fr.seed = scene_.render.seed;
  std::vector<SurfaceDraw> draws;
  bool gain_recorded = false;
  for (size_t i = 0; i < scene_.surfaces.size(); ++i) {
    const size_t mi = static_cast<size_t>(scene_.surfaces[i].material_index);
    const Material& m = scene_.materials[mi];
    const double gain = speed_gain(m, frame_, scene_.probe.velocity);
    if (plan.surface_shadow[i] && !gain_recorded) {
      stats_.speed_gain = gain;
      gain_recorded = true;
    }
    const gl::Texture* albedo = albedo_textures_[mi] ? &albedo_textures_[mi] : nullptr;
    SurfaceDraw d;
    d.mesh = &surface_meshes_[i];
    d.block = make_surface_block(fr, m, gabor_setups_[mi], gain, albedo != nullptr);
    d.shadow = plan.surface_shadow[i];
    d.textured = plan.surface_textured[i];
    d.stratified = gabor_setups_[mi].stratified_count > 0;
    d.albedo = albedo;
    if (gabor_tiles_[mi]) {
      const GaborBakePlan& plan = bake_plans_[mi];
      d.gabor_tile = gabor_tiles_[mi].get();
      d.gabor_tile_linear = plan.linear;
      d.block.misc = glm::vec4(d.block.misc.x, static_cast<float>(plan.period_mm),
                               static_cast<float>(plan.texel_mm), static_cast<float>(plan.texels));
    }
    draws.push_back(std::move(d));
  }
  return draws;
}

void Renderer::apply_reductions(const ReductionResult& r, const FramePlan& plan) {
  // Mean of the visible normals becomes the next frame's reference normal (thesis §4.5.2).
  // A mean of (nearly) zero length - a sheet seen edge-on, a sphere seen from inside - has no
  // direction: keep the previous plane rather than normalising noise.
  const double len = glm::length(r.normal_sum);
  if (len > 1e-6 * std::max(r.normal_coverage, 1e-30) && std::isfinite(len))
    frame_ = make_plane_frame(r.normal_sum / len);
  glm::dvec3 disp(0.0);
  if (plan.shadow_active) {
    if (scene_.render.displacement == DisplacementMethod::kExactMax)
      disp = r.max_resisted_penetration_mm * frame_.n;  // d is measured along n: exact push-out
    else
      disp = r.weighted_displacement;
  }
  if (!std::isfinite(disp.x) || !std::isfinite(disp.y) || !std::isfinite(disp.z)) disp = glm::dvec3(0.0);
  scene_.probe.position += disp;
  stats_.displacement = disp;
  stats_.max_penetration_mm = r.max_penetration_mm;
  stats_.shadow_pixels = r.covered_fragments;
  stats_.penetrating_pixels = r.penetrating_fragments;
  stats_.reference_normal = frame_.n;
  stats_.probe_position = scene_.probe.position;
}

Status Renderer::render_frame() {
  stats_.timings_ms.clear();
  PassTimer timer(options_.time_passes, stats_);
  const BoundingSphere probe = current_probe_bounds();
  const FramePlan plan = make_plan(scene_, surface_bounds_, probe, frame_, scene_.render.depth_map_size);
  stats_.skipped = plan.skipped;
  stats_.skipped.insert(stats_.skipped.end(), strategy_notes_.begin(), strategy_notes_.end());
  timer.lap("plan");
  if (plan.shadow_active) {
    ProbeDepthPass::Inputs in;
    in.frame = &frame_;
    in.window = plan.window;
    const CapsuleShape capsule = capsule_of(scene_.probe);
    if (scene_.probe.shape == ProbeShape::kMesh) {
      in.mesh = &probe_mesh_;
      in.model = glm::translate(glm::dmat4(1.0), scene_.probe.position);
      const double hc = glm::dot(probe.center, frame_.n);
      in.height_lo = hc - probe.radius - 1.0;
      in.height_hi = hc + probe.radius + 1.0;
    } else {
      in.capsule = &capsule;
    }
    probe_depth_.run(in);
    timer.lap("probe_depth");
  }
  if (Status s = surface_.run(surface_draws(plan), plan.shadow_active ? &probe_depth_.depth() : nullptr,
                              scene_.render.background); !s)
    return s;
  timer.lap("surface");
  if (plan.shadow_active) {
    const ReductionResult r = reductions_.run(surface_, {scene_.render.weight_exponent}, true);
    timer.lap("reductions");
    apply_reductions(r, plan);
  } else {
    apply_reductions(ReductionResult{}, plan);  // zero sum: plane kept, no displacement
  }
  if (show_probe_) {
    ProbeViewPass::Inputs in;
    in.view_proj = view_projection(scene_.camera,
                                   static_cast<double>(scene_.render.width) / scene_.render.height);
    in.light = &scene_.light;
    const CapsuleShape capsule = capsule_of(scene_.probe);  // after the displacement
    if (scene_.probe.shape == ProbeShape::kMesh) {
      in.mesh = &probe_mesh_;
      in.model = glm::translate(glm::dmat4(1.0), scene_.probe.position);
    } else {
      in.capsule = &capsule;
    }
    probe_view_.run(in);
    timer.lap("probe_view");
  }
  return ok_status();
}

namespace {

// Reads the image-size region of a (padded) texture, flipping to top-row-first.
Image read_region(const gl::Texture& tex, int w, int h, int channels_out, GLenum format,
                  GLenum type) {
  const int in_channels = 4;
  Image img;
  img.width = w;
  img.height = h;
  img.channels = channels_out;
  img.pixels.resize(static_cast<size_t>(w) * h * channels_out);
  const size_t n = static_cast<size_t>(w) * h * in_channels;
  // Converted straight from the readback buffer: no float copy of a byte image (at 2048^2 that
  // copy alone was 64 MiB of the render's peak memory).
  auto flip_into = [&](const auto* src, float divisor) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < channels_out; ++c)
          img.at(x, y, c) = static_cast<float>(src[(static_cast<size_t>(h - 1 - y) * w + x) * in_channels + c]) / divisor;
  };
  if (type == GL_UNSIGNED_BYTE) {
    std::vector<std::uint8_t> b(n);
    glGetTextureSubImage(tex.id(), 0, 0, 0, 0, w, h, 1, format, type, static_cast<GLsizei>(b.size()), b.data());
    flip_into(b.data(), 255.0f);
  } else {
    std::vector<float> f(n);
    glGetTextureSubImage(tex.id(), 0, 0, 0, 0, w, h, 1, format, type,
                         static_cast<GLsizei>(f.size() * sizeof(float)), f.data());
    flip_into(f.data(), 1.0f);
  }
  return img;
}

Image pick_channel(const Image& src, int channel) {
  Image out;
  out.width = src.width;
  out.height = src.height;
  out.channels = 1;
  out.pixels.resize(static_cast<size_t>(src.width) * src.height);
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < src.width; ++x) out.at(x, y, 0) = src.at(x, y, channel);
  return out;
}

}  // namespace

Image Renderer::read_color() const {
  return read_region(surface_.color(), scene_.render.width, scene_.render.height, 3, GL_RGBA,
                     GL_UNSIGNED_BYTE);
}

Result<Image> Renderer::read_aov(const std::string& name) const {
  const int w = scene_.render.width, h = scene_.render.height;
  if (name == "normal") return read_region(surface_.normal(), w, h, 3, GL_RGBA, GL_FLOAT);
  if (name == "displacement") {
    // Drawn on request from the frame's targets (the frame's average uses row sums instead).
    auto tex = reductions_.displacement_aov(surface_);
    if (!tex) return tex.error();
    return read_region(tex.value(), w, h, 4, GL_RGBA, GL_FLOAT);
  }
  const auto& names = aov_names();
  const auto it = std::find(names.begin(), names.begin() + 3, name);
  if (it == names.begin() + 3) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    return make_error("unknown AOV '" + name + "' (known: " + list + ")");
  }
  const Image all = read_region(surface_.aov(), w, h, 4, GL_RGBA, GL_FLOAT);
  return pick_channel(all, static_cast<int>(it - names.begin()));
}

}  // namespace ps
