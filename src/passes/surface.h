// Surface pass (thesis Table 4.2 step 3): draws every surface once into an MRT framebuffer.
// Variants by name (passes/surface_variant.h): one SurfaceFlags set per program.
//   inputs : surfaces (GpuMesh + material uniforms), probe depth map (R32F), albedo textures,
//            up to kMaxSceneBodies sphere casters per surface (their analytic pseudo-shadows
//            darken the colour target only)
//   outputs: color()  RGBA8    lit surface with the pseudo-shadow (gamma-encoded)
//            normal() RGBA32F  (front-facing normal, 1) per covered pixel (summed by rows for
//                              the mean visible normal: ReductionsPass::mean_normal)
//            aov()    RGBA32F  (intensity, distance d mm, texture in sigmas, resistance),
//                              written inside shadow_rect() only (cleared there to
//                              (0, NaN, 0, 0)); outside it the texture holds stale values and
//                              the AOV is (0, NaN, 0, 0) by definition: d is NaN wherever no
//                              probe is above the pixel (kNoProbeDistance)
//   All targets are allocated at the next power of two of the image size (they were reduced by
//   mipmaps, exact means only for power-of-two RGBA32F on llvmpipe, docs/gl-stack.md); the
//   viewport covers the image and the padding stays cleared.
// Shaders: glsl/surface.{vert,frag}; the PS_INTENSITY_LUT variant reads the material's
// intensity_lut in IntensityLutBlock (uniform binding 1, make_intensity_lut_buffer).
#pragma once

#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "gl/objects.h"
#include "passes/gabor_block.h"
#include "passes/gpu_mesh.h"
#include "passes/pixel_rect.h"
#include "passes/surface_variant.h"
#include "reference/basis.h"
#include "reference/body_shadow.h"
#include "reference/gabor.h"
#include "reference/probe_geometry.h"
#include "scene/scene.h"

