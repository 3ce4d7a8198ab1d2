#include "prepare/field_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "core/hash.h"
#include "prepare/picture_cache.h"
#include "world/fields.h"

namespace ps {

namespace {

// The square the map covers (world X/Y) and the height it is evaluated at.
struct MapFrame {
  glm::dvec2 corner{0.0};
  double side = 1.0, z = 0.0;
};

MapFrame frame_of(const Scene& scene, const Surface& s) {
  const glm::dvec2 extent = s.type == SurfaceType::kBox ? glm::dvec2(s.box_size_mm) : s.size_mm;
  const double top = s.center.z + (s.type == SurfaceType::kBox ? 0.5 * s.box_size_mm.z : 0.0);
  MapFrame f;
  f.side = std::max(extent.x, extent.y);
  f.corner = glm::dvec2(s.center) - 0.5 * glm::dvec2(f.side);
  // At the charges' mean height (where their pulls can cancel), not below the resting probe.
  double z = 0.0;
  int charges = 0;
  for (const Field& c : scene.fields)
    if (c.type == FieldType::kCharge) {
      z += c.position.z;
      ++charges;
    }
  f.z = std::max(top + scene.probe.radius_mm, charges > 0 ? z / charges : 0.0);
  return f;
}

// Dark blue -> magenta -> yellow, t in [0, 1].
glm::dvec3 colour(double t) {
  t = std::clamp(t, 0.0, 1.0);
  const glm::dvec3 a(0.05, 0.05, 0.35), b(0.75, 0.2, 0.55), c(1.0, 0.9, 0.25);
  return t < 0.5 ? glm::mix(a, b, 2.0 * t) : glm::mix(b, c, 2.0 * t - 1.0);
}

}  // namespace

Image field_map_image(const Scene& scene, const Surface& s) {
  const MapFrame f = frame_of(scene, s);
  const int n = kFieldMapSize;
  std::vector<double> mag(static_cast<std::size_t>(n) * n, 0.0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const glm::dvec3 p(f.corner.x + (x + 0.5) * f.side / n, f.corner.y + (y + 0.5) * f.side / n, f.z);
      glm::dvec3 force(0.0);
      for (const Field& c : scene.fields)
        if (c.type == FieldType::kCharge)
          force += world::FieldSet::charge_force_n(p, c.position, c.charge_n_mm2, c.softening_mm);
      mag[static_cast<std::size_t>(y) * n + x] = std::log10(glm::length(force) + 1e-6);
    }
  std::vector<double> sorted = mag;
  std::sort(sorted.begin(), sorted.end());
  const double lo = sorted[sorted.size() / 50], hi = sorted[sorted.size() - 1 - sorted.size() / 50];
  Image im;
  im.width = im.height = n;
  im.channels = 3;
  im.pixels.resize(static_cast<std::size_t>(n) * n * 3);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double v = mag[static_cast<std::size_t>(y) * n + x];
      const glm::dvec3 c = colour(hi > lo ? (v - lo) / (hi - lo) : 0.0);
      for (int k = 0; k < 3; ++k) im.at(x, n - 1 - y, k) = static_cast<float>(c[k]);  // top row = largest y
    }
  return im;
}

Status make_field_maps(Scene& scene) {
  for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
    const Surface& s = scene.surfaces[i];
    if (!s.field_map || s.field_map_material < 0) continue;
    // Named by everything the map depends on: the charges, the frame, the size.
    const MapFrame f = frame_of(scene, s);
    std::uint64_t h = kFnv1aOffset;
    const double head[5] = {f.corner.x, f.corner.y, f.side, f.z, static_cast<double>(kFieldMapSize)};
    h = fnv1a(head, sizeof head, h);
    for (const Field& c : scene.fields)
      if (c.type == FieldType::kCharge) {
        const double q[5] = {c.position.x, c.position.y, c.position.z, c.charge_n_mm2, c.softening_mm};
        h = fnv1a(q, sizeof q, h);
      }
    char name[48];
    std::snprintf(name, sizeof name, "/field_%016llx.png", static_cast<unsigned long long>(h));
    const std::string path = picture_cache_dir() + name;
    auto cached = read_image(path);
    if (!cached || cached->width != kFieldMapSize || cached->height != kFieldMapSize) {
      if (Status st = write_image(path, field_map_image(scene, s)); !st)
        return make_error(scene.path + ":" + std::to_string(s.line) + ": field map: " + st.error().message);
    }
    Material& m = scene.materials[static_cast<std::size_t>(s.field_map_material)];
    m.albedo_texture = path;
    m.albedo_texture_scale_mm = f.side;
    m.albedo_texture_offset_mm = f.corner;
  }
  return ok_status();
}

}  // namespace ps
