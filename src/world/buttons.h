// The scene's [[buttons]] on the haptic side (seed 002 §2; docs/haptics.md, "Buttons"): a flush
// button is a rectangle of the face it sits in that gives way. Its geometry (ButtonShape) makes
// a hole in that face with a pocket behind it, travel x 1.5 deep, whose walls and bottom are
// solid (HapticScene::closest). Its state (ButtonSet, on the haptic thread) pushes the probe
// back out with the button's own spring while the probe presses it in, and at `travel_mm`
// stops pushing and fires, once: it re-arms only when the probe has left the button.
// No allocation after construction.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "world/shapes.h"

namespace ps::world {

inline constexpr int kMaxButtons = kMaxSceneButtons;
// The pocket behind a button is this many times its travel deep: a fired button bottoms out
// there, a little past the point where it gave way.
inline constexpr double kPocketDepthPerTravel = 1.5;

struct ButtonShape {
  glm::dmat3 rotation{1.0};  // local -> world; local +Z is the outward normal
  glm::dvec3 center{0.0};    // face centre
  glm::dvec2 half{0.0};      // half extents along local X, Y
  double pocket_mm = 0.0;    // depth of the pocket's bottom below the face
  double stiffness_n_per_mm = 0.0;
  double travel_mm = 0.0;
  int surface = -1;          // the button's plate (Scene::surfaces index): material and events

  static ButtonShape make(const Button& b, int plate_surface);
  glm::dvec3 normal() const { return rotation[2]; }
  glm::dvec3 to_local(const glm::dvec3& p) const { return glm::transpose(rotation) * (p - center); }
  // p's projection onto the face plane falls inside the button (strictly).
  bool over(const glm::dvec3& local) const { return std::abs(local.x) < half.x && std::abs(local.y) < half.y; }
  // A surface point that lies in the hole: on the face plane (within 1e-6 mm) inside the rectangle
  // or on its edge. HapticScene drops such contacts of the surface the button sits in.
  bool in_hole(const glm::dvec3& local_point) const;
  // Closest point on the pocket (four walls from the face down to the bottom, and the bottom)
  // to a point `local` over the button, in the local frame; the normal faces into the pocket.
  SurfacePoint pocket_closest(const glm::dvec3& local) const;
  // How far a probe sphere of radius r centred at p is pressed into the button: r minus the
  // centre's height above the face, when p is over the button; <= 0 when not pressed.
  double press_depth_mm(const glm::dvec3& p, double r) const;
};

struct ButtonStepResult {
  glm::dvec3 force_n{0.0};           // the pressed buttons' springs on the probe
  std::array<int, kMaxButtons> fired{};
  int fired_count = 0;
  int pressed = -1;                  // the button the probe presses now (-1: none)
  double depth_mm = 0.0;             // and how far
};

class ButtonSet {
 public:
  ButtonSet() = default;
  ButtonSet(const std::vector<ButtonShape>& shapes, double probe_radius_mm);

  // One tick with the probe (the proxy) at proxy_mm: F = k depth n while an armed button is
  // pressed by 0 < depth < travel; at depth >= travel it fires (in fired[]) and its force
  // stops; it re-arms when the depth is back to <= 0 or the probe is no longer over it.
  ButtonStepResult step(const glm::dvec3& proxy_mm);
  std::size_t size() const { return shapes_.size(); }
  bool armed(std::size_t i) const { return armed_[i]; }

 private:
  std::vector<ButtonShape> shapes_;
  std::array<bool, kMaxButtons> armed_{};
  double radius_mm_ = 0.0;
};

}  // namespace ps::world
