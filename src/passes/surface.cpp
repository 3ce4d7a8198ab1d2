#include "passes/surface.h"

#include <algorithm>
#include <bit>
#include <cassert>

#include "gl/shader.h"

namespace ps {

namespace {
glm::vec4 v4(const glm::dvec3& v, double w = 0.0) { return glm::vec4(glm::dvec4(v, w)); }
glm::vec4 v4(double x, double y, double z, double w) { return glm::vec4(glm::dvec4(x, y, z, w)); }
}  // namespace

int next_pow2(int v) { return static_cast<int>(std::bit_ceil(static_cast<unsigned>(std::max(v, 1)))); }

namespace {

// The block's frame-wide part: camera, light, reference plane, depth window, probe heights.
void set_frame(SurfaceBlock& b, const SurfaceFrame& fr) {
  b.view_proj = glm::mat4(fr.view_proj);
  b.light_dir = v4(glm::normalize(fr.light->direction), fr.light->ambient);
  b.light_color = v4(fr.light->color, fr.gamma);
  b.ref_n = v4(fr.plane.n, fr.surface_normal_distance ? 1.0 : 0.0);
  b.ref_t = v4(fr.plane.t, fr.probe_height_lo_mm);
  b.ref_b = v4(fr.plane.b, fr.probe_height_hi_mm);
  b.window = v4(fr.window_center_uv.x, fr.window_center_uv.y, fr.window_half_mm, fr.depth_map_size);
  if (fr.probe_capsule) {
    const CapsuleShape& c = *fr.probe_capsule;
    b.probe_a = v4(to_plane(fr.plane, c.a), c.radius);
    b.probe_b = v4(to_plane(fr.plane, c.b), 1.0);
  }
  if (fr.cast_caster) b.cast_sphere = v4(fr.cast_caster->centre, fr.cast_caster->radius_mm);
  b.feedback = glm::vec4(fr.pseudo_shadow_color ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
}

// The band of w that counts as the probe's sheet is 15 % of the surface's w range: wide enough for
// the sheet's own w change across the shadow window (a few mm), far narrower than the w gap where
// sheets cross. The cutaway and the crossing diagram need the probe and the eye.
void set_sheet(SurfaceBlock& b, const SheetInputs& s) {
  b.sheet = glm::vec4(1.0f, static_cast<float>(s.w), 0.15f * s.w_range, static_cast<float>(s.crossing_diagram_mm));
  if (s.cutaway_mm > 0.0 || s.crossing_diagram_mm > 0.0) {
    const Camera& cam = *s.camera;
    b.cutaway = glm::vec4(glm::vec3(s.probe_mm), static_cast<float>(s.cutaway_mm));
    b.eye = cam.projection == Projection::kPerspective
                ? glm::vec4(glm::vec3(cam.position), 1.0f)
                : glm::vec4(glm::vec3(glm::normalize(cam.target - cam.position)), 0.0f);
  }
}

}  // namespace

SurfaceBlock make_surface_block(const SurfaceFrame& fr, const SurfaceInputs& in) {
  assert(in.material && in.gabor && "make_surface_block: SurfaceInputs needs its material and Gabor block");
  assert(in.bodies.size() <= static_cast<size_t>(kMaxSceneBodies) &&
         "make_surface_block: more body casters than SurfaceBlock::body_spheres holds");
  assert((!in.sheet || in.sheet->camera) && "make_surface_block: SheetInputs needs the camera (the eye)");
  const Material& m = *in.material;
  SurfaceBlock b;
  set_frame(b, fr);
  b.albedo = v4(m.albedo, in.has_albedo_tex ? 1.0 : 0.0);
  b.albedo_scale = v4(m.albedo_texture_scale_mm, m.albedo_texture_offset_mm.x, m.albedo_texture_offset_mm.y, 0.0);
  b.intensity = v4(m.intensity_floor, m.intensity_scale, m.intensity_offset_mm, m.influence_distance_mm);
  b.modulation = v4(in.speed_gain, m.onset_distance_mm, m.resistance, fr.contrast_sigmas);
  b.gabor = *in.gabor;
  const size_t n = std::min(in.bodies.size(), static_cast<size_t>(kMaxSceneBodies));
  for (size_t i = 0; i < n; ++i) b.body_spheres[i] = v4(in.bodies[i].centre, in.bodies[i].radius_mm);
  b.body_count = glm::uvec4(static_cast<unsigned>(n), 0u, 0u, 0u);
  if (in.sheet) set_sheet(b, *in.sheet);
  return b;
}

IntensityLutBlock make_intensity_lut_block(const Lut& lut) {
  assert(lut.points.size() >= 2 && lut.points.size() <= static_cast<std::size_t>(kMaxLutRows) &&
         "make_intensity_lut_block: 2..kMaxLutRows rows (draw without PS_INTENSITY_LUT when empty)");
  IntensityLutBlock b;
  for (std::size_t i = 0; i < lut.points.size(); ++i) {
    glm::vec4& pair = b.rows[i / 2];
    const int at = i % 2 == 0 ? 0 : 2;
    pair[at] = static_cast<float>(lut.points[i].x);
    pair[at + 1] = static_cast<float>(lut.points[i].y);
  }
  b.count = glm::uvec4(static_cast<unsigned>(lut.points.size()), 0u, 0u, 0u);
  return b;
}

gl::Buffer make_intensity_lut_buffer(const Lut& lut) {
  const IntensityLutBlock block = make_intensity_lut_block(lut);
  return gl::make_buffer(sizeof block, &block, 0);
}

Status SurfacePass::init(const std::string& glsl_root, const Params& params) {
  glsl_root_ = glsl_root;
  params_ = params;
  if (Status s = make_targets(); !s) return s;
  auto warm = program(SurfaceFlag::kShadow | SurfaceFlag::kTextured);  // compile the common variant up front: errors surface early
  if (!warm) return warm.error();
  return ok_status();
}

Status SurfacePass::make_targets() {
  padded_ = {next_pow2(params_.width), next_pow2(params_.height)};
  color_ = gl::make_texture_2d(padded_.x, padded_.y, GL_RGBA8);
  normal_ = gl::make_texture_2d(padded_.x, padded_.y, GL_RGBA32F);
  aov_ = gl::make_texture_2d(padded_.x, padded_.y, GL_RGBA32F);
  filter_need_ = gl::make_texture_2d(padded_.x, padded_.y, GL_R32F);
  for (const gl::Texture* t : {&color_, &normal_, &aov_, &filter_need_}) {
    glTextureParameteri(t->id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t->id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  dummy_ = gl::make_texture_2d(1, 1, GL_R32F);  // bound when a sampler has nothing to read
  depth_ = gl::make_renderbuffer(GL_DEPTH_COMPONENT32F, padded_.x, padded_.y);
  fbo_ = gl::make_framebuffer();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, normal_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT2, aov_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT3, filter_need_.id(), 0);
  glNamedFramebufferRenderbuffer(fbo_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  const GLenum buffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
  glNamedFramebufferDrawBuffers(fbo_.id(), 4, buffers);
  if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return make_error("surface pass: MRT framebuffer incomplete (RGBA8 + 2x RGBA32F + R32F + D32F)");
  GLint align = 256;
  glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
  ubo_stride_ = static_cast<GLint>((sizeof(SurfaceBlock) + align - 1) / align * align);
  ubo_capacity_ = 1;
  ubo_ = gl::make_buffer(ubo_stride_, nullptr, GL_DYNAMIC_STORAGE_BIT);
  return ok_status();
}

Result<const gl::Program*> SurfacePass::program(SurfaceFlags variant) {
  auto it = programs_->find(variant);
  if (it != programs_->end()) return &it->second;
  auto built = gl::build_program({{"surface.vert", "surface.frag"}, defines_for(variant)}, glsl_root_);
  if (!built) return built.error();
  return &programs_->emplace(variant, std::move(built.value())).first->second;
}

Status SurfacePass::warm(SurfaceFlags variant) {
  auto prog = program(variant);
  return prog ? ok_status() : Status(prog.error());
}

SurfaceFlags SurfacePass::variant_of(const SurfaceDraw& d, bool shadow) {
  return surface_variant({shadow && d.shadow, d.textured, d.stratified,
                          d.gabor_tile ? (d.gabor_tile_linear ? 2 : 1) : 0,
                          d.gabor_filter_skipped && d.gabor_filter ? 2 : d.gabor_filter ? 1 : 0,
                          d.intensity_lut != nullptr});
}

Status SurfacePass::run(const std::vector<SurfaceDraw>& draws, const gl::Texture* probe_depth,
                        const glm::dvec3& background, const PixelRect& shadow_rect) {
  return run(draws, probe_depth, background, shadow_rect, PixelRect::whole(params_.width, params_.height));
}

Status SurfacePass::run(const std::vector<SurfaceDraw>& draws, const gl::Texture* probe_depth,
                        const glm::dvec3& background, const PixelRect& shadow_rect, const PixelRect& redraw) {
  const PixelRect image = PixelRect::whole(params_.width, params_.height);
  shadow_rect_ = shadow_rect.clipped_to(image);
  const PixelRect area = redraw.clipped_to(image);
  assert(shadow_rect_.clipped_to(area) == shadow_rect_ &&
         "SurfacePass::run: the redrawn area must hold the shadow rectangle (FrameHistory::redraw)");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, params_.width, params_.height);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);  // surfaces may be open or seen from behind (two-sided shading)
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  // The draw buffers stay as init() set them: a change would make llvmpipe rasterise what is
  // queued so far (a flush). The AOV is switched off by its colour mask instead.
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  clear(background, area == image ? nullptr : &area);

  // Every block once, before any draw: updating one block between draws would make llvmpipe
  // finish the queued draws first.
  if (static_cast<int>(draws.size()) > ubo_capacity_) {
    ubo_capacity_ = static_cast<int>(draws.size());
    ubo_ = gl::make_buffer(static_cast<GLsizeiptr>(ubo_capacity_) * ubo_stride_, nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  for (size_t i = 0; i < draws.size(); ++i)
    glNamedBufferSubData(ubo_.id(), static_cast<GLintptr>(i) * ubo_stride_, sizeof(SurfaceBlock), &draws[i].block);
  glBindTextureUnit(0, probe_depth ? probe_depth->id() : dummy_.id());
  glEnable(GL_SCISSOR_TEST);
  const Status s = draw_regions(draws, area);
  glColorMaski(2, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glColorMaski(3, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_SCISSOR_TEST);
  return s;
}

Status SurfacePass::init_sharing(const SurfacePass& programs_from, const Params& params) {
  glsl_root_ = programs_from.glsl_root_;
  params_ = params;
  programs_ = programs_from.programs_;
  return make_targets();
}

// Into the colour attachment alone (with all four draw buffers a blit writes each of them; the
// switch makes llvmpipe flush, in reduced frames only); the depth in a blit of its own, as GL
// allows it the nearest sample only.
void SurfacePass::take_upsampled(const SurfacePass& small, bool depth) {
  const GLint sw = small.params_.width, sh = small.params_.height, w = params_.width, h = params_.height;
  glDisable(GL_SCISSOR_TEST);  // a blit is clipped by the scissor box
  glNamedFramebufferReadBuffer(small.fbo_.id(), GL_COLOR_ATTACHMENT0);
  glNamedFramebufferDrawBuffer(fbo_.id(), GL_COLOR_ATTACHMENT0);
  glBlitNamedFramebuffer(small.fbo_.id(), fbo_.id(), 0, 0, sw, sh, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  if (depth)
    glBlitNamedFramebuffer(small.fbo_.id(), fbo_.id(), 0, 0, sw, sh, 0, 0, w, h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  const GLenum buffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
  glNamedFramebufferDrawBuffers(fbo_.id(), 4, buffers);
}

// Colour (background), normal and depth: the whole padded targets for a full frame (`area`
// null), else only `area` (an incremental frame keeps the rest).
void SurfacePass::clear(const glm::dvec3& background, const PixelRect* area) {
  const glm::vec4 bg(glm::dvec4(background, 1.0));
  const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
  if (area) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(area->x0, area->y0, area->width(), area->height());
  } else {
    glDisable(GL_SCISSOR_TEST);
  }
  if (area && area->empty()) return;  // nothing redrawn this frame
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, &bg.x);
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 1, zero);
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
}

// The footprint's rectangle with its own variants, the AOV cleared and written there only; then
// the rest of `area` in bands around it (all of it when the rectangle is empty): plain shading,
// no AOV, no filter need.
Status SurfacePass::draw_regions(const std::vector<SurfaceDraw>& draws, const PixelRect& area) {
  const float zero[4] = {0, 0, 0, 0}, aov_clear[4] = {0, kNoProbeDistance, 0, 0};
  if (!shadow_rect_.empty()) {
    glScissor(shadow_rect_.x0, shadow_rect_.y0, shadow_rect_.width(), shadow_rect_.height());
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 2, aov_clear);
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 3, zero);
    if (Status s = draw_all(draws, true); !s) return s;
  }
  glColorMaski(2, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glColorMaski(3, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  const PixelRect image = PixelRect::whole(params_.width, params_.height);
  const PixelRect& r = shadow_rect_;
  const PixelRect bands[4] = {{0, 0, image.x1, r.empty() ? image.y1 : r.y0},
                              {0, r.y1, image.x1, image.y1},
                              {0, r.y0, r.x0, r.y1},
                              {r.x1, r.y0, image.x1, r.y1}};
  for (const PixelRect& whole_band : bands) {
    const PixelRect band = whole_band.clipped_to(area);
    if (band.empty()) continue;
    glScissor(band.x0, band.y0, band.width(), band.height());
    if (Status s = draw_all(draws, false); !s) return s;
  }
  return ok_status();
}

Status SurfacePass::draw_all(const std::vector<SurfaceDraw>& draws, bool shadow) {
  for (size_t i = 0; i < draws.size(); ++i) {
    const SurfaceDraw& d = draws[i];
    auto prog = program(variant_of(d, shadow));
    if (!prog) return prog.error();
    glUseProgram(prog.value()->id());
    glBindTextureUnit(1, d.albedo ? d.albedo->id() : dummy_.id());
    glBindTextureUnit(2, d.gabor_tile ? d.gabor_tile->id() : dummy_.id());
    if (d.intensity_lut) glBindBufferBase(GL_UNIFORM_BUFFER, 1, d.intensity_lut->id());
    glBindBufferRange(GL_UNIFORM_BUFFER, 0, ubo_.id(), static_cast<GLintptr>(i) * ubo_stride_, sizeof(SurfaceBlock));
    if (d.wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    d.mesh->draw();
    if (d.wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
  return ok_status();
}

}  // namespace ps
