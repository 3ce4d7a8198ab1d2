// What a scene shows of its haptic world besides its surfaces and bodies (issue "The Virtual
// Universe": "show what people would rather look at than feel"): each charge as a small ball,
// red when it pushes the probe away (q > 0) and blue when it pulls (q < 0); each body's band
// from the probe to the body; the force the fields put on the probe as an arrow from the probe
// (20 mm per newton). Drawn from FrameInput::markers over the image, colour only, like the
// bodies. Scene-only: `replay`/`run` pass the haptic state's probe, bodies, live charges and force.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ps {

struct WorldMarker {
  glm::dvec3 a{0.0}, b{0.0};  // a capsule from a to b (a == b: a ball), world mm
  double radius_mm = 1.0;
  glm::dvec3 color{1.0};      // linear rgb
};

struct ChargeMarker {
  glm::dvec3 position{0.0};
  double charge_n_mm2 = 0.0;
};

inline constexpr double kArrowMmPerN = 20.0;
inline constexpr double kChargeMarkerRadiusMm = 3.0;
inline constexpr double kBandRadiusMm = 0.6;

// `extra_charges`: charges beyond the scene's own (run's live ones). `force_n`: the fields' force
// on the probe (no arrow below 0.01 N, and none in a scene without charges: the arrow shows what
// charges do to the probe; a uniform or viscous field alone, as over a maze's cue room, is felt
// and not drawn, tests/maze/maze_gl_test.cpp).
std::vector<WorldMarker> world_markers(const Scene& scene, const glm::dvec3& probe_mm,
                                       std::span<const glm::dvec3> bodies_mm,
                                       std::span<const ChargeMarker> extra_charges = {},
                                       const glm::dvec3& force_n = glm::dvec3(0.0));

// Where the probe is drawn when it is felt at `felt_mm` (A Virtual Universe §3, "Illusion"): near a
// surface with a visual_stretch (within its felt bounding radius + the probe's radius + 10 mm) the
// position is stretched like the surface, about its centre along its local axes, so the drawn
// probe travels the drawn (stretched) shape while the hand travels the felt one; the stretch
// fades out linearly over the next 20 mm. The first stretched surface near the probe counts.
// No stretched surface: `felt_mm` unchanged.
glm::dvec3 visual_position(const Scene& scene, const glm::dvec3& felt_mm);
inline constexpr double kStretchReachMarginMm = 10.0, kStretchFadeMm = 20.0;

// The rolling manifold's rubber band (Hanson & Zhang §6.4, docs/fourd.md): from the probe to the
// nearest point of the line of sight through the screen centre of `camera` (the world camera a
// frame draws with), the line the tether pulls toward; a == b when the probe is on that line.
// Drawn so a mouse, which feels no force, still sees the band.
WorldMarker rubber_band_marker(const glm::dvec3& probe_mm, const Camera& camera);
inline constexpr double kRubberBandRadiusMm = 0.35;

// The bodies where the scene starts them (Body::position): what `render` shows.
std::vector<glm::dvec3> start_positions(const Scene& scene);

}  // namespace ps
