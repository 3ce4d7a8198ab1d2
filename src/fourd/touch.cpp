#include "fourd/touch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ps::fourd {
namespace {

constexpr int kMaxCellsPerAxis = 48;  // 48^3 cells: a few MB of indices at most

// FourdTouch::closest_adjacent's breadth-first queue: at most N facets, each once, with its
// path length. Fixed storage on the stack (the haptic thread allocates nothing).
template <std::size_t N>
struct FacetQueue {
  std::array<int, N> facet;
  std::array<double, N> path;
  std::array<int, 2 * N> seen;  // open addressing, -1 = empty
  std::size_t count = 0;

  FacetQueue() { seen.fill(-1); }
  bool mark(int f) {  // false if already there
    std::size_t h = (static_cast<std::size_t>(f) * 2654435761u) % seen.size();
    while (seen[h] >= 0) {
      if (seen[h] == f) return false;
      h = (h + 1) % seen.size();
    }
    seen[h] = f;
    return true;
  }
  void push(int f, double d) {  // full: the walk stops growing
    if (count == N || !mark(f)) return;
    facet[count] = f;
    path[count] = d;
    ++count;
  }
};

}  // namespace

FourdTouch::FourdTouch(const FourdMesh& mesh, double scale_mm, const glm::dmat3& rotation,
                       const glm::dvec3& center_mm) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    positions_.push_back(rotation * (scale_mm * mesh.vertices[i].p3) + center_mm);
    normals_.push_back(glm::normalize(rotation * mesh.normals[i]));
    w_.push_back(mesh.vertices[i].w);
    lo = glm::min(lo, positions_.back());
    hi = glm::max(hi, positions_.back());
  }
  double edge_sum = 0.0;
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) edge_sum += glm::length(positions_[t[k]] - positions_[t[(k + 1) % 3]]);
  w_slack_ = auto_w_slack(mesh);
  // Cells about two mean edges wide, at most kMaxCellsPerAxis along any axis.
  const double edge = mesh.triangles.empty() ? 1.0 : edge_sum / (3.0 * static_cast<double>(mesh.triangles.size()));
  const glm::dvec3 extent = glm::max(hi - lo, glm::dvec3(1e-9));
  cell_mm_ = std::max({2.0 * edge, extent.x / kMaxCellsPerAxis, extent.y / kMaxCellsPerAxis, extent.z / kMaxCellsPerAxis});
  origin_ = lo;
  dims_ = glm::max(glm::ivec3(glm::ceil(extent / cell_mm_)), glm::ivec3(1));
  neighbours_ = mesh.neighbours;
  for (const glm::uvec3& t : mesh.triangles) centroid_.push_back((positions_[t.x] + positions_[t.y] + positions_[t.z]) / 3.0);
  build_grid(mesh);
}

// Each facet's w range and cell box, and the grid's facet lists (counted, prefix-summed, filled).
void FourdTouch::build_grid(const FourdMesh& mesh) {
  std::vector<std::uint32_t> count(static_cast<std::size_t>(dims_.x) * dims_.y * dims_.z + 1, 0);
  auto cell_index = [this](int x, int y, int z) {
    return static_cast<std::size_t>((z * dims_.y + y) * dims_.x + x);
  };
  for (const glm::uvec3& t : mesh.triangles) {
    Tri tri{t, std::min({w_[t.x], w_[t.y], w_[t.z]}), std::max({w_[t.x], w_[t.y], w_[t.z]}), {}, {}};
    tri.cell_lo = cell_of(glm::min(glm::min(positions_[t.x], positions_[t.y]), positions_[t.z]));
    tri.cell_hi = cell_of(glm::max(glm::max(positions_[t.x], positions_[t.y]), positions_[t.z]));
    for (int z = tri.cell_lo.z; z <= tri.cell_hi.z; ++z)
      for (int y = tri.cell_lo.y; y <= tri.cell_hi.y; ++y)
        for (int x = tri.cell_lo.x; x <= tri.cell_hi.x; ++x) ++count[cell_index(x, y, z) + 1];
    tris_.push_back(tri);
  }
  for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
  cell_start_ = count;
  cell_facets_.resize(count.back());
  for (std::size_t f = 0; f < tris_.size(); ++f) {
    const Tri& tri = tris_[f];
    for (int z = tri.cell_lo.z; z <= tri.cell_hi.z; ++z)
      for (int y = tri.cell_lo.y; y <= tri.cell_hi.y; ++y)
        for (int x = tri.cell_lo.x; x <= tri.cell_hi.x; ++x) cell_facets_[count[cell_index(x, y, z)]++] = static_cast<std::uint32_t>(f);
  }
}

