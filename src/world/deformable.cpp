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

// Built in order from each other's results, once: weld, adjacency, rest state, stable substep.
Deformable::Deformable(const Mesh& rest, const DeformParams& params) : params_(params) {
  weld(rest);
  const std::size_t deg_max = build_adjacency(rest);
  x_ = base_;
  v_.assign(base_.size(), glm::dvec3(0.0));
  force_.assign(base_.size(), glm::dvec3(0.0));
  is_active_.assign(base_.size(), 0);
  rest_normal_ = rest.normals;
  rest_area_normal_ = area_normals();
  double edges = 0.0;
  for (std::size_t i = 0; i < base_.size(); ++i)
    for (std::uint32_t e = nbr_begin_[i]; e < nbr_begin_[i + 1]; ++e) edges += glm::length(base_[nbr_[e]] - base_[i]);
  mean_edge_mm_ = nbr_.empty() ? 1.0 : edges / static_cast<double>(nbr_.size());
  // The web's stiffest mode: k_b + k_n * (largest Laplacian eigenvalue <= 2 deg_max). Damping is
  // integrated implicitly, so only the springs bound the step; 0.5 / omega leaves a wide margin
  // below the symplectic Euler limit of 2 / omega.
  const double k = (params_.base_n_per_mm + 2.0 * static_cast<double>(deg_max) * params_.neighbour_n_per_mm) * kMmPerM;
  const double omega = std::sqrt(k / (params_.mass_g * 1e-3));
  substep_s_ = std::min(kMaxSubstepS, 0.5 / omega);
}

void Deformable::weld(const Mesh& rest) {
  // Weld by position on a 1e-4 mm grid: files split vertices at seams and hard edges, and a
  // closed parametric shape's seam (u = 0 and u = 1) repeats its positions only to rounding.
  std::map<std::tuple<long long, long long, long long>, std::uint32_t> index;
  weld_.reserve(rest.positions.size());
  for (const glm::vec3& p : rest.positions) {
    const auto q = [](float c) { return std::llround(static_cast<double>(c) * 1e4); };
    const auto [it, inserted] = index.try_emplace({q(p.x), q(p.y), q(p.z)}, static_cast<std::uint32_t>(base_.size()));
    if (inserted) base_.emplace_back(p);
    weld_.push_back(it->second);
  }
}

std::size_t Deformable::build_adjacency(const Mesh& rest) {
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
  return deg_max;
}

void Deformable::reset() {
  x_ = base_;
  std::fill(v_.begin(), v_.end(), glm::dvec3(0.0));
  active_.clear();
}

namespace {
constexpr double kRestMm = 1e-4, kRestMmS = 1e-3;
constexpr int kWindowRings = 3;
}  // namespace

void Deformable::collect_active(const glm::dvec3& centre_mm, double radius_mm, bool probe) {
  std::fill(is_active_.begin(), is_active_.end(), 0);
  active_.clear();
  const double reach = probe ? radius_mm + 2.0 * mean_edge_mm_ : 0.0;
  for (std::size_t i = 0; i < base_.size(); ++i) {
    const bool moved = glm::length(x_[i] - base_[i]) > kRestMm || glm::length(v_[i]) > kRestMmS;
    const bool near = probe && glm::length(x_[i] - centre_mm) < reach;
    if (moved || near) {
      is_active_[i] = 1;
      active_.push_back(static_cast<std::uint32_t>(i));
    }
  }
  std::size_t ring_begin = 0;
  for (int ring = 0; ring < kWindowRings; ++ring) {
    const std::size_t ring_end = active_.size();
    for (std::size_t a = ring_begin; a < ring_end; ++a) {
      const std::uint32_t i = active_[a];
      for (std::uint32_t e = nbr_begin_[i]; e < nbr_begin_[i + 1]; ++e)
        if (!is_active_[nbr_[e]]) {
          is_active_[nbr_[e]] = 1;
          active_.push_back(nbr_[e]);
        }
    }
    ring_begin = ring_end;
  }
}

// The springs' force on every active vertex (N: N/mm * mm), into force_.
void Deformable::accumulate_forces() {
  const double kb = params_.base_n_per_mm, kn = params_.neighbour_n_per_mm;  // N/mm
  for (const std::uint32_t i : active_) {
    const glm::dvec3 ui = x_[i] - base_[i];
    glm::dvec3 f = -kb * ui;
    for (std::uint32_t e = nbr_begin_[i]; e < nbr_begin_[i + 1]; ++e) {
      const std::uint32_t j = nbr_[e];
      f += kn * ((x_[j] - base_[j]) - ui);
    }
    force_[i] = f;
  }
}

