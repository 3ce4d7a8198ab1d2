#include "render/frame_key.h"

#include <cstring>
#include <type_traits>

namespace ps {

namespace {

struct KeyWriter {
  std::vector<std::byte>& out;
  template <typename T>
  void add(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>, "KeyWriter::add: plain values only");
    const auto* p = reinterpret_cast<const std::byte*>(&v);
    out.insert(out.end(), p, p + sizeof(T));
  }
};

// The SurfaceBlock members the PS_SHADOW=0 variant reads (glsl/surface.{vert,frag},
// lib/body_shadow.glsl): everything outside `#if PS_SHADOW`. Members are added one by one, so
// padding never enters the key.
void add_plain_block(KeyWriter& w, const SurfaceBlock& b) {
  w.add(b.view_proj);
  w.add(b.light_dir);
  w.add(b.light_color);
  w.add(b.ref_n);
  w.add(b.albedo);
  w.add(b.albedo_scale);
  w.add(b.intensity);
  w.add(b.body_spheres);
  w.add(b.body_count);
  w.add(b.sheet);
  w.add(b.cutaway);
  w.add(b.eye);
  // The cast shadow moves with the probe, outside the pseudo-shadow's rectangle: with it on, a
  // moved probe changes the key and the frame is redrawn whole. feedback is read only inside
  // PS_SHADOW, but it is constant per scene; keyed so that no reader has to know that.
  w.add(b.cast_sphere);
  w.add(b.feedback);
}

void add_draw(KeyWriter& w, const SurfaceDraw& d) {
  add_plain_block(w, d.block);
  w.add(SurfacePass::variant_of(d, false));
  for (const void* p : {static_cast<const void*>(d.mesh), static_cast<const void*>(d.albedo),
                        static_cast<const void*>(d.gabor_tile), static_cast<const void*>(d.intensity_lut)})
    w.add(reinterpret_cast<std::uintptr_t>(p));
  w.add(d.wireframe);
}

}  // namespace

FrameKey make_frame_key(const FrameKeyInputs& in) {
  FrameKey key;
  KeyWriter w{key.bytes};
  w.add(in.background);
  w.add(in.width);
  w.add(in.height);
  w.add(in.mesh_version);
  w.add(in.bake_progress);
  w.add(in.draws->size());
  for (const SurfaceDraw& d : *in.draws) add_draw(w, d);
  return key;
}

PixelRect bounding_union(const PixelRect& a, const PixelRect& b) {
  if (a.empty()) return b.empty() ? PixelRect{} : b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

PixelRect FrameHistory::redraw(FrameKey key, const PixelRect& shadow_rect, int width, int height, bool enabled) {
  const PixelRect image = PixelRect::whole(width, height);
  const PixelRect now = shadow_rect.clipped_to(image);
  const bool keep = enabled && valid_ && key == key_;
  const PixelRect out = keep ? bounding_union(shadow_rect_, now) : image;
  valid_ = enabled;
  key_ = std::move(key);
  shadow_rect_ = now;
  return out;
}

}  // namespace ps
