#include "world/deformable_surfaces.h"

#include <algorithm>
#include <cmath>

namespace ps::world {

const Mesh& DeformableSurfaces::add(int surface, const Mesh& rest, const DeformParams& params) {
  Record r;
  r.surface = surface;
  r.mesh = subdivide(rest, params.max_edge_mm);
  r.sim = std::make_shared<Deformable>(r.mesh, params);
  surfaces_.push_back(std::move(r));
  stats_.surfaces = static_cast<int>(surfaces_.size());
  return surfaces_.back().mesh;
}

const DeformationStats& DeformableSurfaces::advance(double time_s, const Probe& probe) {
  if (surfaces_.empty() || !std::isfinite(time_s)) return stats_;
  const double dt = time_s_ < 0.0 ? 0.0 : time_s - time_s_;
  time_s_ = time_s;
  return dt > 0.0 ? step(dt, probe) : stats_;
}

const DeformationStats& DeformableSurfaces::step(double dt_s, const Probe& probe) {
  DeformationStats st;
  st.surfaces = static_cast<int>(surfaces_.size());
  const glm::dvec3 centre = probe.shape == ProbeShape::kMesh ? glm::dvec3(std::nan("")) : probe.position;
  for (Record& r : surfaces_) {
    const DeformStep step = r.sim->step(dt_s, centre, probe.radius_mm);
    // At rest with the probe away the step simulates no vertex (none displaced, none near the
    // probe), so nothing changed since the last write: no re-upload, no new normals.
    if (r.sim->active_count() > 0) {
      r.sim->write(r.mesh);
      ++r.version;
      ++st.uploaded;
    }
    st.substeps = std::max(st.substeps, step.substeps);
    st.constrained += step.constrained;
    st.max_displacement_mm = std::max(st.max_displacement_mm, step.max_displacement_mm);
    st.finite = st.finite && r.sim->finite();
  }
  stats_ = st;
  return stats_;
}

std::vector<DeformableSurfaces::Drawn> DeformableSurfaces::drawn() const {
  std::vector<Drawn> out;
  for (const Record& r : surfaces_) out.push_back({r.surface, &r.mesh, r.version});
  return out;
}

const Mesh* DeformableSurfaces::mesh(int surface) const {
  for (const Record& r : surfaces_)
    if (r.surface == surface) return &r.mesh;
  return nullptr;
}

std::vector<glm::dvec3> DeformableSurfaces::positions(int surface) const {
  for (const Record& r : surfaces_)
    if (r.surface == surface) return r.sim->positions();
  return {};
}

Result<std::shared_ptr<DeformableSurfaces>> settled_deformables(const Scene& scene) {
  std::shared_ptr<DeformableSurfaces> out;
  for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
    const Surface& s = scene.surfaces[i];
    if (!s.deform.enabled) continue;
    Result<Mesh> rest = build_drawn_surface_mesh(s);
    if (!rest) return rest.error();
    if (!out) out = std::make_shared<DeformableSurfaces>();
    out->add(static_cast<int>(i), rest.value(), s.deform);
  }
  if (out)
    for (int i = 0; i < 10; ++i) out->step(0.1, scene.probe);
  return out;
}

}  // namespace ps::world
