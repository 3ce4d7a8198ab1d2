#include "fourd/local_model.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace ps::fourd {

LocalModel::LocalModel(const FourdMesh& mesh, double scale_mm, const glm::dmat3& rotation,
                       const glm::dvec3& center_mm)
    : mesh_(mesh) {
  for (const Vertex4& v : mesh.vertices) positions_.push_back(rotation * (scale_mm * v.p3) + center_mm);
  const std::size_t n = mesh.triangles.size();
  box_min_.resize(n);
  box_max_.resize(n);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  double edge_sum = 0.0;
  for (std::size_t f = 0; f < n; ++f) {
    const glm::uvec3 t = mesh.triangles[f];
    box_min_[f] = glm::min(glm::min(positions_[t.x], positions_[t.y]), positions_[t.z]);
    box_max_[f] = glm::max(glm::max(positions_[t.x], positions_[t.y]), positions_[t.z]);
    lo = glm::min(lo, box_min_[f]);
    hi = glm::max(hi, box_max_[f]);
    for (int k = 0; k < 3; ++k) edge_sum += glm::length(positions_[t[k]] - positions_[t[(k + 1) % 3]]);
  }
  auto_w_slack_ = fourd::auto_w_slack(mesh);
  // Facets whose boxes touch (grown by 1 % of a mean edge: shared edges touch exactly), found
  // through a uniform grid of cells about a mean edge wide.
  const double edge = n > 0 ? edge_sum / (3.0 * static_cast<double>(n)) : 1.0;
  const double grow = 0.01 * edge, cell = std::max(edge, 1e-9);
  find_touching(lo, grow, cell);
  out_.reserve(n);
  mark_.assign(n, 0);
  path_mm_.assign(n, 0.0);
  centroid_.resize(n);
  for (std::size_t f = 0; f < n; ++f) {
    const glm::uvec3 t = mesh.triangles[f];
    centroid_[f] = (positions_[t.x] + positions_[t.y] + positions_[t.z]) / 3.0;
  }
}

void LocalModel::find_touching(const glm::dvec3& lo, double grow, double cell) {
  const std::size_t n = box_min_.size();
  std::map<std::tuple<int, int, int>, std::vector<int>> grid;
  auto cell_of = [&](const glm::dvec3& p) { return glm::ivec3(glm::floor((p - lo) / cell)); };
  for (std::size_t f = 0; f < n; ++f) {
    const glm::ivec3 a = cell_of(box_min_[f] - grow), b = cell_of(box_max_[f] + grow);
    for (int x = a.x; x <= b.x; ++x)
      for (int y = a.y; y <= b.y; ++y)
        for (int z = a.z; z <= b.z; ++z) grid[{x, y, z}].push_back(static_cast<int>(f));
  }
  touching_.resize(n);
  for (const auto& [key, facets] : grid)
    for (int f : facets)
      for (int g : facets) {
        if (f == g) continue;
        const auto fu = static_cast<std::size_t>(f), gu = static_cast<std::size_t>(g);
        if (glm::all(glm::lessThanEqual(box_min_[fu] - grow, box_max_[gu] + grow)) &&
            glm::all(glm::lessThanEqual(box_min_[gu] - grow, box_max_[fu] + grow)))
          touching_[fu].push_back(g);
      }
  for (std::vector<int>& t : touching_) {
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
  }
}

bool LocalModel::within(int f, const glm::dvec3& c, double r) const {
  const auto fu = static_cast<std::size_t>(f);
  const glm::dvec3 d = glm::max(glm::max(box_min_[fu] - c, c - box_max_[fu]), glm::dvec3(0.0));
  return glm::dot(d, d) <= r * r;
}

LocalModel::FacetPoint LocalModel::closest_on_facet(int f, const glm::dvec3& p) const {
  const glm::uvec3 t = mesh_.triangles[static_cast<std::size_t>(f)];
  glm::dvec3 bary;
  const glm::dvec3 point = closest_on_triangle(p, positions_[t.x], positions_[t.y], positions_[t.z], bary);
  const double w = bary.x * mesh_.vertices[t.x].w + bary.y * mesh_.vertices[t.y].w + bary.z * mesh_.vertices[t.z].w;
  return {point, w, glm::length(p - point)};
}