template <class Visit>
void FourdTouch::for_each_facet_near(const glm::dvec3& p, double r, Visit&& visit) const {
  const glm::ivec3 lo = cell_of(p - glm::dvec3(r)), hi = cell_of(p + glm::dvec3(r));
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        const std::size_t c = static_cast<std::size_t>((z * dims_.y + y) * dims_.x + x);
        for (std::uint32_t i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
          const Tri& t = tris_[cell_facets_[i]];
          // A facet in several cells is tested once: in the first of them the query visits.
          if (glm::max(t.cell_lo, lo) != glm::ivec3(x, y, z)) continue;
          visit(cell_facets_[i], t);
        }
      }
}

FourdTouch::OtherSheet FourdTouch::other_sheet(const glm::dvec3& p, double max_distance_mm,
                                               const WWindow& window) const {
  OtherSheet out;
  double limit = max_distance_mm;
  for_each_facet_near(p, max_distance_mm, [&](std::uint32_t f, const Tri& t) {
    if (!(t.w_max < window.lo || t.w_min > window.hi)) return;  // the proxy's own sheet
    glm::dvec3 bary;
    const glm::dvec3 a = positions_[t.v.x], b = positions_[t.v.y], cc = positions_[t.v.z];
    const glm::dvec3 q = closest_on_triangle(p, a, b, cc, bary);
    const double d = glm::length(p - q);
    if (d > limit) return;
    const glm::dvec3 n = glm::cross(b - a, cc - a);
    const double len = glm::length(n);
    if (len < 1e-300) return;
    limit = d;
    out.hit = true;
    out.facet = static_cast<int>(f);
    out.signed_mm = glm::dot(p - a, n / len);
    out.w = bary.x * w_[t.v.x] + bary.y * w_[t.v.y] + bary.z * w_[t.v.z];
  });
  return out;
}

bool FourdTouch::facets_touch(int a, int b) const {
  if (a < 0 || b < 0) return false;
  if (a == b) return true;
  const glm::uvec3 ta = tris_[static_cast<std::size_t>(a)].v, tb = tris_[static_cast<std::size_t>(b)].v;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (ta[i] == tb[j] || positions_[ta[i]] == positions_[tb[j]]) return true;
  return false;
}

glm::ivec3 FourdTouch::cell_of(const glm::dvec3& p) const {
  return glm::clamp(glm::ivec3(glm::floor((p - origin_) / cell_mm_)), glm::ivec3(0), dims_ - 1);
}

WWindow FourdTouch::window(double w_cur, double w_pre) const {
  const double half = std::abs(w_cur - w_pre) + w_slack_;
  return {true, w_cur - half, w_cur + half};
}

TouchHit FourdTouch::closest(const glm::dvec3& p, double max_distance_mm, const WWindow& window) const {
  TouchHit best;
  double limit = max_distance_mm;
  for_each_facet_near(p, max_distance_mm, [&](std::uint32_t f, const Tri& t) {
    if (window.active && (t.w_max < window.lo || t.w_min > window.hi)) return;
    ++best.visited;
    glm::dvec3 bary;
    const glm::dvec3 q = closest_on_triangle(p, positions_[t.v.x], positions_[t.v.y], positions_[t.v.z], bary);
    const double d = glm::length(p - q);
    if (d > limit) return;
    limit = d;
    best.hit = true;
    best.facet = static_cast<int>(f);
    best.point = q;
    best.distance_mm = d;
    best.w = bary.x * w_[t.v.x] + bary.y * w_[t.v.y] + bary.z * w_[t.v.z];
  });
  finish(best, p);
  return best;
}

