#include "world/deformable.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <utility>

namespace ps::world {
namespace {

// SI factors: k [N/mm] * 1e3 = N/m, m [g] * 1e-3 = kg, c [N s/mm] * 1e3 = N s/m. Displacements stay
// in mm: a [mm/s^2] = F [N] / m [kg] * 1e3.
constexpr double kMmPerM = 1e3;
constexpr double kMaxStepS = 0.1;
constexpr double kMaxSubstepS = 1e-3;

bool finite3(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

Deformable::Deformable(const Mesh& rest, const DeformParams& params) : params_(params) {
  // Weld by exact position (float bits of the drawn mesh).
  std::map<std::tuple<float, float, float>, std::uint32_t> index;
  weld_.reserve(rest.positions.size());
  for (const glm::vec3& p : rest.positions) {
    const auto [it, inserted] = index.try_emplace({p.x, p.y, p.z}, static_cast<std::uint32_t>(base_.size()));
    if (inserted) base_.emplace_back(p);
    weld_.push_back(it->second);
  }
  std::vector<std::set<std::uint32_t>> nbrs(base_.size());
  triangles_.reserve(rest.indices.size());
  for (std::size_t t = 0; t + 2 < rest.indices.size(); t += 3) {
    const std::uint32_t a = weld_[rest.indices[t]], b = weld_[rest.indices[t + 1]], c = weld_[rest.indices[t + 2]];
    triangles_.insert(triangles_.end(), {a, b, c});
    for (auto [i, j] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
      if (i == j) continue;
      nbrs[i].insert(j);
      nbrs[j].insert(i);
    }
  }
  nbr_begin_.reserve(base_.size() + 1);
  std::size_t deg_max = 0;
  for (const auto& n : nbrs) {
    nbr_begin_.push_back(static_cast<std::uint32_t>(nbr_.size()));
    nbr_.insert(nbr_.end(), n.begin(), n.end());
    deg_max = std::max(deg_max, n.size());
  }
  nbr_begin_.push_back(static_cast<std::uint32_t>(nbr_.size()));
  x_ = base_;
  v_.assign(base_.size(), glm::dvec3(0.0));
  force_.assign(base_.size(), glm::dvec3(0.0));
  // The web's stiffest mode: k_b + k_n * (largest Laplacian eigenvalue <= 2 deg_max). Damping is
  // integrated implicitly, so only the springs bound the step; 0.5 / omega leaves a wide margin
  // below the symplectic Euler limit of 2 / omega.
  const double k = (params_.base_n_per_mm + 2.0 * static_cast<double>(deg_max) * params_.neighbour_n_per_mm) * kMmPerM;
  const double omega = std::sqrt(k / (params_.mass_g * 1e-3));
  substep_s_ = std::min(kMaxSubstepS, 0.5 / omega);
}

void Deformable::reset() {
  x_ = base_;
  std::fill(v_.begin(), v_.end(), glm::dvec3(0.0));
}

DeformStep Deformable::step(double dt_s, const glm::dvec3& centre_mm, double radius_mm) {
  DeformStep out;
  if (!(dt_s > 0.0)) return out;
  dt_s = std::min(dt_s, kMaxStepS);
  out.substeps = static_cast<int>(std::ceil(dt_s / substep_s_ - 1e-9));
  const double h = dt_s / out.substeps;
  const double m = params_.mass_g * 1e-3;                          // kg
  const double kb = params_.base_n_per_mm, kn = params_.neighbour_n_per_mm;  // N/mm
  const double c = params_.damping_n_s_per_mm * kMmPerM;           // N s/m
  const double damp = 1.0 / (1.0 + h * c / m);                     // implicit damping factor
  const bool probe = finite3(centre_mm) && std::isfinite(radius_mm) && radius_mm > 0.0;
  const double max_mm = params_.max_mm;
  const std::size_t n = base_.size();
  for (int s = 0; s < out.substeps; ++s) {
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3 ui = x_[i] - base_[i];
      glm::dvec3 f = -kb * ui;
      for (std::uint32_t e = nbr_begin_[i]; e < nbr_begin_[i + 1]; ++e) {
        const std::uint32_t j = nbr_[e];
        f += kn * ((x_[j] - base_[j]) - ui);
      }
      force_[i] = f;  // N (N/mm * mm)
    }
    out.constrained = 0;
    for (std::size_t i = 0; i < n; ++i) {
      v_[i] = (v_[i] + h * force_[i] / m * kMmPerM) * damp;  // mm/s
      x_[i] += h * v_[i];
      if (probe) {
        const glm::dvec3 d = x_[i] - centre_mm;
        const double len = glm::length(d);
        if (len < radius_mm) {
          // Onto the probe's surface, along the line from its centre (the probe pushes straight
          // out of itself); at the very centre, back toward the base point.
          const glm::dvec3 dir = len > 1e-9 ? d / len : glm::normalize(base_[i] - centre_mm + glm::dvec3(0.0, 0.0, 1e-9));
          x_[i] = centre_mm + radius_mm * dir;
          const double into = glm::dot(v_[i], dir);
          if (into < 0.0) v_[i] -= into * dir;
          ++out.constrained;
        }
      }
      const glm::dvec3 u = x_[i] - base_[i];
      const double ul = glm::length(u);
      if (ul > max_mm) {
        x_[i] = base_[i] + u * (max_mm / ul);
        v_[i] = glm::dvec3(0.0);
      }
    }
  }
  out.max_displacement_mm = max_displacement_mm();
  return out;
}

void Deformable::write(Mesh& mesh) const {
  std::vector<glm::dvec3> normals(base_.size(), glm::dvec3(0.0));
  for (std::size_t t = 0; t + 2 < triangles_.size(); t += 3) {
    const glm::dvec3 &a = x_[triangles_[t]], &b = x_[triangles_[t + 1]], &c = x_[triangles_[t + 2]];
    const glm::dvec3 area2 = glm::cross(b - a, c - a);  // length = twice the area: area-weighted
    for (int k = 0; k < 3; ++k) normals[triangles_[t + k]] += area2;
  }
  for (std::size_t i = 0; i < mesh.positions.size() && i < weld_.size(); ++i) {
    const std::uint32_t w = weld_[i];
    mesh.positions[i] = glm::vec3(x_[w]);
    const double len = glm::length(normals[w]);
    if (i < mesh.normals.size() && len > 0.0) mesh.normals[i] = glm::vec3(normals[w] / len);
  }
}

double Deformable::max_displacement_mm() const {
  double m = 0.0;
  for (std::size_t i = 0; i < x_.size(); ++i) m = std::max(m, glm::length(x_[i] - base_[i]));
  return m;
}

bool Deformable::finite() const {
  return std::all_of(x_.begin(), x_.end(), finite3) && std::all_of(v_.begin(), v_.end(), finite3);
}

glm::dvec3 pressed_position(const Scene& scene, int contact_surface, const glm::dvec3& proxy_mm,
                            const glm::dvec3& device_mm, double coupling_n_per_mm) {
  if (contact_surface < 0 || static_cast<std::size_t>(contact_surface) >= scene.surfaces.size()) return proxy_mm;
  const Surface& s = scene.surfaces[static_cast<std::size_t>(contact_surface)];
  if (!s.deform.enabled || !finite3(device_mm)) return proxy_mm;
  const double k = scene.materials[static_cast<std::size_t>(s.material_index)].haptic.stiffness_n_per_mm;
  const double share = coupling_n_per_mm / (coupling_n_per_mm + std::max(k, 0.0));
  const glm::dvec3 in = (device_mm - proxy_mm) * share;
  const double limit = std::min(s.deform.max_mm, 0.5 * scene.probe.radius_mm);
  const double len = glm::length(in);
  return len > limit ? proxy_mm + in * (limit / len) : proxy_mm + in;
}

}  // namespace ps::world
