// The scene's [[buttons]] on the haptic side (A Virtual Universe §2; docs/haptics.md, "Buttons"): a
// flush button is a rectangle of the face it sits in that gives way. Its geometry (ButtonShape)
// makes a hole in that face with a pocket behind it, travel x 1.5 deep, whose walls and bottom are
// solid (HapticScene::closest). Its state (ButtonSet, on the haptic thread) pushes the probe
// back out with the button's own spring while the probe presses it in, and at `travel_mm`
// stops pushing and fires, once: it re-arms only when the probe has left the button.
// No allocation after construction.
#pragma once

#include <array>
#include <cstdint>
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
  glm::dvec3 force_n{0.0};           // the buttons' springs on the probe (pressed or held flush)
  std::array<int, kMaxButtons> fired{};
  int fired_count = 0;
  int pressed = -1;                  // the button the probe presses now (-1: none)
  double depth_mm = 0.0;             // and how far
};

// A press counts only when the probe comes at the button's face from the front (Sandia's
// push), never when it arrives sideways already below the face (a slide across the wall with
// the hand pressed in) or was already there when the scene began (a switch or the start with
// the probe sunk): such a button is held flush instead, and is ready for a press once the probe
// has left it, sideways or lifted clear of its face, or once the hand pushes on from where it is
// held (kHeldPushMm: PageDown on a probe resting flush on it; not after a switch, kLeaveFirst).
enum class ButtonPhase : std::uint8_t {
  kIdle,      // not ready: the probe is away, or came in without approaching the face
  kReady,     // the probe is over the face and clear of it: the next push is a press
  kPressing,  // pushed in from kReady: the button's spring, fires at the travel
  kFired,     // gave way: no force until the probe is back out of it
  // After a scene switch: held like kIdle until the hand has left the button sideways. Lifting
  // is not enough here: for a frame or more after a switch the hand may still be mapped through
  // the old scene's camera and plane, and the proxy starts where the old scene left it.
  kLeaveFirst,
};

// How far above the face the probe's lowest point must be for the face to count as approached
// (the proxy's and the hand's, ButtonSet::step):
// a probe resting on the face (the god-object holds it within 1e-6 mm) has not left it, one
// lifted by a quarter of a height step (0.5 mm) has.
inline constexpr double kButtonClearMm = 0.25;
// A held button is pressed when the hand goes this much deeper than the shallowest it has been
// since the hold began (PageDown, or a push on a device): a press from where it is held, as from
// kReady. Half a height step (0.5 mm): one PageDown counts on a face within 60 degrees of the
// pointer's plane (the step along the face's normal is 0.5 cos a), while a hand resting or sliding
// at one height (the mouse's hovers at the same height over a flush face) never does.
inline constexpr double kHeldPushMm = 0.25;
// A held button gives way by this share of the hand's depth (0.1 mm for a hand 4.5 mm in): flush
// to the eye. Its force is taken from the hand's depth, not the proxy's, so it is stable however
// stiff (a spring on the proxy stiffer than the coupling would oscillate).
inline constexpr double kHeldShare = 0.02;

class ButtonSet {
 public:
  ButtonSet() = default;
  // coupling_n_per_mm: the virtual coupling between hand and proxy (HapticsParams), which sets
  // the force that holds a button flush.
  // after_switch: the scene was switched to (not opened at start): every button starts in
  // kLeaveFirst.
  ButtonSet(const std::vector<ButtonShape>& shapes, double probe_radius_mm, double coupling_n_per_mm = 0.5,
            bool after_switch = false);

  // One tick with the probe (the proxy) at proxy_mm and the hand at hand_mm. A button pressed
  // from kReady pushes back with F = k depth n while 0 < depth < travel; at depth >= travel it
  // fires (in fired[]), its force stops, and it is ready again once the depth is back to <= 0
  // or the probe has left it. A button the probe is in without having approached it is held
  // flush (ButtonPhase) until the hand pushes kHeldPushMm deeper than the shallowest it has been
  // while held: that push is a press from there, which fires once at the travel. After a switch
  // (kLeaveFirst) it is held until the hand has left it sideways, however deep it goes.
  ButtonStepResult step(const glm::dvec3& proxy_mm, const glm::dvec3& hand_mm);
  ButtonStepResult step(const glm::dvec3& proxy_mm) { return step(proxy_mm, proxy_mm); }
  std::size_t size() const { return shapes_.size(); }
  ButtonPhase phase(std::size_t i) const { return phase_[i]; }
  bool armed(std::size_t i) const { return phase_[i] == ButtonPhase::kReady || phase_[i] == ButtonPhase::kPressing; }

 private:
  std::vector<ButtonShape> shapes_;
  // One button's tick (step()): its phase, force and firing into r.
  void step_button(std::size_t i, const glm::dvec3& proxy_mm, const glm::dvec3& hand_mm, ButtonStepResult& r);
  // Button i holds a probe that came in without an approach flush (its force into r), until the
  // hand goes kHeldPushMm deeper than the shallowest it has been held at (kIdle only): false, a
  // press from here.
  bool hold(std::size_t i, double hand_depth, const glm::dvec3& hand_mm, ButtonStepResult& r);

  std::array<ButtonPhase, kMaxButtons> phase_{};  // all kIdle: nothing fires before an approach
  // While held (kIdle or kLeaveFirst with the probe in): the shallowest hand depth since the hold
  // began; infinity while not held.
  std::array<double, kMaxButtons> held_from_mm_{};
  double radius_mm_ = 0.0;
  double coupling_n_per_mm_ = 0.5;
};

// How deep the hand must go below a button's face for the proxy to reach its travel through the
// coupling: the proxy goes in by k_c / (k_c + k) of the hand's depth, so travel (k_c + k) / k_c
// (4.2 mm for the defaults). Zero without buttons. The height control must reach this deep.
double deepest_press_mm(const std::vector<ButtonShape>& shapes, double coupling_n_per_mm);

}  // namespace ps::world