void LocalModel::admit(const Admission& a, int f, std::size_t from) {
  const auto fu = static_cast<std::size_t>(f);
  if (mark_[fu] == stamp_) return;
  if (a.kind == LocalModelKind::kAdjacency) {
    // Distance along the surface (centroid to centroid along the walk): a sheet that crosses
    // this one is near in 3D but far along the surface. A facet too far by this path stays
    // unmarked, so a shorter path found later still admits it.
    const double path = path_mm_[from] + glm::length(centroid_[fu] - centroid_[from]);
    if (path > a.params.radius_mm) return;
    path_mm_[fu] = path;
    mark_[fu] = stamp_;
  } else {
    mark_[fu] = stamp_;
    if (!within(f, a.contact_mm, a.params.radius_mm)) return;
  }
  if (a.kind == LocalModelKind::kContinuity &&
      (mesh_.tri_w_max(fu) < a.w_cur - a.half || mesh_.tri_w_min(fu) > a.w_cur + a.half))
    return;
  out_.push_back(f);
}

std::span<const int> LocalModel::build(LocalModelKind kind, int facet, const glm::dvec3& contact_mm, double w_cur,
                                       double w_pre, const LocalModelParams& params) {
  out_.clear();
  const int n = static_cast<int>(mesh_.triangles.size());
  if (kind == LocalModelKind::kNearest) {
    for (int f = 0; f < n; ++f) out_.push_back(f);
    return out_;
  }
  assert(facet >= 0 && facet < n && "LocalModel::build: the proxy's facet is out of range (reset the proxy first)");
  if (++stamp_ == 0) {  // wrapped: clear the stamps once every 2^32 builds
    std::fill(mark_.begin(), mark_.end(), 0u);
    stamp_ = 1;
  }
  const double slack = params.w_slack >= 0.0 ? params.w_slack : auto_w_slack_;
  const double half = std::abs(w_cur - w_pre) + slack;  // eq. 3-4
  const Admission rule{kind, contact_mm, w_cur, half, params};
  const auto start = static_cast<std::size_t>(facet);
  mark_[start] = stamp_;
  path_mm_[start] = glm::length(centroid_[start] - contact_mm);
  out_.push_back(facet);  // the proxy's own facet is always in
  for (std::size_t head = 0; head < out_.size(); ++head) {
    const auto f = static_cast<std::size_t>(out_[head]);
    if (kind == LocalModelKind::kContinuity) {
      for (int g : touching_[f]) admit(rule, g, f);
    } else {
      for (int k = 0; k < 3; ++k)
        if (mesh_.neighbours[f][k] >= 0) admit(rule, mesh_.neighbours[f][k], f);
    }
  }
  return out_;
}

void SheetProxy::reset(const glm::dvec3& device_mm) {
  const std::span<const int> all = model_.build(LocalModelKind::kNearest, 0, device_mm, 0.0, 0.0, params_);
  double best = std::numeric_limits<double>::infinity();
  for (int f : all) {
    const LocalModel::FacetPoint fp = model_.closest_on_facet(f, device_mm);
    if (fp.distance_mm < best) {
      best = fp.distance_mm;
      state_.facet = f;
      state_.contact_mm = fp.point;
      state_.w_cur = state_.w_pre = fp.w;
    }
  }
  state_.local_facets = all.size();
}

const ProxyState& SheetProxy::update(const glm::dvec3& device_mm) {
  if (state_.facet < 0) reset(device_mm);
  const std::span<const int> local =
      model_.build(kind_, state_.facet, state_.contact_mm, state_.w_cur, state_.w_pre, params_);
  double best = std::numeric_limits<double>::infinity();
  LocalModel::FacetPoint chosen{state_.contact_mm, state_.w_cur, 0.0};
  int facet = state_.facet;
  for (int f : local) {
    const LocalModel::FacetPoint fp = model_.closest_on_facet(f, device_mm);
    if (fp.distance_mm < best) {
      best = fp.distance_mm;
      chosen = fp;
      facet = f;
    }
  }
  state_.w_pre = state_.w_cur;  // step 5 of the previous tick, done here so eq. 3 sees both
  state_.w_cur = chosen.w;
  state_.facet = facet;
  state_.contact_mm = chosen.point;
  state_.local_facets = local.size();
  return state_;
}

}  // namespace ps::fourd
