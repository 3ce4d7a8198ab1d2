#include "render/material_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "image/image.h"
#include "passes/surface.h"
#include "render/plan.h"  // has_texture

namespace ps {

namespace {

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

// What --stats says about a textured material's Gabor strategy: auto's choice and why, or a
// baked strategy's fallback to the naive sum; empty when there is nothing to say.
std::string strategy_note(const Material& m, const GaborStrategyChoice& choice, double shadow_window_mm) {
  const GaborBakePlan& plan = choice.plan;
  char note[200];
  if (m.gabor.strategy == GaborParams::Strategy::kAuto) {
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
    return note;
  }
  if (!plan.ok && (m.gabor.strategy == GaborParams::Strategy::kBaked ||
                   m.gabor.strategy == GaborParams::Strategy::kBakedLinear))
    return "material '" + m.name + "': too fine for a baked tile "
           "(lambda_max / lambda_min too large), naive Gabor used";
  return {};
}

// "auto" picked a tile, but the frames this renderer will draw need less texture work than
// the bake: the per-pixel sum evaluates at most width x height pixels a frame (every pixel in
// the shadow), the bake evaluates texels^2 samples of the same sum once.
bool naive_is_less_work(const Material& m, int tile_texels, const StrategyInputs& in) {
  if (m.gabor.strategy != GaborParams::Strategy::kAuto || tile_texels <= 0 || in.expected_frames <= 0)
    return false;
  const double pixels = static_cast<double>(in.expected_frames) * in.textured_pixels_per_frame;
  return pixels <= static_cast<double>(tile_texels) * tile_texels;
}

std::string naive_note(const Material& m, int tile_texels, const StrategyInputs& in) {
  char note[200];
  std::snprintf(note, sizeof note, "material '%s': naive Gabor sum (%d frame%s of <= %.0f textured pixels "
                "are less work than baking a %d^2 tile)", m.name.c_str(), in.expected_frames,
                in.expected_frames == 1 ? "" : "s", in.textured_pixels_per_frame, tile_texels);
  return note;
}

// A textured material's strategy: the naive sum when even the smallest tile auto could pick is
// more work than the frames expected (decided before auto measures its candidates' error, a CPU
// sum costing about as much as a small frame), else auto's or the file's choice, unless the
// tile chosen is more work than the frames.
void choose_strategy(const Material& m, const StrategyInputs& in, MaterialGpu& ms) {
  const int smallest = smallest_auto_tile_texels(m.gabor, ms.gabor_setup, in.shadow_window_mm);
  if (naive_is_less_work(m, smallest, in)) {
    ms.strategy_note = naive_note(m, smallest, in);
    return;
  }
  const GaborStrategyChoice choice = choose_gabor_tile(m.gabor, ms.gabor_setup, in.seed, in.shadow_window_mm);
  ms.bake_plan = choice.plan;
  ms.strategy_note = strategy_note(m, choice, in.shadow_window_mm);
  if (choice.plan.ok && naive_is_less_work(m, choice.plan.texels, in)) {
    ms.strategy_note = naive_note(m, choice.plan.texels, in);
    ms.bake_plan = GaborBakePlan{};
  }
}

}  // namespace

Result<MaterialGpu> load_material_gpu(const Material& m, const StrategyInputs& in) {
  MaterialGpu ms;
  ms.material = &m;
  if (!m.albedo_texture.empty()) {
    auto t = upload_albedo(m.albedo_texture);
    if (!t) return t.error();
    ms.albedo = std::move(t.value());
  }
  if (!m.intensity_lut.empty()) ms.intensity_lut = make_intensity_lut_buffer(m.intensity_lut);
  ms.gabor_setup = make_gabor_setup(m.gabor);
  if (m.textured) choose_strategy(m, in, ms);
  ms.gabor_block = make_gabor_block(m.gabor, ms.gabor_setup, ms.bake_plan, in.seed);
  return ms;
}

std::shared_ptr<gl::Texture> reusable_tile(std::span<const MaterialGpu> old, const Material& m,
                                           const GaborBakePlan& plan) {
  for (const MaterialGpu& o : old) {
    if (o.gabor_tile && o.material->gabor == m.gabor && o.bake_plan.linear == plan.linear &&
        o.bake_plan.texels == plan.texels && o.bake_plan.period_cells == plan.period_cells &&
        o.bake_plan.filtered_levels == plan.filtered_levels)
      return o.gabor_tile;
  }
  return nullptr;
}

// The probe's position at creation stands for the frames' (a replay that brings it much closer
// bakes less often than it should; the images are right either way).
double textured_pixels_bound(const RenderSettings& rs, const Camera& c, const glm::dvec3& probe_mm,
                             double probe_diameter_mm) {
  const double image = static_cast<double>(rs.width) * rs.height;
  const double radius = 0.5 * probe_diameter_mm;
  double pixels_per_mm = 0.0;
  if (c.projection == Projection::kOrthographic) {
    pixels_per_mm = rs.height / std::max(c.ortho_height_mm, 1e-9);
  } else {
    const double distance = glm::length(probe_mm - c.position) - radius;
    if (distance <= c.near_mm) return image;
    pixels_per_mm = rs.height / (2.0 * distance * std::tan(glm::radians(c.fov_y_deg) * 0.5));
  }
  const double side_px = 2.0 * radius * pixels_per_mm;
  return std::min(image, side_px * side_px);
}

Status MaterialSet::load(std::span<const Material> materials, const StrategyInputs& in) {
  for (const Material& m : materials) {
    auto ms = load_material_gpu(m, in);
    if (!ms) return ms.error();
    materials_.push_back(std::move(ms.value()));
  }
  return ok_status();
}

Status MaterialSet::bake(const std::string& glsl_root, double slice_ms, const MaterialSet* reuse) {
  tiles_.set_params({slice_ms});
  for (size_t i = 0; i < materials_.size(); ++i) {
    MaterialGpu& ms = materials_[i];
    if (!ms.bake_plan.ok) continue;
    if (reuse) ms.gabor_tile = reusable_tile(reuse->materials_, *ms.material, ms.bake_plan);
    if (!ms.gabor_tile) tiles_.add(i, ms.gabor_block, ms.bake_plan);
  }
  if (slice_ms <= 0.0)
    if (Status s = tiles_.bake_all(glsl_root); !s) return s;
  collect();
  return ok_status();
}

Status MaterialSet::advance(const std::string& glsl_root, double last_frame_ms) {
  if (tiles_.done()) return ok_status();
  if (Status s = tiles_.bake_slice(glsl_root, last_frame_ms); !s) return s;
  collect();
  return ok_status();
}

Status MaterialSet::warm_unfiltered(SurfacePass& surface, std::span<const Surface> surfaces) const {
  for (const Surface& s : surfaces) {
    const MaterialGpu& ms = materials_[static_cast<std::size_t>(s.material_index)];
    const Material& m = *ms.material;
    if (!has_texture(m) || m.gabor.filter != GaborParams::Filter::kAnalytic) continue;
    const int baked = ms.bake_plan.ok ? (ms.bake_plan.linear ? 2 : 1) : 0;
    const SurfaceFlags variant =
        surface_variant({true, true, ms.gabor_setup.stratified_count > 0, baked, 2, static_cast<bool>(ms.intensity_lut)});
    if (Status st = surface.warm(variant); !st) return st;
  }
  return ok_status();
}

void MaterialSet::collect() {
  for (TileBaker::Finished& f : tiles_.take_finished()) materials_[f.material].gabor_tile = std::move(f.tile);
}

}  // namespace ps
