#include "render/renderer.h"

#include "fourd/fourd_mesh.h"  // depth_colour: the probe path on 4D sheets


#include <algorithm>
#include <limits>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/shader.h"
#include "reference/modulation.h"
#include "scene/camera.h"
#include "render/material_gpu.h"
#include "scene/mesh.h"
#include "world/deformable.h"

namespace ps {

namespace {

bool same_camera(const Camera& a, const Camera& b) {
  return a.projection == b.projection && a.position == b.position && a.target == b.target && a.up == b.up &&
         a.fov_y_deg == b.fov_y_deg && a.ortho_height_mm == b.ortho_height_mm && a.near_mm == b.near_mm &&
         a.far_mm == b.far_mm;
}

Aabb mesh_bounds(const Mesh& m) { return {m.bounds_min, m.bounds_max}; }

// Surface::visual_stretch: positions scaled along the surface's local axes about its centre,
// normals by the inverse (the normal transform of a scaling), bounds recomputed.
void stretch_mesh(Mesh& m, const Surface& s) {
  const glm::dmat3 rot = euler_xyz_deg(s.rotation_deg);
  const glm::dmat3 scale(glm::dvec3(s.visual_stretch.x, 0, 0), glm::dvec3(0, s.visual_stretch.y, 0),
                         glm::dvec3(0, 0, s.visual_stretch.z));
  const glm::dmat3 inverse_scale(glm::dvec3(1.0 / s.visual_stretch.x, 0, 0), glm::dvec3(0, 1.0 / s.visual_stretch.y, 0),
                                 glm::dvec3(0, 0, 1.0 / s.visual_stretch.z));
  const glm::dmat3 to = rot * scale * glm::transpose(rot), to_n = rot * inverse_scale * glm::transpose(rot);
  m.bounds_min = glm::dvec3(std::numeric_limits<double>::infinity());
  m.bounds_max = -m.bounds_min;
  for (glm::vec3& p : m.positions) {
    const glm::dvec3 q = s.center + to * (glm::dvec3(p) - s.center);
    p = glm::vec3(q);
    m.bounds_min = glm::min(m.bounds_min, q);
    m.bounds_max = glm::max(m.bounds_max, q);
  }
  for (glm::vec3& n : m.normals) n = glm::vec3(glm::normalize(to_n * glm::dvec3(n)));
}

// CPU wall time per pass (glFinish between passes) and, where `gpu` is given, GPU time per pass
// from timer queries (no wait; gl/timer_query.h).
class PassTimer {
 public:
  PassTimer(bool enabled, FrameStats& stats, gl::TimerQueries* gpu) : enabled_(enabled), stats_(stats), gpu_(gpu) {
    restart();
    if (gpu_ != nullptr) gpu_->begin_frame();
  }
  ~PassTimer() {
    if (gpu_ == nullptr) return;
    gpu_->end_frame();
    stats_.gpu_timings_ms = gpu_->results();
    stats_.gpu_timings_lag = gpu_->lag();
  }
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;
  void lap(const char* name) {
    if (gpu_ != nullptr) gpu_->lap(name);
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
  gl::TimerQueries* gpu_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

Result<std::unique_ptr<Renderer>> Renderer::create(const Scene& scene, const RendererOptions& options) {
  std::unique_ptr<Renderer> r(new Renderer());
  r->created_at_ = std::chrono::steady_clock::now();
  r->scene_ = scene;
  r->options_ = options;
  r->probe_ = r->scene_.probe;
  r->camera_ = r->scene_.camera;
  r->light_ = r->scene_.light;
  if (r->options_.glsl_root.empty()) r->options_.glsl_root = gl::default_glsl_root();
  r->frame_ = make_plane_frame(toward_viewer(scene.camera));
  for (Status (Renderer::*step)() : {&Renderer::upload_surfaces, &Renderer::load_probe_mesh,
                                     &Renderer::load_materials, &Renderer::init_passes,
                                     &Renderer::bake_gabor_tiles}) {
    if (Status s = (r.get()->*step)(); !s) return s.error();
  }
  if (options.prime_reference_plane) {
    if (Status s = r->prime_reference_plane(); !s) return s.error();
  }
  if (r->filter_lod())
    if (Status s = r->warm_unfiltered_variants(); !s) return s.error();
  r->stats_.reference_normal = r->frame_.n;
  r->stats_.probe_position = scene.probe.position;
  return r;
}

Status Renderer::upload_surfaces() {
  for (const Surface& s : scene_.surfaces) {
    auto mesh = build_surface_mesh(s);
    if (!mesh) return mesh.error();
    if (s.visual_stretch != glm::dvec3(1.0)) stretch_mesh(mesh.value(), s);
    SurfaceGeometry g;
    g.bounds = mesh_bounds(mesh.value());
    if (!mesh->w4.empty()) {
      g.sheet_positions = mesh->positions;
      g.w4 = mesh->w4;
      g.w_min = *std::min_element(g.w4.begin(), g.w4.end());
      g.w_max = *std::max_element(g.w4.begin(), g.w4.end());
    }
    if (s.deform.enabled) {
      Deformed d;
      d.surface = static_cast<int>(geometry_.surfaces.size());
      d.mesh = world::subdivide(mesh.value(), s.deform.max_edge_mm);
      d.sim = std::make_shared<world::Deformable>(d.mesh, s.deform);
      g.mesh = GpuMesh::upload(d.mesh, true);
      deformed_.push_back(std::move(d));
    } else {
      g.mesh = GpuMesh::upload(mesh.value());
    }
    geometry_.surfaces.push_back(std::move(g));
  }
  deform_stats_.surfaces = static_cast<int>(deformed_.size());
  // `render` shows the scene's probe pressing in as it would after a second of holding still.
  if (!deformed_.empty())
    for (int i = 0; i < 10; ++i) step_deformation(0.1);
  return ok_status();
}

std::vector<Aabb> Renderer::surface_bounds() const {
  std::vector<Aabb> out;
  for (const SurfaceGeometry& g : geometry_.surfaces) out.push_back(g.bounds);
  return out;
}

DeformationStats Renderer::advance_deformation(double time_s) {
  if (deformed_.empty() || !std::isfinite(time_s)) return deform_stats_;
  const double dt = deform_time_s_ < 0.0 ? 0.0 : time_s - deform_time_s_;
  deform_time_s_ = time_s;
  return dt > 0.0 ? step_deformation(dt) : deform_stats_;
}

DeformationStats Renderer::step_deformation(double dt_s) {
  DeformationStats st;
  st.surfaces = static_cast<int>(deformed_.size());
  // The probe's sphere: a sphere probe, or a capsule's tip cap (Probe::position is its centre);
  // a mesh probe's bounding sphere would dent far more than the mesh touches, so it does not press.
  const Probe& p = probe_;
  const glm::dvec3 centre = p.shape == ProbeShape::kMesh ? glm::dvec3(std::nan("")) : p.position;
  bool moved = false;
  for (Deformed& d : deformed_) {
    const world::DeformStep step = d.sim->step(dt_s, centre, p.radius_mm);
    // At rest with the probe away the step simulates no vertex (none displaced, none near the
    // probe), so nothing changed since the last upload: no re-upload, no new normals.
    if (d.sim->active_count() > 0) {
      d.sim->write(d.mesh);
      geometry_.surfaces[static_cast<std::size_t>(d.surface)].mesh.update(d.mesh);
      moved = true;
      ++st.uploaded;
    }
    st.substeps = std::max(st.substeps, step.substeps);
    st.constrained += step.constrained;
    st.max_displacement_mm = std::max(st.max_displacement_mm, step.max_displacement_mm);
    st.finite = st.finite && d.sim->finite();
  }
  // The normal target's mean holds only while the surfaces do not move.
  if (moved) normal_mean_.valid = false;
  deform_stats_ = st;
  return st;
}

std::vector<glm::dvec3> Renderer::deformed_vertices(int surface) const {
  for (const Deformed& d : deformed_)
    if (d.surface == surface) return d.sim->positions();
  return {};
}

Status Renderer::load_probe_mesh() {
  if (probe_.shape != ProbeShape::kMesh) return ok_status();  // analytic: nothing to load
  auto mesh = load_mesh_file(probe_.mesh_file);
  if (!mesh) return mesh.error();
  transform_mesh(mesh.value(), probe_.mesh_scale, glm::dvec3(0.0), glm::dvec3(0.0));
  geometry_.probe_mesh_bounds = mesh_bounds(mesh.value());
  geometry_.probe_mesh = GpuMesh::upload(mesh.value());
  return ok_status();
}

Status Renderer::load_materials() {
  // Editing the probe's size builds a new Renderer, so the strategy is chosen again.
  const StrategyInputs in{2.0 * current_probe_bounds().radius, scene_.render.seed, options_.expected_frames,
                          textured_pixels_per_frame()};
  for (const Material& m : scene_.materials) {
    auto ms = load_material_gpu(m, in);
    if (!ms) return ms.error();
    materials_.push_back(std::move(ms.value()));
  }
  return ok_status();
}

// An upper bound on the pixels a frame textures: the pseudo-shadow's square window (as wide as
// the probe's bounding diameter, plan.cpp) seen face-on at the probe's nearest distance to the
// camera (foreshortening only shrinks it), capped by the image. The probe's position at
// creation stands for the frames' (a replay that brings it much closer bakes less often than
// it should; the images are right either way).
double Renderer::textured_pixels_per_frame() const {
  const double image = static_cast<double>(scene_.render.width) * scene_.render.height;
  const BoundingSphere b = current_probe_bounds();
  const Camera& c = camera_;
  double pixels_per_mm = 0.0;
  if (c.projection == Projection::kOrthographic) {
    pixels_per_mm = scene_.render.height / std::max(c.ortho_height_mm, 1e-9);
  } else {
    const double distance = glm::length(probe_.position - c.position) - b.radius;
    if (distance <= c.near_mm) return image;
    pixels_per_mm = scene_.render.height / (2.0 * distance * std::tan(glm::radians(c.fov_y_deg) * 0.5));
  }
  const double side_px = 2.0 * b.radius * pixels_per_mm;
  return std::min(image, side_px * side_px);
}

Status Renderer::init_passes() {
  const RenderSettings& rs = scene_.render;
  if (Status s = probe_depth_.init(options_.glsl_root, {rs.depth_map_size}); !s) return s;
  if (Status s = surface_.init(options_.glsl_root, {rs.width, rs.height}); !s) return s;
  if (Status s = reductions_.init(options_.glsl_root, surface_); !s) return s;
  return probe_view_.init(options_.glsl_root, surface_);
}

// Strategy "baked": one tile per material, baked here (or queued for render_frame when
// sliced), i.e. again only when the material changes (every edit builds a new Renderer;
// reuse_tiles_from keeps the unchanged, finished ones).
Status Renderer::bake_gabor_tiles() {
  tiles_.set_params({options_.bake_slice_ms});
  for (size_t i = 0; i < materials_.size(); ++i) {
    MaterialGpu& ms = materials_[i];
    if (!ms.bake_plan.ok) continue;
    ms.gabor_tile = reusable_tile(scene_.materials[i], ms.bake_plan);
    if (!ms.gabor_tile) tiles_.add(i, ms.gabor_block, ms.bake_plan);
  }
  if (options_.bake_slice_ms <= 0.0)
    if (Status s = tiles_.bake_all(options_.glsl_root); !s) return s;
  collect_tiles();
  return ok_status();
}

Status Renderer::advance_bake() {
  if (tiles_.done()) return ok_status();
  if (Status s = tiles_.bake_slice(options_.glsl_root); !s) return s;
  collect_tiles();
  return ok_status();
}

// A finished tile replaces its material's per-pixel sum from the next draw on.
void Renderer::collect_tiles() {
  for (TileBaker::Finished& f : tiles_.take_finished()) materials_[f.material].gabor_tile = std::move(f.tile);
  stats_.bake_ms = tiles_.bake_ms();
  stats_.bake_progress = tiles_.progress();
  if (tiles_.done() && stats_.tiles_ready_ms < 0.0) stats_.tiles_ready_ms = ms_since_creation();
}

double Renderer::ms_since_creation() const {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - created_at_).count();
}

// A tile of options_.reuse_tiles_from made from the same Gabor parameters, seed and plan.
std::shared_ptr<gl::Texture> Renderer::reusable_tile(const Material& m, const GaborBakePlan& plan) const {
  const Renderer* old = options_.reuse_tiles_from;
  if (!old || old->scene_.render.seed != scene_.render.seed) return nullptr;
  return ps::reusable_tile(old->materials_, m, plan);
}

Status Renderer::prime_reference_plane() {
  FramePlan plan = make_plan(scene_, camera_, surface_bounds(), current_probe_bounds(), frame_,
                             scene_.render.depth_map_size);
  for (SurfacePlan& sp : plan.surfaces) sp.shadow = sp.textured = false;
  if (Status s = surface_.run(surface_draws(plan), nullptr, scene_.render.background, PixelRect{}); !s) return s;
  bool reduced = false;
  update_reference_plane(mean_visible_normal(reduced));
  return ok_status();
}

void Renderer::set_probe_state(const glm::dvec3& position, const glm::dvec3& velocity) {
  probe_.position = position;
  probe_.velocity = velocity;
}

void Renderer::set_view_pose(const ViewPose& pose) {
  camera_ = carried_camera(camera_, view_, pose);
  light_.direction = carried_direction(light_.direction, view_, pose);
  view_ = pose;
}

void Renderer::apply(const FrameInput& in) {
  if (in.probe) set_probe_state(in.probe->position_mm, in.probe->velocity_mm_s);
  if (std::isfinite(in.time_s)) advance_deformation(in.time_s);
  if (in.camera) camera_ = *in.camera;
  if (in.view) set_view_pose(*in.view);
  if (in.device_mm) device_position_ = *in.device_mm;
  if (in.sheet) {
    sheet_ = *in.sheet;
    add_path_point();
  }
  if (in.bodies_mm)
    body_positions_.assign(in.bodies_mm->begin(),
                           in.bodies_mm->begin() + std::min(in.bodies_mm->size(), scene_.bodies.size()));
  if (in.markers) markers_ = *in.markers;
}

Result<FrameStats> Renderer::render(const FrameInput& input) {
  apply(input);
  if (Status s = render_frame(); !s) return s.error();
  return stats_;
}

BoundingSphere Renderer::current_probe_bounds() const {
  const Probe& p = probe_;
  const Aabb& b = geometry_.probe_mesh_bounds;
  return probe_bounds(p, b.min + p.position, b.max + p.position);
}

ProbeInput Renderer::probe_input() const {
  ProbeInput in;
  if (probe_.shape == ProbeShape::kMesh) {
    in.mesh = &geometry_.probe_mesh;
    in.model = glm::translate(glm::dmat4(1.0), probe_.position);
  } else {
    in.capsule = capsule_of(probe_);
  }
  return in;
}

namespace {

// What every surface of the frame shares: the camera, the reference plane, the depth window, the
// light and the probe's height range (and its capsule, for the closed-form distance).
SurfaceFrame surface_frame(const RenderSettings& rs, const Camera& camera, const Light& light, const PlaneFrame& frame,
                           const FramePlan& plan, const BoundingSphere& probe, const Probe& p,
                           const RendererOptions& options) {
  SurfaceFrame fr;
  fr.view_proj = view_projection(camera, static_cast<double>(rs.width) / rs.height);
  fr.plane = frame;
  fr.window_center_uv = plan.window.center_uv;
  fr.window_half_mm = plan.window.half_size_mm;
  fr.depth_map_size = rs.depth_map_size;
  fr.light = &light;
  fr.contrast_sigmas = options.contrast_sigmas;
  fr.surface_normal_distance = rs.shadow_distance == ShadowDistance::kSurfaceNormal;
  fr.probe_height_lo_mm = glm::dot(probe.center, frame.n) - probe.radius;
  fr.probe_height_hi_mm = glm::dot(probe.center, frame.n) + probe.radius;
  if (p.shape != ProbeShape::kMesh && options.closed_form_normal_distance) fr.probe_capsule = capsule_of(p);
  return fr;
}

// The w of the vertex nearest the probe (`fallback` when none is nearer than infinity: a NaN probe).
double nearest_w(std::span<const glm::vec3> positions, std::span<const float> w4, const glm::dvec3& probe_mm,
                 double fallback) {
  double w = fallback;
  float best = std::numeric_limits<float>::infinity();
  const glm::vec3 probe(probe_mm);
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const glm::vec3 dv = positions[v] - probe;
    const float d2 = glm::dot(dv, dv);
    if (d2 < best) best = d2, w = w4[v];
  }
  return w;
}

}  // namespace

std::vector<SurfaceDraw> Renderer::surface_draws(const FramePlan& plan) {
  const SurfaceFrame fr = surface_frame(scene_.render, camera_, light_, frame_, plan, current_probe_bounds(),
                                         probe_, options_);
  const std::vector<SphereCaster> bodies = body_casters();
  std::vector<SurfaceDraw> draws;
  bool gain_recorded = false;
  for (size_t i = 0; i < scene_.surfaces.size(); ++i) {
    if (!scene_.surfaces[i].visible) continue;  // a hidden object: felt (haptics), never drawn
    const size_t mi = static_cast<size_t>(scene_.surfaces[i].material_index);
    const Material& m = scene_.materials[mi];
    const MaterialGpu& ms = materials_[mi];
    const double gain = speed_gain(m, frame_, probe_.velocity);
    if (plan.surfaces[i].shadow && !gain_recorded) {
      stats_.speed_gain = gain;
      gain_recorded = true;
    }
    const SurfaceGeometry& g = geometry_.surfaces[i];
    const std::vector<SphereCaster> reach = bodies_in_reach(bodies, g.bounds, m.influence_distance_mm);
    SurfaceInputs inputs{&m, &ms.gabor_block, gain, static_cast<bool>(ms.albedo), reach, std::nullopt};
    SurfaceDraw d;
    if (!g.w4.empty()) {
      // The probe's sheet: the haptic proxy's (FrameInput::sheet), else the nearest vertex's.
      const double w = sheet_.surface == static_cast<int>(i)
                           ? sheet_.w4
                           : nearest_w(g.sheet_positions, g.w4, probe_.position, sheet_.w4);
      const fourd::Spec& spec = scene_.surfaces[i].fourd;
      inputs.sheet = SheetInputs{w, g.w_max - g.w_min, spec.crossing_diagram_mm, spec.cutaway_mm,
                                 probe_.position, &camera_};
      d.wireframe = spec.wireframe;
    }
    d.mesh = &g.mesh;
    d.block = make_surface_block(fr, inputs);
    d.shadow = plan.surfaces[i].shadow;
    d.textured = plan.surfaces[i].textured;
    d.stratified = ms.gabor_setup.stratified_count > 0;
    d.albedo = ms.albedo ? &ms.albedo : nullptr;
    d.gabor_tile = ms.gabor_tile.get();
    d.gabor_tile_linear = ms.bake_plan.linear;
    d.intensity_lut = ms.intensity_lut ? &ms.intensity_lut : nullptr;
    d.gabor_filter = m.gabor.filter == GaborParams::Filter::kAnalytic;
    // Only a material drawn in its final form switches: one with an unfinished tile (the window
    // bakes in slices) keeps the per-pixel sum filtered until the tile is there.
    d.gabor_filter_skipped = filter_negligible_ && (ms.gabor_tile || !ms.bake_plan.ok);
    draws.push_back(std::move(d));
  }
  return draws;
}


ReductionResult Renderer::mean_visible_normal(bool& reduced) {
  reduced = !normal_mean_.valid || !same_camera(normal_mean_.camera, camera_);
  if (reduced) normal_mean_ = {true, camera_, reductions_.mean_normal(surface_)};
  return normal_mean_.result;
}

// Mean of the visible normals becomes the next frame's reference normal (thesis §4.5.2).
// A mean of (nearly) zero length - a sheet seen edge-on, a sphere seen from inside - has no
// direction: keep the previous plane rather than normalising noise.
void Renderer::update_reference_plane(const ReductionResult& r) {
  const double len = glm::length(r.normal_sum);
  if (len > 1e-6 * std::max(r.normal_coverage, 1e-30) && std::isfinite(len))
    frame_ = make_plane_frame(r.normal_sum / len);
}

void Renderer::apply_reductions(const ReductionResult& r, const FramePlan& plan) {
  update_reference_plane(r);
  glm::dvec3 disp(0.0);
  if (plan.shadow_active) {
    if (scene_.render.displacement == DisplacementMethod::kExactMax)
      disp = r.max_resisted_penetration_mm * frame_.n;  // d is measured along n: exact push-out
    else
      disp = r.weighted_displacement;
  }
  if (!std::isfinite(disp.x) || !std::isfinite(disp.y) || !std::isfinite(disp.z)) disp = glm::dvec3(0.0);
  probe_.position += disp;
  stats_.displacement = disp;
  stats_.max_penetration_mm = r.max_penetration_mm;
  stats_.shadow_pixels = r.covered_fragments;
  stats_.penetrating_pixels = r.penetrating_fragments;
  stats_.reference_normal = frame_.n;
  stats_.probe_position = probe_.position;
}

Status Renderer::render_frame() {
  stats_.timings_ms.clear();
  stats_.deformation = deform_stats_;
  if (Status s = advance_bake(); !s) return s;  // before the timer: a band is not the frame's work
  PassTimer timer(options_.time_passes, stats_, options_.gpu_timers ? &gpu_timers_ : nullptr);
  const BoundingSphere probe = current_probe_bounds();
  const FramePlan plan = make_plan(scene_, camera_, surface_bounds(), probe, frame_,
                                   scene_.render.depth_map_size);
  stats_.skipped = plan.skipped;
  if (!plan.shadow_active || !filter_lod()) filter_negligible_ = false;  // no measure to go by
  stats_.gabor_filter_skipped = filter_negligible_;
  stats_.gabor_filter_need = 0.0;
  for (const MaterialGpu& ms : materials_)
    if (!ms.strategy_note.empty()) stats_.skipped.push_back(ms.strategy_note);
  timer.lap("plan");
  if (plan.shadow_active) {
    run_probe_depth(plan, probe);
    timer.lap("probe_depth");
  }
  if (Status s = surface_.run(surface_draws(plan), plan.shadow_active ? &probe_depth_.depth() : nullptr,
                              scene_.render.background, shadow_rect(plan));
      !s)
    return s;
  timer.lap("surface");
  if (plan.shadow_active) {
    ReductionResult r = reductions_.run(surface_, {scene_.render.weight_exponent,
                                                   scene_.render.displacement == DisplacementMethod::kWeightedAverage,
                                                   options_.footprint_rect});
    timer.lap("reductions");
    bool reduced = false;
    const ReductionResult n = mean_visible_normal(reduced);
    if (reduced) timer.lap("reference_normal");
    r.normal_sum = n.normal_sum;
    r.normal_coverage = n.normal_coverage;
    apply_reductions(r, plan);
    // The next frame's choice: skipped only when this frame measured a filtered texture, and
    // its need was negligible everywhere (with the filter skipped too the need is measured).
    stats_.gabor_filter_need = r.max_filter_need;
    filter_negligible_ = filter_lod() && r.max_filter_need > 0.0 && r.max_filter_need < kGaborFilterNegligibleNeed;
  } else {
    apply_reductions(ReductionResult{}, plan);  // zero sum: plane kept, no displacement
  }
  if (show_probe_) {
    run_probe_view();
    timer.lap("probe_view");
  }
  if (!body_positions_.empty() || !markers_.empty() || show_device_ || !path_.empty()) {
    run_world_view();
    timer.lap("world_view");
  }
  if (!tiles_.done()) ++stats_.frames_before_tiles;
  if (stats_.first_frame_ms < 0.0) {
    glFinish();  // the frame is drawn, not only queued
    stats_.first_frame_ms = ms_since_creation();
  }
  return ok_status();
}

void Renderer::poll_gpu_timings(bool wait) {
  if (!options_.gpu_timers) return;
  gpu_timers_.poll(wait);
  stats_.gpu_timings_ms = gpu_timers_.results();
  stats_.gpu_timings_lag = gpu_timers_.lag();
}

Status Renderer::warm_unfiltered_variants() {
  for (std::size_t i = 0; i < scene_.surfaces.size(); ++i) {
    const auto mi = static_cast<std::size_t>(scene_.surfaces[i].material_index);
    const Material& m = scene_.materials[mi];
    if (!has_texture(m) || m.gabor.filter != GaborParams::Filter::kAnalytic) continue;
    const MaterialGpu& ms = materials_[mi];
    // As surface_draws() will draw it once its tile is there, with the filter skipped.
    const int baked = ms.bake_plan.ok ? (ms.bake_plan.linear ? 2 : 1) : 0;
    const SurfaceFlags variant =
        surface_variant({true, true, ms.gabor_setup.stratified_count > 0, baked, 2, static_cast<bool>(ms.intensity_lut)});
    if (Status s = surface_.warm(variant); !s) return s;
  }
  return ok_status();
}

PixelRect Renderer::shadow_rect(const FramePlan& plan) const {
  if (!plan.shadow_active) return {};
  return options_.footprint_rect ? plan.shadow_rect : PixelRect::whole(scene_.render.width, scene_.render.height);
}

void Renderer::run_probe_depth(const FramePlan& plan, const BoundingSphere& probe) {
  ProbeDepthPass::Inputs in;
  in.frame = &frame_;
  in.window = plan.window;
  in.probe = probe_input();
  // Mesh probes: the depth buffer spans the probe's plane-height range, with 1 mm of margin.
  const double hc = glm::dot(probe.center, frame_.n);
  in.height_lo = hc - probe.radius - 1.0;
  in.height_hi = hc + probe.radius + 1.0;
  probe_depth_.run(in);
}

// The bodies drawn this frame as shadow casters (spheres of their radius), in scene order.
std::vector<SphereCaster> Renderer::body_casters() const {
  std::vector<SphereCaster> out;
  for (std::size_t i = 0; i < body_positions_.size(); ++i)
    out.push_back({body_positions_[i], scene_.bodies[i].radius_mm});
  return out;
}

void Renderer::add_path_point() {
  const int surface = sheet_.surface;
  const double w4 = sheet_.w4;
  const bool on_sheet = surface >= 0 && static_cast<std::size_t>(surface) < geometry_.surfaces.size() &&
                        !geometry_.surfaces[static_cast<std::size_t>(surface)].w4.empty();
  if (!show_path_ || !on_sheet) {
    path_break_ = true;  // off every sheet (lifted): the path starts a new piece
    return;
  }
  const SurfaceGeometry& sheets = geometry_.surfaces[static_cast<std::size_t>(surface)];
  const double range = sheets.w_max - sheets.w_min;
  const glm::dvec3 colour = fourd::depth_colour(range > 0.0 ? (w4 - sheets.w_min) / range : 0.5);
  const glm::dvec3 p = probe_.position;
  // A tube from the last point, unless the probe left the sheet since (lifted and put down).
  constexpr double kPathRadiusMm = 0.6;
  const bool joined = !path_.empty() && !path_break_;
  path_break_ = false;
  if (joined && glm::length(p - path_.back().b) < 0.25) return;  // closer than a segment is worth
  path_.push_back({joined ? path_.back().b : p, p, kPathRadiusMm, colour});
}

void Renderer::run_world_view() {
  if (!world_view_ready_) {
    if (!body_view_.init(options_.glsl_root, surface_) || !ghost_view_.init(options_.glsl_root, surface_)) return;
    world_view_ready_ = true;
  }
  ProbeViewPass::Inputs in;
  in.view_proj = view_projection(camera_, static_cast<double>(scene_.render.width) / scene_.render.height);
  in.light = &light_;
  for (std::size_t i = 0; i < body_positions_.size(); ++i) {
    const Body& b = scene_.bodies[i];
    const std::size_t m = static_cast<std::size_t>(b.material_index);
    in.probe = ProbeInput{};
    in.probe.capsule = CapsuleShape{body_positions_[i], body_positions_[i], b.radius_mm};
    in.color = m < scene_.materials.size() ? scene_.materials[m].albedo : ProbeViewPass::kColor;
    body_view_.run(in);
  }
  for (const std::vector<WorldMarker>* list : {&path_, &markers_})
    for (const WorldMarker& m : *list) {
      in.probe = ProbeInput{};
      in.probe.capsule = CapsuleShape{m.a, m.b, m.radius_mm};
      in.color = m.color;
      body_view_.run(in);
    }
  if (show_device_) {
    // The probe's shape at the device, faint: where the hand is, against where the proxy is drawn.
    in.probe = probe_input();
    const glm::dvec3 shift = device_position_ - probe_.position;
    in.probe.capsule.a += shift;
    in.probe.capsule.b += shift;
    in.probe.model = glm::translate(glm::dmat4(1.0), shift) * in.probe.model;
    in.color = glm::dvec3(0.35, 0.75, 1.0);
    in.alpha = 0.25;
    ghost_view_.run(in);
  }
}

void Renderer::run_probe_view() {
  ProbeViewPass::Inputs in;
  in.view_proj = view_projection(camera_, static_cast<double>(scene_.render.width) / scene_.render.height);
  in.light = &light_;
  in.probe = probe_input();  // after this frame's displacement
  probe_view_.run(in);
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

// The surface pass writes its AOV target inside the footprint's rectangle only (the texture
// keeps older frames' values elsewhere): outside it every pixel is (0, NaN, 0, 0), the values
// that say "no probe above this pixel" (passes/surface.h). `rect`: GL window coordinates.
Image no_probe_outside(Image img, const PixelRect& rect) {
  const float none[4] = {0.0f, kNoProbeDistance, 0.0f, 0.0f};
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (!rect.contains(x, img.height - 1 - y))  // img is top row first
        for (int c = 0; c < img.channels; ++c) img.at(x, y, c) = none[c];
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

Result<Image> Renderer::read_aov(Aov aov) const {
  const AovInfo& e = aov_info(aov);
  const int w = scene_.render.width, h = scene_.render.height;
  switch (e.source) {
    case AovSource::kSurfaceAov:
      return pick_channel(no_probe_outside(read_region(surface_.aov(), w, h, 4, GL_RGBA, GL_FLOAT),
                                           surface_.shadow_rect()),
                          e.channel);
    case AovSource::kNormal:
      return read_region(surface_.normal(), w, h, 3, GL_RGBA, GL_FLOAT);
    case AovSource::kDisplacement: {
      // Drawn on request from the frame's targets (the frame's average uses row sums instead).
      auto tex = reductions_.displacement_aov(surface_);
      if (!tex) return tex.error();
      return read_region(tex.value(), w, h, 4, GL_RGBA, GL_FLOAT);
    }
  }
  return make_error("read_aov: unhandled AOV source");  // unreachable: the switch covers AovSource
}

Result<Image> Renderer::read_aov(const std::string& name) const {
  const Result<Aov> aov = parse_aov(name);
  if (!aov) return aov.error();
  return read_aov(aov.value());
}

}  // namespace ps
