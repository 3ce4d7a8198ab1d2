#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/es30.h"
#include "gl/shader.h"
#include "reference/modulation.h"
#include "render/pass_timer.h"
#include "render/readback.h"
#include "render/surface_draws.h"
#include "scene/camera.h"
#include "scene/mesh.h"

namespace ps {

bool same_camera(const Camera& a, const Camera& b) {
  return a.projection == b.projection && a.position == b.position && a.target == b.target && a.up == b.up &&
         a.fov_y_deg == b.fov_y_deg && a.ortho_height_mm == b.ortho_height_mm && a.near_mm == b.near_mm &&
         a.far_mm == b.far_mm;
}

namespace {

// The probe's bounds where it stands (a mesh probe's from its model-space box).
BoundingSphere bounds_at(const Probe& p, const Aabb& mesh_box) {
  return probe_bounds(p, mesh_box.min + p.position, mesh_box.max + p.position);
}

}  // namespace

Result<std::unique_ptr<Renderer>> Renderer::create(const Scene& scene, const RendererOptions& options) {
  std::unique_ptr<Renderer> r(new Renderer());
  r->created_at_ = std::chrono::steady_clock::now();
  r->scene_ = scene;
  r->options_ = options;
  r->options_.view.reset();  // held once, in view_
  if (gl::dialect() == gl::Dialect::kEs30) r->options_.gpu_timers = false;  // ES 3.0: no timer queries
  r->view_ = options.view;
  if (!r->view_) {
    auto view = make_view(r->scene_);
    if (!view) return view.error();
    r->view_ = std::move(view.value());
  }
  r->probe_ = r->scene_.probe;
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

// The view's deformable surfaces as they stand (a fresh view's: the scene's probe pressing in as it
// would after a second of holding still, what `render` shows).
Status Renderer::upload_surfaces() {
  const world::DeformableSurfaces* deformables = view_->deformables.get();
  uploaded_.assign(scene_.surfaces.size(), 0);
  for (std::size_t i = 0; i < scene_.surfaces.size(); ++i) {
    auto g = make_surface_geometry(scene_.surfaces[i], static_cast<int>(i), deformables);
    if (!g) return g.error();
    geometry_.surfaces.push_back(std::move(g.value()));
  }
  if (deformables)
    for (const world::DeformableSurfaces::Drawn& d : deformables->drawn())
      uploaded_.at(static_cast<std::size_t>(d.surface)) = d.version;
  return ok_status();
}

// The deformable meshes stepped since their last upload, to the GPU. The normal target's mean
// holds only while the surfaces do not move.
void Renderer::upload_deformed() {
  if (!view_->deformables) return;
  for (const world::DeformableSurfaces::Drawn& d : view_->deformables->drawn()) {
    std::uint64_t& uploaded = uploaded_.at(static_cast<std::size_t>(d.surface));
    if (d.version == uploaded) continue;
    geometry_.surfaces[static_cast<std::size_t>(d.surface)].mesh.update(*d.mesh);
    uploaded = d.version;
    normal_mean_.valid = false;
    ++mesh_version_;  // in the frame key: the next frame redraws everything
  }
}

const DeformationStats& Renderer::deformation() const {
  static const DeformationStats none;
  return view_->deformables ? view_->deformables->stats() : none;
}

std::vector<glm::dvec3> Renderer::deformed_vertices(int surface) const {
  return view_->deformables ? view_->deformables->positions(surface) : std::vector<glm::dvec3>{};
}

Status Renderer::load_probe_mesh() {
  if (probe_.shape != ProbeShape::kMesh) return ok_status();  // analytic: nothing to load
  auto mesh = load_mesh_file(probe_.mesh_file);
  if (!mesh) return mesh.error();
  transform_mesh(mesh.value(), probe_.mesh_scale, glm::dvec3(0.0), glm::dvec3(0.0));
  geometry_.probe_mesh_bounds = {mesh->bounds_min, mesh->bounds_max};
  geometry_.probe_mesh = GpuMesh::upload(mesh.value());
  return ok_status();
}

Status Renderer::load_materials() {
  // Editing the probe's size builds a new Renderer, so the strategy is chosen again.
  const StrategyInputs in{2.0 * current_probe_bounds().radius, scene_.render.seed, options_.expected_frames,
                          textured_pixels_per_frame()};
  return materials_.load(scene_.materials, in);
}

// At the scene's start (its camera and probe): what a renderer weighs a bake with when created.
double Renderer::textured_pixels_per_frame() const {
  return textured_pixels_bound(scene_.render, scene_.camera, scene_.probe.position,
                               2.0 * bounds_at(scene_.probe, geometry_.probe_mesh_bounds).radius);
}

Status Renderer::init_passes() {
  const RenderSettings& rs = scene_.render;
  if (Status s = probe_depth_.init(options_.glsl_root, {rs.depth_map_size}); !s) return s;
  if (Status s = surface_.init(options_.glsl_root, {rs.width, rs.height}); !s) return s;
  if (Status s = reductions_.init(options_.glsl_root, surface_, options_.reductions); !s) return s;
  return probe_view_.init(options_.glsl_root, surface_);
}

// Tiles of options_.reuse_tiles_from are kept where its seed is this scene's (MaterialSet::bake).
Status Renderer::bake_gabor_tiles() {
  const Renderer* old = options_.reuse_tiles_from;
  const MaterialSet* reuse = old && old->scene_.render.seed == scene_.render.seed ? &old->materials_ : nullptr;
  if (Status s = materials_.bake(options_.glsl_root, options_.bake_slice_ms, reuse); !s) return s;
  note_bake();
  return ok_status();
}

Status Renderer::advance_bake() {
  if (materials_.tiles().done()) return ok_status();
  if (Status s = materials_.advance(options_.glsl_root, last_draw_ms_); !s) return s;
  note_bake();
  return ok_status();
}

void Renderer::note_bake() {
  const TileBaker& tiles = materials_.tiles();
  stats_.bake_ms = tiles.bake_ms();
  stats_.bake_progress = tiles.progress();
  if (tiles.done() && stats_.tiles_ready_ms < 0.0) stats_.tiles_ready_ms = ms_since_creation();
}

double Renderer::ms_since_creation() const {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - created_at_).count();
}

// Under the scene's camera and light, whatever view the renderer was given (the plane a renderer
// starts from is its scene's; a kept camera re-reduces the normals at the first frame).
Status Renderer::prime_reference_plane() {
  FramePlan plan = make_plan(scene_, scene_.camera, bounds_of(geometry_.surfaces), current_probe_bounds(), frame_,
                             scene_.render.depth_map_size);
  for (SurfacePlan& sp : plan.surfaces) sp.shadow = sp.textured = false;
  View start;
  start.probe = scene_.probe;
  start.camera = scene_.camera;
  start.light = scene_.light;
  if (Status s = surface_.run(surface_draws(plan, start), nullptr, scene_.render.background, PixelRect{}); !s) return s;
  bool reduced = false;
  update_reference_plane(mean_visible_normal(reduced, scene_.camera));
  return ok_status();
}

Result<FrameStats> Renderer::render(const FrameInput& input) {
  apply_input(*view_, input);
  if (input.sheet) add_path_point();
  if (Status s = draw(); !s) return s.error();
  view_->probe.position = probe_.position;  // the displacement, the session's from now on
  return stats_;
}

Status Renderer::render_frame() {
  if (auto s = render({}); !s) return s.error();
  return ok_status();
}

BoundingSphere Renderer::current_probe_bounds() const { return bounds_at(probe_, geometry_.probe_mesh_bounds); }

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

std::vector<SurfaceDraw> Renderer::surface_draws(const FramePlan& plan, const View& view) {
  const SurfaceFrame fr = surface_frame(scene_.render, view.camera, view.light, frame_, plan, current_probe_bounds(),
                                         probe_, options_);
  const std::vector<SphereCaster> bodies = body_casters(scene_, view.bodies_mm);
  const ProbeSheet& sheet = view.sheet;
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
    SurfaceDraw d = material_draw(ms, filter_negligible_);
    if (!g.w4.empty()) {
      // The probe's sheet: the haptic proxy's (FrameInput::sheet), else the nearest vertex's.
      const double w = sheet.surface == static_cast<int>(i) ? sheet.w4 : g.nearest_w(probe_.position, sheet.w4);
      const fourd::Spec& spec = scene_.surfaces[i].fourd;
      inputs.sheet = SheetInputs{w, g.w_max - g.w_min, spec.crossing_diagram_mm, spec.cutaway_mm,
                                 probe_.position, &view.camera};
      d.wireframe = spec.wireframe;
    }
    d.mesh = &g.mesh;
    d.block = make_surface_block(fr, inputs);
    d.shadow = plan.surfaces[i].shadow;
    d.textured = plan.surfaces[i].textured;
    draws.push_back(std::move(d));
  }
  return draws;
}