// The hit's normals: both on the query point's side (the image has no outside).
void FourdTouch::finish(TouchHit& best, const glm::dvec3& p) const {
  if (!best.hit) return;
  const Tri& t = tris_[static_cast<std::size_t>(best.facet)];
  const glm::dvec3 a = positions_[t.v.x], b = positions_[t.v.y], c = positions_[t.v.z];
  glm::dvec3 n = glm::cross(b - a, c - a);
  const double len = glm::length(n);
  n = len > 1e-300 ? n / len : glm::dvec3(0.0, 0.0, 1.0);
  glm::dvec3 bary;
  closest_on_triangle(best.point, a, b, c, bary);
  glm::dvec3 s = bary.x * normals_[t.v.x] + bary.y * normals_[t.v.y] + bary.z * normals_[t.v.z];
  s = glm::length(s) > 1e-12 ? glm::normalize(s) : n;
  const double side = glm::dot(p - best.point, n);
  if (side < 0.0) n = -n;
  if (glm::dot(s, n) < 0.0) s = -s;
  best.normal = n;
  best.shaded_normal = s;
}

TouchHit FourdTouch::closest_adjacent(const glm::dvec3& p, double max_distance_mm, int start_facet,
                                      const glm::dvec3& start_point, double radius_mm) const {
  TouchHit best;
  if (start_facet < 0 || static_cast<std::size_t>(start_facet) >= tris_.size()) return best;
  // Breadth-first over shared mesh edges, each facet with its path length along the surface
  // (start point to centroid, then centroid to centroid); a facet reached too far stays
  // unvisited, so a shorter path found later still admits it. Fixed storage on the stack: the
  // haptic thread allocates nothing; at kMaxAdjacent facets the walk stops.
  FacetQueue<kMaxAdjacent> walk;
  walk.push(start_facet, glm::length(centroid_[static_cast<std::size_t>(start_facet)] - start_point));
  double limit = max_distance_mm;
  for (std::size_t head = 0; head < walk.count; ++head) {
    const int f = walk.facet[head];
    const auto fu = static_cast<std::size_t>(f);
    const Tri& t = tris_[fu];
    ++best.visited;
    glm::dvec3 bary;
    const glm::dvec3 q = closest_on_triangle(p, positions_[t.v.x], positions_[t.v.y], positions_[t.v.z], bary);
    const double d = glm::length(p - q);
    if (d <= limit) {
      limit = d;
      best.hit = true;
      best.facet = f;
      best.point = q;
      best.distance_mm = d;
      best.w = bary.x * w_[t.v.x] + bary.y * w_[t.v.y] + bary.z * w_[t.v.z];
    }
    for (int k = 0; k < 3; ++k) {
      const int g = neighbours_[fu][k];
      if (g < 0) continue;
      const double along = walk.path[head] + glm::length(centroid_[static_cast<std::size_t>(g)] - centroid_[fu]);
      if (along <= radius_mm) walk.push(g, along);
    }
  }
  finish(best, p);
  return best;
}

glm::dvec3 FourdTouch::facet_normal(int f) const {
  const Tri& t = tris_[static_cast<std::size_t>(f)];
  const glm::dvec3 n = glm::cross(positions_[t.v.y] - positions_[t.v.x], positions_[t.v.z] - positions_[t.v.x]);
  const double len = glm::length(n);
  return len > 1e-300 ? n / len : glm::dvec3(0.0, 0.0, 1.0);
}

}  // namespace ps::fourd