namespace ps {

// std140 mirror of glsl/lib/surface_block.glsl.
struct SurfaceBlock {
  glm::mat4 view_proj{1.0f};
  glm::vec4 light_dir, light_color, ref_n, ref_t, ref_b, window, albedo, albedo_scale, intensity;
  glm::vec4 modulation;
  GaborBlock gabor;
  glm::vec4 body_spheres[kMaxSceneBodies]{};  // bodies casting on this surface: centre, radius (mm)
  glm::uvec4 body_count{0u};                  // x: how many body_spheres are set
  // x: 1 = the pseudo-shadow falls on one sheet of a surface embedded in 4D only (fourd: the
  // probe's sheet); y: that sheet's w; z: half-width of the band of w that counts as it.
  glm::vec4 sheet{0.0f};
  // Cutaway of the other sheets between the eye and the probe (Hanson & Zhang §6.3): xyz the
  // probe's centre, w the radius (0: off); eye: xyz the camera position (perspective, w = 1) or its
  // view direction (orthographic, w = 0).
  glm::vec4 cutaway{0.0f};
  // The sphere/capsule probe in plane coordinates (u, v, height along ref_n) mm: end a with the
  // radius in w; end b with w = 1 when surface_normal distances are taken in closed form against
  // it (0: marched through the probe depth map, a mesh probe).
  glm::vec4 probe_a{0.0f}, probe_b{0.0f};
  glm::vec4 eye{0.0f};
  // The feedback keys of [render]: the probe's cast shadow, its bounding sphere (world centre mm,
  // radius mm in w; w = 0: none), and x = 1 where the pseudo-shadow is composited into the colour.
  glm::vec4 cast_sphere{0.0f};
  glm::vec4 feedback{1.0f, 0.0f, 0.0f, 0.0f};
};
static_assert(sizeof(SurfaceBlock) == 64 + 10 * 16 + sizeof(GaborBlock) + (kMaxSceneBodies + 8) * 16,
              "SurfaceBlock must match std140 layout");

// The distance AOV's value (aov().y) wherever no probe is above the pixel: outside the probe's
// footprint, on surfaces beyond their influence distance, on the background. NaN, not a huge
// number, so image statistics (oiiotool --stats) count those pixels apart instead of averaging
// them in; test with std::isnan. Never reaches the colour target.
inline constexpr float kNoProbeDistance = std::numeric_limits<float>::quiet_NaN();

// Per-frame values shared by every surface draw.
struct SurfaceFrame {
  glm::dmat4 view_proj{1.0};
  PlaneFrame plane;
  glm::dvec2 window_center_uv{0.0};
  double window_half_mm = 1.0;
  int depth_map_size = 256;
  const Light* light = nullptr;
  double gamma = 1.0 / 2.2;
  double contrast_sigmas = 2.5;  // texture shown as 0.5 +- 0.5 * value / contrast_sigmas
  bool surface_normal_distance = false;  // ShadowDistance::kSurfaceNormal
  // The probe's heights along the reference normal lie within [lo, hi] (its bounding sphere):
  // where a surface_normal ray may start and by when it must have met the probe.
  double probe_height_lo_mm = 0.0, probe_height_hi_mm = 0.0;
  // A sphere/capsule probe (world mm): surface_normal distances in closed form against it
  // (capsule_column_distance); unset for a mesh probe, whose distances are marched through the
  // depth map.
  std::optional<CapsuleShape> probe_capsule;
  // render.pseudo_shadow: false keeps the pseudo-shadow out of the colour only (AOVs unchanged).
  bool pseudo_shadow_color = true;
  // render.cast_shadow: the probe's bounding sphere casting an ordinary shadow along the light.
  std::optional<SphereCaster> cast_caster;
};

// A surface embedded in 4D (docs/fourd.md) shows the pseudo-shadow on the probe's sheet only:
// SurfaceBlock::sheet, cutaway and eye.
struct SheetInputs {
  double w = 0.0;                  // the probe's sheet
  float w_range = 0.0f;            // the surface's (max - min w); the sheet's band is 15 % of it
  double crossing_diagram_mm = 0.0;
  double cutaway_mm = 0.0;         // fourd::Spec's; both 0: no cutaway, no eye
  glm::dvec3 probe_mm{0.0};        // the cutaway's centre
  const Camera* camera = nullptr;  // the eye (its position, or its view direction if orthographic)
};

// What one surface's block is made from besides the frame. `gabor`: the material's texture as
// make_gabor_block() packed it (with its baked tile, if any). `bodies`: the bodies whose
// pseudo-shadow may fall on this surface (at most kMaxSceneBodies; lib/body_shadow.glsl).
struct SurfaceInputs {
  const Material* material = nullptr;
  const GaborBlock* gabor = nullptr;
  double speed_gain = 0.0;
  bool has_albedo_tex = false;
  std::span<const SphereCaster> bodies;
  std::optional<SheetInputs> sheet;  // a surface embedded in 4D
};

SurfaceBlock make_surface_block(const SurfaceFrame& frame, const SurfaceInputs& in);

struct SurfaceDraw {
  const GpuMesh* mesh = nullptr;
  SurfaceBlock block;
  bool shadow = true;    // PS_SHADOW variant
  bool textured = true;  // PS_TEXTURED variant
  bool stratified = false;  // PS_GABOR_STRATIFIED variant (GaborParams::Strategy::kStratified)
  const gl::Texture* albedo = nullptr;
  const gl::Texture* gabor_tile = nullptr;  // set: PS_GABOR_BAKED variant reads this tile
  bool gabor_tile_linear = false;           // the tile is values only, read bilinearly (PS_GABOR_BAKED 2)
  bool gabor_filter = false;                // PS_GABOR_FILTER variant (GaborParams::Filter::kAnalytic)
  bool gabor_filter_skipped = false;        // with gabor_filter: PS_GABOR_FILTER 2, the filter skipped
                                            // (negligible this frame), its need still measured
  bool wireframe = false;                   // the triangles' edges only (glPolygonMode GL_LINE)
  const gl::Buffer* intensity_lut = nullptr;  // set: PS_INTENSITY_LUT variant reads this table
};

// std140 mirror of IntensityLutBlock in glsl/lib/intensity_lut.glsl: a distance -> intensity
// table's rows (scene/lut.h), two per vec4 (row 2k in xy, row 2k + 1 in zw), and their count.
struct IntensityLutBlock {
  glm::vec4 rows[kMaxLutRows / 2]{};
  glm::uvec4 count{0u};
};
static_assert(sizeof(IntensityLutBlock) == (kMaxLutRows / 2 + 1) * 16, "IntensityLutBlock must match std140 layout");

IntensityLutBlock make_intensity_lut_block(const Lut& lut);
// The block in a uniform buffer, made once per material (bound at binding 1 by its draws).
gl::Buffer make_intensity_lut_buffer(const Lut& lut);

struct SurfacePass {
  struct Params {
    int width = 512, height = 512;
  };

