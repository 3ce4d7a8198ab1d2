#include "fourd/fourd_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "fourd/rotation4.h"
#include "fourd/surfaces.h"

namespace ps::fourd {
namespace {

// Vertices closer than this in R^4 are one point of the surface (the seams' duplicates differ
// by rounding, ~1e-15; the nearest distinct grid vertices are ~1e-3 apart).
constexpr double kWeldQuantum = 1e-7;

using WeldKey = std::array<long long, 4>;
WeldKey weld_key(const glm::dvec4& p) {
  return {std::llround(p.x / kWeldQuantum), std::llround(p.y / kWeldQuantum), std::llround(p.z / kWeldQuantum),
          std::llround(p.w / kWeldQuantum)};
}

// Welded id per vertex, then each triangle's neighbour across each edge.
void find_neighbours(FourdMesh& m) {
  std::map<WeldKey, std::uint32_t> ids;
  std::vector<std::uint32_t> weld(m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    weld[i] = ids.emplace(weld_key(m.vertices[i].p4), static_cast<std::uint32_t>(ids.size())).first->second;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::pair<int, int>>> edges;
  for (std::size_t f = 0; f < m.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = weld[m.triangles[f][k]], b = weld[m.triangles[f][(k + 1) % 3]];
      if (a > b) std::swap(a, b);
      edges[{a, b}].emplace_back(static_cast<int>(f), k);
    }
  m.neighbours.assign(m.triangles.size(), glm::ivec3(-1));
  for (const auto& [edge, uses] : edges) {
    if (uses.size() != 2) continue;  // a border (none on these closed surfaces)
    m.neighbours[static_cast<std::size_t>(uses[0].first)][uses[0].second] = uses[1].first;
    m.neighbours[static_cast<std::size_t>(uses[1].first)][uses[1].second] = uses[0].first;
  }
}

// Area-weighted normals of the 3D image around each grid vertex (the grid's own triangles: one
// orientation around every vertex, also on the non-orientable Roman surface).
void compute_normals(FourdMesh& m) {
  m.normals.assign(m.vertices.size(), glm::dvec3(0.0));
  for (const glm::uvec3& t : m.triangles) {
    const glm::dvec3 a = m.vertices[t.x].p3, b = m.vertices[t.y].p3, c = m.vertices[t.z].p3;
    const glm::dvec3 n = glm::cross(b - a, c - a);
    for (int k = 0; k < 3; ++k) m.normals[t[k]] += n;
  }
  for (glm::dvec3& n : m.normals) {
    const double len = glm::length(n);
    n = len > 1e-300 ? n / len : glm::dvec3(0.0, 0.0, 1.0);
  }
}

Status eye_error(const Spec& spec, double w_max) {
  if (spec.projection != Projection4::kPerspective || w_max < 0.95 * spec.eye_distance) return ok_status();
  char text[256];
  std::snprintf(text, sizeof text,
                "puts the 4D eye (at w = %g) inside or too near the rotated surface, whose largest w is %.3g; "
                "make fourd_eye_distance larger than %.3g (e.g. fourd_eye_distance = %g)",
                spec.eye_distance, w_max, w_max / 0.95, std::ceil(w_max / 0.95 + 0.5));
  return make_error(text);
}

}  // namespace

Status check_eye(const Spec& spec) {
  const glm::ivec2 grid = default_grid(spec.kind);
  const int nu = spec.nu > 0 ? spec.nu : grid.x, nv = spec.nv > 0 ? spec.nv : grid.y;
  const KnottedArc arc = (spec.kind == SurfaceKind::kSpunTrefoil || spec.kind == SurfaceKind::kTwistSpunTrefoil)
                             ? KnottedArc::make(spec.kind == SurfaceKind::kTwistSpunTrefoil)
                             : KnottedArc{};
  const glm::dmat4 rotation = rotation_from_deg(spec.rotation_deg);
  double w_max = -1e300;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i)
      w_max = std::max(w_max, (rotation * surface_point(spec.kind, double(i) / nu, double(j) / nv, spec.twists, &arc)).w);
  return eye_error(spec, w_max);
}

double FourdMesh::tri_w_min(std::size_t f) const {
  const glm::uvec3 t = triangles[f];
  return std::min({vertices[t.x].w, vertices[t.y].w, vertices[t.z].w});
}
double FourdMesh::tri_w_max(std::size_t f) const {
  const glm::uvec3 t = triangles[f];
  return std::max({vertices[t.x].w, vertices[t.y].w, vertices[t.z].w});
}

namespace {

// Two triangles per grid cell, leaving out those that a pole collapses (two corners at one point).
void triangulate(FourdMesh& m) {
  auto index = [&m](int i, int j) { return static_cast<std::uint32_t>(j * (m.nu + 1) + i); };
  auto add = [&m](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const auto& p = m.vertices;
    auto same = [&p](std::uint32_t x, std::uint32_t y) { return glm::length(p[x].p4 - p[y].p4) < kWeldQuantum; };
    if (same(a, b) || same(b, c) || same(a, c)) return;  // a pole
    m.triangles.emplace_back(a, b, c);
  };
  for (int j = 0; j < m.nv; ++j)
    for (int i = 0; i < m.nu; ++i) {
      add(index(i, j), index(i + 1, j), index(i + 1, j + 1));
      add(index(i, j), index(i + 1, j + 1), index(i, j + 1));
    }
}

}  // namespace

Result<FourdMesh> build_fourd_mesh(const Spec& spec) {
  FourdMesh m;
  m.spec = spec;
  const glm::ivec2 grid = default_grid(spec.kind);
  m.nu = spec.nu > 0 ? spec.nu : grid.x;
  m.nv = spec.nv > 0 ? spec.nv : grid.y;
  if (m.nu < 3 || m.nv < 3) return make_error("fourd: the grid needs at least 3 x 3 cells");
  const KnottedArc arc = (spec.kind == SurfaceKind::kSpunTrefoil || spec.kind == SurfaceKind::kTwistSpunTrefoil)
                             ? KnottedArc::make(spec.kind == SurfaceKind::kTwistSpunTrefoil)
                             : KnottedArc{};
  const glm::dmat4 rotation = rotation_from_deg(spec.rotation_deg);
  m.w_min = 1e300;
  m.w_max = -1e300;
  for (int j = 0; j <= m.nv; ++j)
    for (int i = 0; i <= m.nu; ++i) {
      Vertex4 v;
      v.uv = {static_cast<double>(i) / m.nu, static_cast<double>(j) / m.nv};
      v.p4 = rotation * surface_point(spec.kind, v.uv.x, v.uv.y, spec.twists, &arc);
      v.w = v.p4.w;
      m.w_min = std::min(m.w_min, v.w);
      m.w_max = std::max(m.w_max, v.w);
      m.vertices.push_back(v);
    }
  if (Status eye = eye_error(spec, m.w_max); !eye) return eye.error();
  for (Vertex4& v : m.vertices) v.p3 = project(v.p4, spec.projection, spec.eye_distance).p3;
  triangulate(m);
  find_neighbours(m);
  compute_normals(m);
  return m;
}

glm::dvec3 closest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                               glm::dvec3& bary) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return bary = {1, 0, 0}, a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return bary = {0, 1, 0}, b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return bary = {1 - v, v, 0}, a + v * ab;
  }
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return bary = {0, 0, 1}, c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return bary = {1 - w, 0, w}, a + w * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return bary = {0, 1 - w, w}, b + w * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return bary = {1 - v - w, v, w}, a + ab * v + ac * w;
}


double auto_w_slack(const FourdMesh& mesh) {
  std::vector<double> dw;
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) dw.push_back(std::abs(mesh.vertices[t[k]].w - mesh.vertices[t[(k + 1) % 3]].w));
  if (dw.empty()) return 0.0;
  std::nth_element(dw.begin(), dw.begin() + static_cast<long>(dw.size() / 2), dw.end());
  return 2.0 * dw[dw.size() / 2];
}

glm::dvec3 depth_colour(double t) {
  static constexpr std::array<glm::dvec3, 5> kStops = {
      glm::dvec3(0.15, 0.30, 0.90), glm::dvec3(0.15, 0.75, 0.85), glm::dvec3(0.35, 0.80, 0.30),
      glm::dvec3(0.95, 0.80, 0.20), glm::dvec3(0.90, 0.25, 0.20)};
  const double x = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (kStops.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(x), kStops.size() - 2);
  return glm::mix(kStops[i], kStops[i + 1], x - static_cast<double>(i));
}

}  // namespace ps::fourd
