// The frame loop shared by the headless CLI, the window and the tests (one render path):
//   plan -> probe depth pass -> surface pass -> reductions -> reference plane + displacement.
// While the frame key (render/frame_key.h: the plain variant's inputs, meshes, background, size)
// is the last frame's, the surface pass redraws only the last and new shadow rectangles
// (RendererOptions::incremental); overlays make the next frame a full one.
// Draws the session's view (render/view.h: probe, camera, flags, world), never its own copy of
// it: a rebuilt renderer is handed the view and needs nothing copied over.
// Lives on the render thread; owns every GL object it uses. Needs a current GL context.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "gl/timer_query.h"
#include "image/image.h"
#include "passes/gabor_bake.h"
#include "passes/gabor_block.h"
#include "passes/probe_depth.h"
#include "passes/probe_view.h"
#include "passes/reductions.h"
#include "passes/surface.h"
#include "render/adaptive_scale.h"
#include "render/aov.h"
#include "render/frame_input.h"
#include "render/frame_key.h"
#include "render/frame_stats.h"
#include "render/material_gpu.h"
#include "render/plan.h"
#include "render/surface_geometry.h"
#include "render/tile_bake.h"
#include "render/view.h"
#include "render/world_markers.h"
#include "render/world_view.h"
#include "scene/scene.h"

namespace ps {

class PassTimer;
struct RendererOptions {
  std::string glsl_root;          // empty: gl::default_glsl_root()
  bool time_passes = true;        // glFinish around passes for per-pass wall times
  // GL_TIME_ELAPSED queries around the same passes (gpu_timings_ms); they never make the CPU
  // wait (gl/timer_query.h), so the window keeps them on with time_passes off.
  bool gpu_timers = true;
  double contrast_sigmas = 2.5;   // texture display contrast (see SurfaceFrame)
  // The thesis starts the reference plane facing the viewer and lets it converge over the
  // following frames; a headless render of one frame would then measure distances along the
  // view direction. Priming runs one shadow-free surface pass + normal reduction at creation
  // so the first frame already uses the mean visible normal. false = thesis behaviour.
  bool prime_reference_plane = true;
  // Baked Gabor tiles of this renderer are shared where a material's Gabor parameters and the
  // seed are unchanged (a tuning edit of another value does not re-bake). Must stay alive
  // during create(); never set it across shader reloads (the bake shader may have changed).
  const class Renderer* reuse_tiles_from = nullptr;
  // 0: bake every Gabor tile whole in create(), so every frame reads it (render, replay, tests).
  // > 0 (the window): create() bakes nothing; each render_frame() first bakes one band of the
  // tiles, of about this many ms, and materials with an unfinished tile draw with the per-pixel
  // sum meanwhile: the first frame comes at once, never a black window (render/tile_bake.h).
  double bake_slice_ms = 0.0;
  // > 0: the frames this renderer will draw (render --frames, a tune cell, a replay). For a
  // material whose "auto" strategy picked a tile, the tile is baked only if that is less work
  // than the per-pixel sum over those frames: with frames x P <= texels^2 (P: an upper bound on
  // the pixels a frame textures, the shadow window seen face-on at the probe, capped by the
  // image) the naive sum is drawn instead and nothing is baked (docs/benchmarks.md, "Time to
  // the first image"). 0 = unknown (the window): bake.
  int expected_frames = 0;
  // true: the pseudo-shadow variants, the AOV target and the shadow's reductions cover only the
  // footprint's screen rectangle (FramePlan::shadow_rect), the weighted row sums only the box of
  // penetrating pixels. false: the whole image and whole rows, as before; the results are the
  // same bits (tests compare the two).
  bool footprint_rect = true;
  // Texture filtering's level of detail (docs/architecture.md, "Texture filtering"): a frame
  // draws its analytically filtered materials without the filter when the last frame measured
  // the filter's need below kGaborFilterNegligibleNeed over the whole shadow. The unfiltered
  // variant is one more shader to build (~0.3 s on llvmpipe) for ~0.7 ms of a 512^2 frame: a
  // renderer that expects fewer than kFilterLodMinFrames frames (expected_frames: a render, a
  // golden, a tune cell, a replay) never switches. false: always filtered.
  bool filter_lod = true;
  // render.shadow_distance = "surface_normal" with a sphere or capsule probe: each point's
  // distance in closed form against the probe's shape (capsule_column_distance). false: marched
  // through the probe depth map as for a mesh probe; bench --shadow-distance compares the two.
  bool closed_form_normal_distance = true;
  // Incremental frames (render/frame_key.h): while the frame key is unchanged (only the probe
  // moved), the surface pass redraws the last and this frame's shadow rectangles only and keeps
  // the rest of the last frame; the results are the same bits (tests compare). false: every
  // frame redraws every pixel (FrameStats::drawn_pixels tells which).
  bool incremental = true;
  // The reductions' path (passes/reductions.h): compute shaders (the default), or fragment
  // shaders with the rows reduced on the host, what WebGL2 can run. The same bits either way
  // (ReductionPathsGLTest); `render --reductions fragment` draws with the second.
  ReductionMethod reductions = ReductionMethod::kCompute;
  // The session's view (render/view.h): what each frame draws besides the scene, owned by the
  // session, which hands a rebuilt or switched renderer its view and copies nothing over; it must
  // be of this scene (make_view, rebuilt_view). create() reads only its deformable surfaces.
  // Null: create() makes a fresh view of the scene (make_view: what `render` shows).
  std::shared_ptr<View> view;
};

// The filter's need (glsl/lib/gabor.glsl gabor_filter_need: the exponent of its attenuation of
// lambda_min) under which the next frame skips it: 3 %. For a square footprint need = (pi^2 / 6)
// (pixel / lambda_min)^2, so 3 % is lambda_min seen across 7.4 pixels or more everywhere in the
// shadow, far from the 2 pixels where aliasing starts, and the filter would take at most 3 % of
// lambda_min's contrast (less of the longer wavelengths). A view that zooms out by sqrt(2) between
// two frames (the need grows with the square of the footprint) draws one frame at 5.2 pixels per
// lambda_min, 6 %, unfiltered, and the next one filtered again.
inline constexpr double kGaborFilterNegligibleNeed = 0.03;
inline constexpr int kFilterLodMinFrames = 1000;



class Renderer {
 public:
  static Result<std::unique_ptr<Renderer>> create(const Scene& scene, const RendererOptions& options);