// Vertex i held out of the probe sphere (kContactOverlapMm inside its surface); true if it was inside.
bool Deformable::hold_out_of_probe(std::uint32_t i, const glm::dvec3& centre_mm, double radius_mm) {
  const glm::dvec3 d = x_[i] - centre_mm;
  const double len = glm::length(d);
  const double held = std::max(0.0, radius_mm - kContactOverlapMm);
  if (!(len < held)) return false;
  // Onto the probe's surface, along the line from its centre (the probe pushes straight
  // out of itself); at the very centre, back toward the base point.
  const glm::dvec3 dir = len > 1e-9 ? d / len : glm::normalize(base_[i] - centre_mm + glm::dvec3(0.0, 0.0, 1e-9));
  x_[i] = centre_mm + held * dir;
  const double into = glm::dot(v_[i], dir);
  if (into < 0.0) v_[i] -= into * dir;
  return true;
}

DeformStep Deformable::step(double dt_s, const glm::dvec3& centre_mm, double radius_mm) {
  DeformStep out;
  if (!(dt_s > 0.0)) return out;
  dt_s = std::min(dt_s, kMaxStepS);
  out.substeps = static_cast<int>(std::ceil(dt_s / substep_s_ - 1e-9));
  const double h = dt_s / out.substeps;
  const double m = params_.mass_g * 1e-3;                          // kg
  const double c = params_.damping_n_s_per_mm * kMmPerM;           // N s/m
  const double damp = 1.0 / (1.0 + h * c / m);                     // implicit damping factor
  const bool probe = finite3(centre_mm) && std::isfinite(radius_mm) && radius_mm > 0.0;
  const double max_mm = params_.max_mm;
  collect_active(centre_mm, radius_mm, probe);
  for (int s = 0; s < out.substeps; ++s) {
    accumulate_forces();
    out.constrained = 0;
    for (const std::uint32_t i : active_) {
      v_[i] = (v_[i] + h * force_[i] / m * kMmPerM) * damp;  // mm/s
      x_[i] += h * v_[i];
      if (probe && hold_out_of_probe(i, centre_mm, radius_mm)) ++out.constrained;
      const glm::dvec3 u = x_[i] - base_[i];
      const double ul = glm::length(u);
      if (ul > max_mm) {
        x_[i] = base_[i] + u * (max_mm / ul);
        v_[i] = glm::dvec3(0.0);
      }
    }
  }
  for (const std::uint32_t i : active_)
    if (glm::length(x_[i] - base_[i]) <= kRestMm && glm::length(v_[i]) <= kRestMmS) {
      x_[i] = base_[i];
      v_[i] = glm::dvec3(0.0);
    }
  out.max_displacement_mm = max_displacement_mm();
  return out;
}

std::vector<glm::dvec3> Deformable::area_normals() const {
  std::vector<glm::dvec3> normals(base_.size(), glm::dvec3(0.0));
  for (std::size_t t = 0; t + 2 < triangles_.size(); t += 3) {
    const glm::dvec3 &a = x_[triangles_[t]], &b = x_[triangles_[t + 1]], &c = x_[triangles_[t + 2]];
    const glm::dvec3 area2 = glm::cross(b - a, c - a);  // length = twice the area: area-weighted
    for (int k = 0; k < 3; ++k) normals[triangles_[t + k]] += area2;
  }
  for (glm::dvec3& n : normals) {
    const double len = glm::length(n);
    if (len > 0.0) n /= len;
  }
  return normals;
}

void Deformable::write(Mesh& mesh) const {
  const std::vector<glm::dvec3> now = area_normals();
  for (std::size_t i = 0; i < mesh.positions.size() && i < weld_.size(); ++i) {
    const std::uint32_t w = weld_[i];
    mesh.positions[i] = glm::vec3(x_[w]);
    if (i >= mesh.normals.size() || i >= rest_normal_.size()) continue;
    const glm::dvec3 n = glm::dvec3(rest_normal_[i]) + (now[w] - rest_area_normal_[w]);
    const double len = glm::length(n);
    mesh.normals[i] = len > 1e-12 ? glm::vec3(n / len) : glm::vec3(now[w]);
  }
}

Mesh subdivide(const Mesh& mesh, double max_edge_mm, std::size_t max_triangles) {
  Mesh out = mesh;
  for (int level = 0; level < 3; ++level) {
    double longest = 0.0;
    for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3)
      for (int k = 0; k < 3; ++k)
        longest = std::max(longest, static_cast<double>(glm::length(out.positions[out.indices[t + k]] -
                                                                     out.positions[out.indices[t + (k + 1) % 3]])));
    if (longest <= max_edge_mm || out.indices.size() / 3 * 4 > max_triangles) break;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = mid.try_emplace({key.first, key.second}, static_cast<std::uint32_t>(out.positions.size()));
      if (inserted) {
        out.positions.push_back(0.5f * (out.positions[a] + out.positions[b]));
        if (out.normals.size() + 1 == out.positions.size()) {
          const glm::vec3 n = out.normals[a] + out.normals[b];
          const float len = glm::length(n);
          out.normals.push_back(len > 0.0f ? n / len : out.normals[a]);
        }
      }
      return it->second;
    };
    std::vector<std::uint32_t> indices;
    indices.reserve(out.indices.size() * 4);
    for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3) {
      const std::uint32_t a = out.indices[t], b = out.indices[t + 1], c = out.indices[t + 2];
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      indices.insert(indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    out.indices = std::move(indices);
  }
  return out;
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
