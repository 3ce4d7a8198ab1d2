#include "haptics/workspace.h"

#include "haptics/haptic_state.h"
#include "world/god_object.h"

namespace ps {

namespace {

// Whether `p` (world) lies over one of the scene's buttons: within its rectangle, at any height.
bool over_a_button(const world::HapticScene& scene, const glm::dvec3& p) {
  for (const world::ButtonShape& b : scene.button_shapes())
    if (b.over(b.to_local(p))) return true;
  return false;
}

}  // namespace

void Workspace::restart(const world::HapticScene* scene) {
  scene_ = scene;
  home();
}

void Workspace::home() {
  view_ = fourd::ViewPose{};
  roll_.reset();
}

glm::dvec3 Workspace::navigate(const glm::dvec3& device_mm, double dt, HapticState& s, bool travel) {
  // Every tick publishes this scene's pose, also where nothing moves it: a scene without
  // [navigation] or a rolling surface must not show the pose the last scene left in the state
  // (Field's -90 mm drawn under the panel), and Home must reach the state there too.
  s.view_offset_mm = view_.offset;
  s.view_rotation = view_.rotation;
  if (scene_ == nullptr) return glm::dvec3(0.0);
  const Navigation& nav = scene_->navigation();
  if (!nav.enabled && !scene_->any_fourd_roll()) return glm::dvec3(0.0);  // workspace = world
  const glm::dvec3 hand = s.position_mm;  // workspace
  glm::dvec3 v(0.0), wall(0.0);
  if (nav.enabled) {
    // A rate control with the box as its dead zone, on the device's own position: the Kalman
    // filter overshoots a step (a mouse jumping from the window's edge back to its centre), and
    // the view must stop when the hand is back inside, not travel on (38 mm back in `run`).
    const glm::dvec3 half = 0.5 * nav.box_size_mm;
    glm::dvec3 past = device_mm - glm::clamp(device_mm, nav.box_center - half, nav.box_center + half);
    // Over a button (Field's back button lies beyond the box's wall): neither wall nor travel,
    // so the probe reaches the button and the view stays while the person aims at it.
    if (over_a_button(*scene_, view_.to_world(device_mm))) past = glm::dvec3(0.0);
    // Held (the pointer out of the window, the window unfocused): the walls still push, the
    // view stays; a mouse parked past a wall is no push of the person's.
    if (travel) v = nav.speed_mm_s_per_mm * past;
    const double speed = glm::length(v);
    if (speed > nav.max_speed_mm_s) v *= nav.max_speed_mm_s / speed;
    view_.offset += view_.rotation * v * dt;
    wall = -nav.wall_n_per_mm * past;
  }
  s.view_offset_mm = view_.offset;
  s.view_rotation = view_.rotation;
  s.position_mm = view_.to_world(hand);
  s.device_mm = view_.to_world(device_mm);
  // The hand's speed over the world: the texture sees the craft move.
  s.velocity_mm_s = view_.rotation * (s.velocity_mm_s + v);
  return view_.rotation * wall;
}

bool Workspace::roll(const world::GodObject* god, const Snapshot<PublishedViewAxes>& published, double dt,
                     HapticState& s, glm::dvec3& tether_n) {
  if (scene_ == nullptr || god == nullptr) return false;
  tether_n = glm::dvec3(0.0);
  if (!scene_->any_fourd_roll()) return true;
  const world::Contact* c = god->sheet_contact();
  const fourd::RollParams p = c != nullptr ? scene_->fourd_roll(c->surface) : fourd::RollParams{};
  fourd::RollContact rc;
  if (c != nullptr && p.on) {
    rc.on_sheet = true;
    rc.facet = c->fourd_facet;
    rc.point = c->point;
    rc.normal = c->normal;
    rc.hand_at_rest = glm::length(s.velocity_mm_s) < fourd::kRollRestMmS;
  }
  const PublishedViewAxes camera = published.read();
  const fourd::ViewAxes& axes = camera.valid ? camera.axes : scene_->view_axes();
  roll_.step(p, axes, rc, dt, view_);
  s.view_offset_mm = view_.offset;
  s.view_rotation = view_.rotation;
  s.roll_facet = roll_.facet();
  if (rc.on_sheet) tether_n = fourd::RollingManifold::tether_force(p, axes, view_, s.proxy_mm);
  return true;
}

}  // namespace ps