  // One frame of the view: `input` replaces what it gives of it (apply_input), then the view is
  // drawn (plan -> passes -> reductions -> overlays) and the probe's displacement is applied to the
  // view (the pseudo-haptic loop). The scene is never modified.
  Result<FrameStats> render(const FrameInput& input);
  Status render_frame();  // render({}): the view as it stands
  Image read_color() const;                        // RGB, top row first, image size
  Result<Image> read_aov(Aov aov) const;
  Result<Image> read_aov(const std::string& name) const;  // unknown name: error listing aov_names()
  // The same image as read_aov(aov), into `out` through `raw`, both reused: a read every frame
  // (the window's shadow measure) allocates nothing once they have grown to the image.
  Status read_aov_into(Aov aov, Image& out, std::vector<float>& raw) const;

  // An upper bound on the pixels a frame textures (the probe's shadow window seen face-on at
  // the probe, capped by the image): what RendererOptions::expected_frames is weighed with.
  double textured_pixels_per_frame() const;
  const FrameStats& stats() const { return stats_; }
  // Takes GPU timer results that have come back since the frame (wait = true: blocks until the
  // last frame's are there, for a one-shot command about to read its image anyway).
  void poll_gpu_timings(bool wait);
  // The baked tile material i is drawn with (ok == false: the per-pixel sum), as chosen at creation.
  const GaborBakePlan& gabor_bake_plan(size_t material) const { return materials_[material].bake_plan; }
  // The scene as given to create() (prepared: prepare/prepare.h): never changed by a frame.
  const Scene& scene() const { return scene_; }
  const PlaneFrame& reference() const { return frame_; }
  // The bodies (View::bodies_mm) are drawn as spheres of their radius in their material's albedo
  // after the pseudo-shadow (colour only, like the probe), each casting its own analytic
  // pseudo-shadow on the surfaces within the receiving material's influence distance (colour
  // only: the AOVs, reductions and displacement stay the probe's; reference/body_shadow.h). Fewer
  // centres than bodies: the rest are neither drawn nor cast. Markers (render/world_markers.h) are
  // drawn like the bodies, the device (View::device_mm) as a faint ghost of the probe when shown.
  // On a surface embedded in 4D, the probe's sheet (View::sheet) shows the pseudo-shadow on that
  // sheet only (docs/fourd.md); with View::show.path each frame given a sheet also adds the probe's
  // position to its path, drawn after the pseudo-shadow as a tube coloured by w
  // (fourd::depth_colour over the surface's w range; Hanson & Zhang, Fig. 5c): the path is this
  // renderer's drawing, begun afresh by a new one.
  //
  // The view this renderer draws (RendererOptions::view; render/view.h), and two of its parts: the
  // probe now (the scene's, moved by the frame inputs and each frame's displacement) and the world
  // camera the next frame draws with.
  const View& view() const { return *view_; }
  // The same view, for a session that holds it through the renderer drawing it (drive_frame steps
  // its deformable surfaces): it is the session's, shared, never the renderer's own state.
  View& view() { return *view_; }
  const Probe& probe() const { return view_->probe; }
  const Camera& camera() const { return view_->camera; }
  // What the view's deformable surfaces' last step did (all zero without any).
  const DeformationStats& deformation() const;
  // The welded vertices of deformable surface `surface` now (world mm); empty if not deformable.
  std::vector<glm::dvec3> deformed_vertices(int surface) const;
  // The frame's colour target (RGBA8, padded to a power of two; the image is the
  // width x height region at the origin, bottom row first): blitted to the window.
  const gl::Texture& color_texture() const { return surface_.color(); }
  // Adaptive resolution (docs/adaptive.md; the window's frame loop, render/adaptive_scale.h): the
  // scale the surface pass is drawn at from the next frame on, `moving` when the frame's camera
  // differs from the last frame's, else `still`. Below 1 the frame is drawn small and upsampled,
  // and the footprint's rectangle (all the reductions read: max penetration, displacement) is
  // redrawn at full resolution over it; the reference plane is reduced from the small image's
  // normals (a whole frame at rest reduces the whole image's again). Never set (every headless command): {1, 1}, every frame whole. With
  // RendererOptions::footprint_rect off every frame is whole (the reductions read the image).
  void set_surface_scale(SurfaceScale scale) { surface_scale_ = scale; }

