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
  for (Record& r : surfaces_) r.changed = false;
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
    r.changed = r.sim->active_count() > 0;
    if (r.changed) {
      r.sim->write(r.mesh);
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

std::vector<DeformableSurfaces::Changed> DeformableSurfaces::changed() const {
  std::vector<Changed> out;
  for (const Record& r : surfaces_)
    if (r.changed) out.push_back({r.surface, &r.mesh});
  return out;
}

std::vector<glm::dvec3> DeformableSurfaces::positions(int surface) const {
  for (const Record& r : surfaces_)
    if (r.surface == surface) return r.sim->positions();
  return {};
}

}  // namespace ps::world
