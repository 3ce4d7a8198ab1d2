#include "world/god_object.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "world/shapes.h"

namespace ps::world {

GodObject::GodObject(const HapticScene& scene, const GodObjectParams& params)
    : scene_(scene), params_(params), radius_(scene.probe_radius_mm()) {}

void GodObject::reset(const glm::dvec3& device_mm) {
  proxy_ = device_mm;
  initialized_ = true;
  hint_.has_w4 = false;  // no sheet of a 4D surface yet: the next touch picks one
  // Up to a few passes: pushing out of one surface can push into a neighbour.
  for (int pass = 0; pass < 4; ++pass) {
    const Contact c = scene_.closest(proxy_, radius_);
    if (!c.hit || c.distance_mm >= radius_) return;
    // Outward normal, not (proxy - point): a device deep inside a closed mesh lies on the
    // inner side of the face it is closest to.
    proxy_ = c.point + (radius_ + params_.contact_epsilon_mm) * c.normal;
  }
}

glm::dvec3 GodObject::constrained_target(const glm::dvec3& goal, const Plane* planes, int count,
                                         const glm::dvec3& fallback) const {
  auto feasible = [&](const glm::dvec3& x) {
    for (int i = 0; i < count; ++i)
      if (glm::dot(planes[i].n, x) < planes[i].d - 1e-9) return false;
    return true;
  };
  if (feasible(goal)) return goal;
  double best = std::numeric_limits<double>::infinity();
  glm::dvec3 best_x = fallback;
  // Every non-empty active set S: x = goal + sum_j lambda_j n_j with n_k . x = d_k (k in S),
  // i.e. G lambda = d - N goal with the Gram matrix G; valid when lambda >= 0 (a constraint
  // pushes, never pulls) and the planes outside S hold.
  for (int mask = 1; mask < (1 << count); ++mask) {
    int idx[3], m = 0;
    for (int i = 0; i < count; ++i)
      if (mask & (1 << i)) idx[m++] = i;
    glm::dmat3 g(1.0);
    glm::dvec3 rhs(0.0);
    for (int a = 0; a < m; ++a) {
      rhs[a] = planes[idx[a]].d - glm::dot(planes[idx[a]].n, goal);
      for (int b = 0; b < m; ++b) g[b][a] = glm::dot(planes[idx[a]].n, planes[idx[b]].n);
    }
    // Nearly parallel planes make G singular: that active set has no unique solution.
    if (std::abs(glm::determinant(g)) < 1e-9) continue;
    const glm::dvec3 lambda = glm::inverse(g) * rhs;
    bool pushes = true;
    glm::dvec3 x = goal;
    for (int a = 0; a < m; ++a) {
      if (lambda[a] < -1e-12) pushes = false;
      x += lambda[a] * planes[idx[a]].n;
    }
    if (!pushes || !feasible(x)) continue;
    const double dist = glm::length(x - goal);
    if (dist < best) { best = dist; best_x = x; }
  }
  return best_x;
}

// Distance from p to the nearest surface within `limit`, minus R (infinity when none).
double GodObject::gap(const glm::dvec3& p, double limit, Contact& c, std::uint32_t& facets) {
  c = scene_.closest(p, radius_ + limit, &hint_);
  facets += c.facets_visited;
  if (c.mesh_hit.hit) hint_.mesh_hit = c.mesh_hit;
  // A surface embedded in 4D, touched (within the query margin): the proxy keeps to this sheet
  // from now on (eq. 3: the w before this query becomes w_pre).
  if (c.hit && c.has_w4 && c.distance_mm - radius_ <= params_.query_margin_mm) {
    hint_.w4_pre = hint_.has_w4 && hint_.surface == c.surface ? hint_.w4 : c.w4;
    hint_.w4 = c.w4;
    hint_.has_w4 = true;
    hint_.surface = c.surface;
    hint_.point = c.point;
    hint_.normal = c.normal;
    hint_.fourd_facet = c.fourd_facet;
  }
  return c.hit ? c.distance_mm - radius_ : std::numeric_limits<double>::infinity();
}

// A step of at most slide_step_fraction x R along a surface, then out of whatever it entered
// along (centre - nearest point). The centre moves less than R, so it cannot cross a surface
// (distance is 1-Lipschitz and was >= R - epsilon): the push-out direction points to the side
// the proxy came from. False (p unchanged) if the pushed-out sphere still overlaps something.
bool GodObject::slide(glm::dvec3& p, const glm::dvec3& target, std::uint32_t& facets) {
  const glm::dvec3 dir = target - p;
  const double len = glm::length(dir);
  const double s = std::min(len, params_.slide_step_fraction * radius_);
  glm::dvec3 q = p + dir * (s / len);
  Contact c;
  for (int pass = 0; pass < 3; ++pass) {  // pushing out of one surface may push into a neighbour
    if (gap(q, 0.0, c, facets) >= 0.0) {
      p = q;
      return true;
    }
    q = c.point + radius_ * unit_or(q - c.point, c.normal);
  }
  if (gap(q, 0.0, c, facets) >= -params_.contact_epsilon_mm) {
    p = q;
    return true;
  }
  return false;
}

void GodObject::keep_plane(Plane* planes, int& count, const Plane& plane) {
  int slot = count;
  for (int i = 0; i < count; ++i)
    if (glm::dot(planes[i].n, plane.n) > 0.999) slot = i;
  if (slot == count) slot = count < 3 ? count++ : 0;  // four distinct planes: drop the oldest
  planes[slot] = plane;
}

Contact GodObject::constrain(const glm::dvec3& goal_mm, glm::dvec3& p, int& count, std::uint32_t& facets) {
  Plane planes[3];
  count = 0;
  Contact touched;
  for (int it = 0; it < params_.max_iterations; ++it) {
    const glm::dvec3 target = constrained_target(goal_mm, planes, count, p);
    const glm::dvec3 dir = target - p;
    const double len = glm::length(dir);
    if (len <= 1e-9) break;
    Contact c;
    const double g = gap(p, len + params_.query_margin_mm, c, facets);
    if (g >= len) {  // the nearest surface is farther than the whole move: free
      p = target;
      if (count == 0) break;
      // The planes led the proxy off their surfaces (past a convex edge, into free space):
      // they no longer touch, so drop them and head for the goal itself again.
      count = 0;
      continue;
    }
    if (g > params_.contact_epsilon_mm) {
      // Approach: less than the gap keeps the sphere clear of every surface, half an epsilon
      // short keeps rounding from touching it.
      p += dir * ((g - 0.5 * params_.contact_epsilon_mm) / len);
      continue;
    }
    // Touching c: its tangent plane, offset by R, constrains the rest of the move. A plane
    // nearly parallel to one we have replaces it (the same surface, a little further on).
    touched = c;
    const glm::dvec3 n = unit_or(p - c.point, c.normal);
    keep_plane(planes, count, Plane{n, glm::dot(n, c.point) + radius_});
    const glm::dvec3 along = constrained_target(goal_mm, planes, count, p);
    if (glm::length(along - p) <= 1e-9 || !slide(p, along, facets)) break;
  }
  return touched;
}

void GodObject::settle(ProxyStep& out, const glm::dvec3& goal_mm, const glm::dvec3& p, Contact touched) {
  if (hint_.has_w4 && !touched.hit) {
    // Clear of its 4D surface's sheet by more than R: let go of it, so the next touch may
    // land on any sheet (a proxy lifted off and put down elsewhere).
    Contact c;
    if (gap(p, radius_, c, out.facets_visited) > radius_) hint_.has_w4 = false;
  }
  if (touched.hit && glm::length(goal_mm - p) > 1e-9) {
    out.in_contact = true;
    out.surface = touched.surface;
    // Normal where the proxy rests now (it may have slid since the last touch).
    Contact c;
    if (gap(p, params_.query_margin_mm, c, out.facets_visited) < params_.query_margin_mm) touched = c;
    out.surface = touched.surface;
    out.contact_point = touched.point;
    out.contact_normal = unit_or(p - touched.point, touched.normal);
    // Open meshes and planes are two-sided: the shading normal faces the proxy.
    out.shaded_normal = glm::dot(touched.shaded_normal, out.contact_normal) < 0.0 ? -touched.shaded_normal
                                                                                  : touched.shaded_normal;
  }
}

ProxyStep GodObject::move(const glm::dvec3& goal_mm) {
  ProxyStep out;
  if (!initialized_) reset(goal_mm);
  glm::dvec3 p = proxy_;
  int count = 0;
  const Contact touched = constrain(goal_mm, p, count, out.facets_visited);
  proxy_ = p;
  out.proxy_mm = p;
  out.planes = count;
  out.short_of_goal = !touched.hit && glm::length(goal_mm - p) > 1e-6;
  settle(out, goal_mm, p, touched);
  return out;
}

}  // namespace ps::world