 private:
  gl::TimerQueries gpu_timers_;  // per-pass GL_TIME_ELAPSED queries (RendererOptions::gpu_timers)
  struct Geometry {
    std::vector<SurfaceGeometry> surfaces;
    GpuMesh probe_mesh;                   // mesh probes only
    Aabb probe_mesh_bounds;               // model space, scaled
  };

  Renderer() = default;
  // Creation, in order: each builds one part of the state.
  Status upload_surfaces();
  Status load_probe_mesh();
  Status load_materials();        // albedo textures, Gabor setup and strategy
  Status init_passes();
  Status warm_unfiltered_variants();  // filter_lod(): the PS_GABOR_FILTER=2 variants, built ahead
  Status bake_gabor_tiles();      // tiles of the materials whose strategy chose one (or queue them)
  Status advance_bake();          // per frame: one band of the queued tiles, then the stats
  void note_bake();               // the bake's stats
  double ms_since_creation() const;
  Status prime_reference_plane();
  void upload_deformed();
  // Per frame.
  // The probe itself is drawn (ProbeViewPass) where the view shows it (--show-probe, run's P) or
  // the scene asks for it (render.draw_probe): either one draws it.
  bool probe_drawn() const { return view_->show.probe || scene_.render.draw_probe; }
  BoundingSphere current_probe_bounds() const;
  ProbeInput probe_input() const;
  void run_probe_depth(const FramePlan& plan, const BoundingSphere& probe);
  PixelRect shadow_rect(const FramePlan& plan) const;  // the surface pass's (options_.footprint_rect)
  std::vector<SurfaceDraw> surface_draws(const FramePlan& plan, const View& view);
  void update_reference_plane(const ReductionResult& r);
  // The mean visible normal of this frame's normal target, drawn with `camera`: reduced when the
  // camera changed since the last reduction, else that reduction's result (see normal_mean_).
  // `reduced`: set when the reduction ran.
  ReductionResult mean_visible_normal(bool& reduced, const Camera& camera);
  void apply_reductions(const ReductionResult& r, const FramePlan& plan);
  void reduce(const FramePlan& plan, PassTimer& timer);
  void draw_overlays(PassTimer& timer);  // ends the incremental run (renderer_incremental.cpp)
  PixelRect redraw_rect(const std::vector<SurfaceDraw>& draws, const PixelRect& shadow_rect);
  // The surface pass, whole or at a reduced scale (renderer_adaptive.cpp).
  Status draw_surfaces(const std::vector<SurfaceDraw>& draws, const FramePlan& plan, const PixelRect& rect);
  Status draw_reduced(const std::vector<SurfaceDraw>& draws, const FramePlan& plan, const PixelRect& rect,
                      glm::ivec2 size);
  Result<SurfacePass*> reduced_pass(glm::ivec2 size);
  double frame_scale();  // this frame's scale; notes it and whether the view moved in stats_

