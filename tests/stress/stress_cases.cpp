#include "stress/stress_cases.h"

#include <limits>
#include <numbers>

#include "support/scenes.h"

namespace ps::test {

Scene stress_base_scene() {
  Scene s = flat_plane_scene(7.0);
  s.render.width = s.render.height = 32;
  s.render.depth_map_size = 32;
  s.materials[0].onset_distance_mm = 100.0;
  s.materials[0].gabor.lambda_min_mm = s.materials[0].gabor.lambda_max_mm = 1.0;
  return s;
}

namespace {

constexpr double kPi = std::numbers::pi;

void offset_scene(Scene& s, const glm::dvec3& o) {
  s.camera.position += o;
  s.camera.target += o;
  s.probe.position += o;
  for (Surface& f : s.surfaces) f.center += o;
}

Material& mat(Scene& s) { return s.materials[0]; }
GaborParams& gab(Scene& s) { return s.materials[0].gabor; }

// Two sheets back to back, 0.01 mm apart, seen exactly edge-on: no pixel covered, the normal
// sum is zero and the plane must be kept.
void sheet_edge_on(Scene& s) {
  s.surfaces[0].rotation_deg = {90.0, 0.0, 0.0};
  Surface back = s.surfaces[0];
  back.rotation_deg = {-90.0, 0.0, 0.0};
  back.center = {0.0, 0.01, 0.0};
  s.surfaces.push_back(back);
  s.probe.position = {0.0, 7.0, 0.0};
}

// Closed sphere seen from its centre (perspective, 120 deg): every visible normal faces the
// eye from all around, so they nearly cancel.
void inside_sphere(Scene& s) {
  Surface& f = s.surfaces[0];
  f.type = SurfaceType::kSphere;
  f.radius_mm = 50.0;
  f.center = {0.0, 0.0, 0.0};
  f.resolution = 16;
  s.camera.projection = Projection::kPerspective;
  s.camera.position = {0.0, 0.0, 0.0};
  s.camera.target = {0.0, 0.0, -1.0};
  s.camera.fov_y_deg = 120.0;
  s.probe.position = {0.0, 0.0, -45.0};
}

std::vector<StressCase> make_cases() {
  const double denorm = std::numeric_limits<double>::denorm_min();
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {
      {"baseline", [](Scene&) {}, 1, true},
      {"probe_far_1e6_above", [](Scene& s) { s.probe.position = {0, 0, 1e6}; }},
      {"probe_far_1e6_lateral", [](Scene& s) { s.probe.position = {1e6, -1e6, 7}; }},
      {"probe_deep_1e3", [](Scene& s) { s.probe.position.z = 8.0 - 1e3; }, 1, true},
      {"probe_deep_1e3_exact_max", [](Scene& s) { s.probe.position.z = 8.0 - 1e3; s.render.displacement = DisplacementMethod::kExactMax; }, 1, true},
      {"scene_offset_1e5", [](Scene& s) { offset_scene(s, {1e5, 1e5, 1e5}); }},
      {"scene_offset_1e5_tilted", [](Scene& s) { s.surfaces[0].rotation_deg = {25, 10, 0}; offset_scene(s, {-1e5, 1e5, 0}); }},
      {"speed_zero", [](Scene& s) { s.probe.velocity = {0, 0, 0}; }},
      {"speed_denormal", [=](Scene& s) { s.probe.velocity = {denorm, denorm, 0}; }},
      {"speed_huge", [](Scene& s) { s.probe.velocity = {1e300, -1e300, 0}; }},
      {"speed_infinite", [=](Scene& s) { s.probe.velocity = {inf, 0, 0}; }},
      {"speed_nan", [=](Scene& s) { s.probe.velocity = {nan, 0, 0}; }},
      {"lambda_tiny", [](Scene& s) { gab(s).lambda_min_mm = gab(s).lambda_max_mm = 1e-6; }},
      {"lambda_huge", [](Scene& s) { gab(s).lambda_min_mm = gab(s).lambda_max_mm = 1e6; }},
      {"lambda_range_wide", [](Scene& s) { gab(s).lambda_min_mm = 1e-4; gab(s).lambda_max_mm = 1e4; }},
      {"n_zero", [](Scene& s) { gab(s).n_min = gab(s).n_max = 0; }},
      {"n_huge_capped", [](Scene& s) { gab(s).n_min = gab(s).n_max = 1e9; }},
      {"amplitude_zero", [](Scene& s) { gab(s).a_min = gab(s).a_max = 0; }},
      {"amplitude_signed", [](Scene& s) { gab(s).a_min = -1; gab(s).a_max = 1; }},
      {"theta_empty", [](Scene& s) { gab(s).theta_min_rad = gab(s).theta_max_rad = 0.7; }},
      {"theta_full", [](Scene& s) { gab(s).theta_min_rad = 0; gab(s).theta_max_rad = 2 * kPi; }},
      {"theta_reversed", [](Scene& s) { gab(s).theta_min_rad = 2.0; gab(s).theta_max_rad = -1.0; }},
      {"kernel_periods_zero", [](Scene& s) { gab(s).kernel_periods = 0; }},
      {"truncation_one", [](Scene& s) { gab(s).truncation = 1.0; }},
      {"resistance_zero", [](Scene& s) { mat(s).resistance = 0; }},
      {"resistance_one_exact", [](Scene& s) { mat(s).resistance = 1; s.render.displacement = DisplacementMethod::kExactMax; }, 1, true},
      {"resistance_above_one", [](Scene& s) { mat(s).resistance = 3; }, 1, true},
      {"sheet_edge_on", sheet_edge_on},
      {"sphere_from_inside", inside_sphere},
      {"probe_touching_d0", [](Scene& s) { s.probe.position.z = 8.0; }},
      {"weights_overflow_c40", [](Scene& s) { s.probe.position.z = 8.0 - 200; s.render.weight_exponent = 40; }, 1, true},
      {"weights_c_1e4", [](Scene& s) { s.probe.position.z = 8.0 - 5; s.render.weight_exponent = 1e4; }, 1, true},
      {"intensity_offset_zero", [](Scene& s) { mat(s).intensity_offset_mm = 0; s.probe.position.z = 8.0 + 1e-30; }},
      {"influence_zero", [](Scene& s) { mat(s).influence_distance_mm = 0; }},
      {"probe_radius_tiny", [](Scene& s) { s.probe.radius_mm = 1e-6; s.probe.position.z = 0; }},
      {"probe_radius_huge", [](Scene& s) { s.probe.radius_mm = 1e5; s.probe.position.z = 1e5 - 1; }},
      {"capsule_zero_length", [](Scene& s) { s.probe.shape = ProbeShape::kCapsule; s.probe.length_mm = 0; }},
      {"capsule_zero_axis", [](Scene& s) { s.probe.shape = ProbeShape::kCapsule; s.probe.axis = {0, 0, 0}; }},
      {"depth_map_16_min", [](Scene& s) { s.render.depth_map_size = 16; }},
      {"image_1x1", [](Scene& s) { s.render.width = s.render.height = 1; }},
      {"frames_20_weighted_contact", [](Scene& s) { s.probe.position.z = 2.0; }, 20},
  };
}

}  // namespace

const std::vector<StressCase>& stress_cases() {
  static const std::vector<StressCase> cases = make_cases();
  return cases;
}

}  // namespace ps::test
