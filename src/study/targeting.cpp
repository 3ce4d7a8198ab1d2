#include "study/targeting.h"

#include <cmath>
#include <numbers>

namespace ps::study {

namespace {

using V = std::array<double, 3>;

V cross(const V& a, const V& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V unit(const V& a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

}  // namespace

Ring make_ring(const TargetingSpec& spec, double diameter) {
  Ring r;
  r.centre = {spec.centre[0], spec.centre[1], spec.centre[2]};
  r.normal = unit(spec.normal);
  // World +x projected onto the plane; world +y when the normal is (nearly) along x.
  const V x = std::abs(r.normal[0]) > 0.9 ? V{0.0, 1.0, 0.0} : V{1.0, 0.0, 0.0};
  const double k = dot(x, r.normal);
  r.u = unit({x[0] - k * r.normal[0], x[1] - k * r.normal[1], x[2] - k * r.normal[2]});
  r.v = cross(r.normal, r.u);
  r.diameter = diameter;
  r.targets = spec.targets;
  return r;
}

Point3 target_centre(const Ring& ring, int index) {
  const double a = 2.0 * std::numbers::pi * index / ring.targets, h = 0.5 * ring.diameter;
  const double cu = h * std::cos(a), cv = h * std::sin(a);
  return {ring.centre.x + cu * ring.u[0] + cv * ring.v[0], ring.centre.y + cu * ring.u[1] + cv * ring.v[1],
          ring.centre.z + cu * ring.u[2] + cv * ring.v[2]};
}

int target_at_step(int targets, int step) { return static_cast<int>((static_cast<long long>(step) * ((targets + 1) / 2)) % targets); }

double movement_distance(double diameter, int targets) {
  return diameter * std::sin(std::numbers::pi * (targets - 1) / (2.0 * targets));
}

Point3 on_axis(const Ring& ring, const Point3& from, const Point3& to, double along, double aside) {
  const V a = unit({to.x - from.x, to.y - from.y, to.z - from.z});
  const V l = cross(ring.normal, a);
  return {from.x + along * a[0] + aside * l[0], from.y + along * a[1] + aside * l[1], from.z + along * a[2] + aside * l[2]};
}

bool TouchSelector::tick(double time_s, bool in_contact, double gap_mm) {
  if (in_contact) {
    const bool selected = armed_;
    armed_ = false;
    lifted_since_ = -1.0;
    return selected;
  }
  if (gap_mm <= rearm_mm_) {
    lifted_since_ = -1.0;
  } else {
    if (lifted_since_ < 0.0) lifted_since_ = time_s;
    if (time_s - lifted_since_ >= rearm_s_) armed_ = true;
  }
  return false;
}

bool hidden_by_sphere(const Point3& eye, const Point3& p, const Point3& centre, double radius) {
  const V d{p.x - eye.x, p.y - eye.y, p.z - eye.z}, f{eye.x - centre.x, eye.y - centre.y, eye.z - centre.z};
  const V q{p.x - centre.x, p.y - centre.y, p.z - centre.z};
  if (dot(q, q) < radius * radius) return true;  // under the probe
  const double a = dot(d, d), b = 2.0 * dot(f, d), c = dot(f, f) - radius * radius;
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return false;
  const double t = (-b - std::sqrt(disc)) / (2.0 * a);  // where the segment enters the sphere
  return t > 0.0 && t < 1.0;
}

double distance(const Point3& a, const Point3& b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); }

}  // namespace ps::study