  Scene scene_;
  RendererOptions options_;
  PlaneFrame frame_;
  FrameStats stats_;
  Geometry geometry_;
  MaterialSet materials_;  // GPU state of Scene::materials, in order (each points at its material)
  std::chrono::steady_clock::time_point created_at_;  // start of create(): the stats' time origin
  double last_draw_ms_ = 0.0;  // the last draw()'s wall time, its band excluded: the next band's budget
  // The last mean visible normal and the camera it was reduced for. The normal target holds
  // the visible surfaces' normals, which depend on the camera alone (the surfaces are fixed for a
  // renderer's life; neither the probe, the reference plane nor the shader variant changes a
  // normal's bits), so while the camera stays, a new reduction would give these bits again.
  struct NormalMean {
    bool valid = false;
    Camera camera;
    ReductionResult result;  // normal_sum and normal_coverage
  };
  NormalMean normal_mean_;
  // The view's deformable surfaces' meshes are geometry_'s dynamic ones; uploaded_: the version
  // each upload drew (by scene surface, 0 for the others).
  std::vector<std::uint64_t> uploaded_;
  std::uint64_t mesh_version_ = 0;         // deformed mesh uploads so far (the frame key)
  FrameHistory history_;                   // what the last frame left: incremental frames
  SurfaceScale surface_scale_;             // set_surface_scale
  std::optional<Camera> last_camera_;      // the last frame's: did this frame's view move?
  // The passes reduced frames are drawn by, by size, and the one the last frame was (null: whole).
  std::map<std::pair<int, int>, SurfacePass> reduced_passes_;
  const SurfacePass* last_reduced_ = nullptr;
  ProbeDepthPass probe_depth_;
  SurfacePass surface_;
  ReductionsPass reductions_;
  ProbeViewPass probe_view_;
  bool filter_negligible_ = false;  // the last frame's filter need was negligible: skip it now
  bool filter_lod() const {
    return options_.filter_lod && (options_.expected_frames <= 0 || options_.expected_frames >= kFilterLodMinFrames);
  }
  std::shared_ptr<View> view_;  // the session's (RendererOptions::view)
  Probe probe_;                 // this frame's: the view's, then moved by the displacement
  Status draw();                // the view as it stands (render_frame's work)
  void add_path_point();        // the probe on its sheet, to the world view's path
  WorldView world_view_;  // bodies, markers, the 4D path and the device ghost
};

// Every field of the two cameras equal: the same view matrix and projection.
bool same_camera(const Camera& a, const Camera& b);

// Stats as JSON (the CLI's --stats FILE): backend, renderer, reference_normal, displacement,
// max_penetration, probe_position, timings_ms, skipped, ...
// `egl_device`: gl::Context::egl_device().
std::string stats_json(const FrameStats& stats, const std::string& backend, const std::string& egl_device,
                       const std::string& gl_renderer, int frames);

}  // namespace ps