  Status init(const std::string& glsl_root, const Params& params);
  // `shadow_rect` (FramePlan::shadow_rect): the pixels that can show the pseudo-shadow. Only
  // there do shadowed draws run their PS_SHADOW variant and is the AOV target written; every
  // other pixel gets the PS_SHADOW=0 variant, whose colour and normal are the same bytes where
  // the footprint is absent (intensity 0 composites as rgb * 1).
  Status run(const std::vector<SurfaceDraw>& draws, const gl::Texture* probe_depth,
             const glm::dvec3& background, const PixelRect& shadow_rect);
  // An incremental frame (render/frame_key.h): only `redraw` (which holds shadow_rect) is
  // cleared and drawn; every other pixel of the colour, normal and depth targets keeps the last
  // run()'s value. The whole image: the same as the overload above.
  Status run(const std::vector<SurfaceDraw>& draws, const gl::Texture* probe_depth,
             const glm::dvec3& background, const PixelRect& shadow_rect, const PixelRect& redraw);
  // A reduced frame (adaptive resolution while the view moves, docs/adaptive.md) is drawn by a
  // second, smaller pass over the same view: init_sharing() makes one that builds no program
  // of its own (it uses `programs_from`'s, built once for both), and take_upsampled() puts its
  // image into this pass's whole image: the colour bilinearly, the depth (with `depth`: what the
  // overlays are depth-tested against) by the nearest sample. The normal and AOV targets are
  // left as they were: the caller redraws what the reductions read with run().
  Status init_sharing(const SurfacePass& programs_from, const Params& params);
  void take_upsampled(const SurfacePass& small, bool depth);
  // Builds a variant now, not at its first draw: a variant a live session switches to later (the
  // filter's level of detail) is built ahead instead of stalling that frame.
  Status warm(SurfaceFlags variant);
  // The variant that draws `d` (inside the shadow rectangle when `shadow`).
  static SurfaceFlags variant_of(const SurfaceDraw& d, bool shadow);
  // The last run()'s shadow_rect, clipped to the image: where aov() is valid.
  const PixelRect& shadow_rect() const { return shadow_rect_; }

  const gl::Texture& color() const { return color_; }
  const gl::Texture& normal() const { return normal_; }
  const gl::Texture& aov() const { return aov_; }
  // R32F: gabor_filter_need where a filtered material's texture was evaluated, 0 elsewhere in
  // shadow_rect() (undefined outside it).
  const gl::Texture& filter_need() const { return filter_need_; }
  const gl::Renderbuffer& depth_buffer() const { return depth_; }  // D32F, the surfaces' depth
  int width() const { return params_.width; }
  int height() const { return params_.height; }
  glm::ivec2 padded_size() const { return padded_; }

 private:
  Result<const gl::Program*> program(SurfaceFlags variant);  // built on first use, then cached

  std::string glsl_root_;
  Params params_;
  glm::ivec2 padded_{1, 1};
  // Draws every surface (inside the caller's scissor box); shadow == false draws all of them
  // with their PS_SHADOW=0 variant.
  Status draw_all(const std::vector<SurfaceDraw>& draws, bool shadow);
  void clear(const glm::dvec3& background, const PixelRect* area);
  Status draw_regions(const std::vector<SurfaceDraw>& draws, const PixelRect& area);

  // Shared with the passes init_sharing() made from this one (one context, one build each).
  std::shared_ptr<std::map<SurfaceFlags, gl::Program>> programs_ = std::make_shared<std::map<SurfaceFlags, gl::Program>>();
  Status make_targets();
  gl::Texture color_, normal_, aov_, filter_need_, dummy_;
  gl::Renderbuffer depth_;
  gl::Framebuffer fbo_;
  gl::Buffer ubo_;        // one SurfaceBlock per draw, ubo_stride_ bytes apart
  int ubo_capacity_ = 0;   // blocks
  GLint ubo_stride_ = 0;
  PixelRect shadow_rect_;
};

int next_pow2(int v);

}  // namespace ps