ReductionResult Renderer::mean_visible_normal(bool& reduced, const Camera& camera) {
  reduced = !normal_mean_.valid || !same_camera(normal_mean_.camera, camera);
  if (reduced) normal_mean_ = {true, camera, reductions_.mean_normal(surface_)};
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

// The view as it stands, with this frame's probe (probe_) moved by the displacement.
Status Renderer::draw() {
  const View& view = *view_;
  probe_.position = view.probe.position;
  probe_.velocity = view.probe.velocity;
  stats_.timings_ms.clear();
  stats_.new_targets = false;
  upload_deformed();  // what the session stepped since the last frame
  stats_.deformation = deformation();
  if (Status s = advance_bake(); !s) return s;  // before the timer: a band is not the frame's work
  const auto drawn_from = std::chrono::steady_clock::now();
  PassTimer timer(options_.time_passes, stats_, options_.gpu_timers ? &gpu_timers_ : nullptr);
  const BoundingSphere probe = current_probe_bounds();
  const FramePlan plan = make_plan(scene_, view.camera, bounds_of(geometry_.surfaces), probe, frame_,
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
  const std::vector<SurfaceDraw> draws = surface_draws(plan, view);
  const PixelRect rect = shadow_rect(plan);
  if (Status s = draw_surfaces(draws, plan, rect); !s) return s;
  timer.lap("surface");
  reduce(plan, timer);
  draw_overlays(timer);
  if (!materials_.tiles().done()) ++stats_.frames_before_tiles;
  // The frame's wall time, the next band's budget (the reductions' read-back waited for the
  // surfaces, so on llvmpipe this is the drawing itself).
  last_draw_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - drawn_from).count();
  if (stats_.first_frame_ms < 0.0) {
    glFinish();  // the frame is drawn, not only queued
    stats_.first_frame_ms = ms_since_creation();
  }
  return ok_status();
}

// The shadow's reductions, then the reference plane and the probe's displacement from them.
void Renderer::reduce(const FramePlan& plan, PassTimer& timer) {
  if (plan.shadow_active) {
    ReductionResult r = reductions_.run(surface_, {scene_.render.weight_exponent,
                                                   scene_.render.displacement == DisplacementMethod::kWeightedAverage,
                                                   options_.footprint_rect});
    timer.lap("reductions");
    // A reduced frame's plane is the mean of the small image's normals (the same surfaces at
    // fewer pixels), never kept in normal_mean_: that holds whole images' means, by camera.
    bool reduced = last_reduced_ != nullptr;
    const ReductionResult n =
        last_reduced_ ? reductions_.mean_normal(*last_reduced_) : mean_visible_normal(reduced, view_->camera);
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
}

void Renderer::poll_gpu_timings(bool wait) {
  if (!options_.gpu_timers) return;
  gpu_timers_.poll(wait);
  stats_.gpu_timings_ms = gpu_timers_.results();
  stats_.gpu_timings_lag = gpu_timers_.lag();
}

Status Renderer::warm_unfiltered_variants() { return materials_.warm_unfiltered(surface_, scene_.surfaces); }

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

// The probe on its sheet, to the world view's path (a frame given a sheet).
void Renderer::add_path_point() {
  const ProbeSheet& sheet = view_->sheet;
  const auto surface = static_cast<std::size_t>(sheet.surface);
  const bool on_sheet = sheet.surface >= 0 && surface < geometry_.surfaces.size() && !geometry_.surfaces[surface].w4.empty();
  double fraction = 0.5;
  if (on_sheet) {
    const SurfaceGeometry& g = geometry_.surfaces[surface];
    const double range = g.w_max - g.w_min;
    if (range > 0.0) fraction = (sheet.w4 - g.w_min) / range;
  }
  world_view_.add_path_point(view_->show.path && on_sheet, fraction, view_->probe.position);
}

Image Renderer::read_color() const { return read_color_image(surface_); }

Result<Image> Renderer::read_aov(Aov aov) const { return read_aov_image(surface_, reductions_, aov); }

Status Renderer::read_aov_into(Aov aov, Image& out, std::vector<float>& raw) const {
  return read_aov_image_into(surface_, reductions_, aov, out, raw);
}

Result<Image> Renderer::read_aov(const std::string& name) const {
  const Result<Aov> aov = parse_aov(name);
  if (!aov) return aov.error();
  return read_aov(aov.value());
}

}  // namespace ps
