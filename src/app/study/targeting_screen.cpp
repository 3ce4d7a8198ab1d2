#include "app/study/targeting_screen.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "app/session/session.h"
#include "app/window/live_window.h"
#include "app/window/text_box.h"
#include "devices/glfw_input.h"
#include "haptics/session_driver.h"
#include "prepare/prepare.h"
#include "scene/scene_io.h"
#include "world/haptic_scene.h"

namespace ps {

namespace {

// Ticks the selection feed holds between two frames: 16 s at 1 kHz (a frame takes tens of
// milliseconds on llvmpipe; a loop switch or a stall longer than that loses ticks, and a touch
// in them is missed rather than misplaced).
constexpr std::size_t kFeedTicks = std::size_t{1} << 14;

glm::dvec3 vec(const study::Point3& p) { return {p.x, p.y, p.z}; }
glm::dvec3 vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
study::Point3 as_point(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

// Where a contact point lies on the ring's plane (the selection's place).
study::Point3 on_ring_plane(const study::Ring& ring, const glm::dvec3& p) {
  const glm::dvec3 c = vec(ring.centre), n = vec(ring.normal);
  const glm::dvec3 q = p - glm::dot(p - c, n) * n;
  return {q.x, q.y, q.z};
}

// A target's outline: its circle on the ring's plane, in the world and projected into the window.
struct Outline {
  std::vector<glm::dvec3> world;
  std::vector<ImVec2> window;
  glm::dvec3 centre{0.0};
};

Outline outline(const PointerView& view, const study::Ring& ring, int index, double width_mm) {
  Outline o;
  o.centre = vec(study::target_centre(ring, index));
  const glm::dvec3 u = vec(ring.u), v = vec(ring.v);
  constexpr int kSegments = 40;
  for (int i = 0; i < kSegments; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kSegments;
    o.world.push_back(o.centre + 0.5 * width_mm * (std::cos(a) * u + std::sin(a) * v));
    const glm::dvec2 w = project_to_window(view, o.world.back());
    o.window.emplace_back(static_cast<float>(w.x), static_cast<float>(w.y));
  }
  return o;
}

}  // namespace

TargetingScreen::TargetingScreen(const study::Experiment& e, LiveWindow& win, HeightInput& height)
    : e_(e), win_(win), height_(height) {}

TargetingScreen::~TargetingScreen() {
  if (loop_) loop_->loop().stop();
}

Result<std::unique_ptr<TargetingScreen>> TargetingScreen::open(const study::Experiment& e, LiveWindow& win,
                                                               HeightInput& height, const DeviceSpec& device) {
  if (Status s = win.open_device(device); !s) return s.error();
  // Only the condition's feedback shows where the probe is: the pointer is hidden over the window.
  glfwSetInputMode(win.glfw(), GLFW_CURSOR, GLFW_CURSOR_HIDDEN);
  return std::unique_ptr<TargetingScreen>(new TargetingScreen(e, win, height));
}

Status TargetingScreen::use_condition(int condition) {
  if (condition == condition_) return ok_status();
  if (loop_) loop_->loop().stop();
  loop_.reset();
  const study::Variant& c = e_.conditions[static_cast<std::size_t>(condition)];
  Result<Scene> scene = load_scene(e_.scene, study::condition_overrides(e_, c));
  if (!scene) return scene.error();
  auto r = open_renderer(std::move(scene.value()), RendererOptions{});
  if (!r) return r.error();
  renderer_ = std::move(r.value());
  auto haptic = world::HapticScene::build(renderer_->scene());
  if (!haptic) return haptic.error();
  haptic_ = std::make_shared<const world::HapticScene>(std::move(haptic.value()));
  axes_ = pointer_plane(*renderer_);
  loop_ = std::make_unique<RecordedLoop>(win_.device(), clock_, HapticLoopParams{}, haptic_, "", kFeedTicks);
  loop_->loop().surface().publish(initial_surface_model(axes_, renderer_->probe().radius_mm));
  poll_device();  // the first tick already has a sample
  loop_->loop().start();
  condition_ = condition;
  selector_ = study::TouchSelector();
  last_.reset();  // a new condition's ring starts with a touch
  return ok_status();
}

void TargetingScreen::poll_device() {
  GlfwInputDevice* const device = win_.input();
  if (!device) return;
  device->add_height_steps(std::exchange(height_.steps, 0));
  device->add_scroll(std::exchange(height_.scroll, 0.0));
  const PointerView view = pointer_view(*renderer_, axes_, glm::dvec2(win_.window_size()));
  device->poll(loop_ ? loop_->loop().state().read().time_s : 0.0, view);
}

std::optional<TargetingScreen::Selection> TargetingScreen::take_selection() {
  const study::Ring ring = study::make_ring(e_.targeting, 1.0);  // its plane: the centre and normal
  const glm::dvec3 c = vec(ring.centre), n = vec(ring.normal);
  const double radius = renderer_->probe().radius_mm;
  std::optional<Selection> first;
  loop_->feed()->drain([&](const TickSample& s) {
    const double gap = glm::dot(s.proxy_centre_mm - c, n) - radius;
    if (selector_.tick(s.time_s, s.in_contact, gap) && !first) first = Selection{on_ring_plane(ring, s.proxy_mm), s.time_s};
  });
  return first;
}

void TargetingScreen::draw(const study::TrialStimulus& t, const std::string& text) {
  win_.begin_frame_on_black();
  const ImVec2 d = ImGui::GetIO().DisplaySize;
  win_.draw_frame_image(*renderer_, UiRect{0.f, 0.f, d.x, d.y});
  const PointerView view = pointer_view(*renderer_, axes_, glm::dvec2(win_.window_size()));
  const study::Ring ring = study::make_ring(e_.targeting, t.ring_diameter);
  ImDrawList* dl = ImGui::GetBackgroundDrawList();  // over the picture, under the text
  // The probe drawn opaque (render.draw_probe) hides what is behind it: its bounding sphere, where
  // the frame drew it (after its displacement).
  const bool probe_drawn = renderer_->scene().render.draw_probe;
  const study::Point3 eye = as_point(view.camera.position), probe = as_point(renderer_->stats().probe_position);
  const double radius = renderer_->probe().radius_mm;
  const auto visible = [&](const glm::dvec3& p) { return !probe_drawn || !study::hidden_by_sphere(eye, as_point(p), probe, radius); };
  for (int i = 0; i < ring.targets; ++i) {
    const Outline o = outline(view, ring, i, t.width);
    const std::size_t n = o.world.size();
    const bool start = !last_ && i == t.from, goal = last_ && i == t.to;
    const glm::dvec2 cw = project_to_window(view, o.centre);
    const ImVec2 c(static_cast<float>(cw.x), static_cast<float>(cw.y));
    // Translucent fills, so the feedback under a target stays visible; a fan of triangles, each
    // left out where the probe hides a corner of it.
    const ImU32 fill = start ? IM_COL32(60, 200, 90, 110) : IM_COL32(255, 150, 30, 110);
    const ImU32 line = start ? IM_COL32(60, 220, 90, 255) : goal ? IM_COL32(255, 160, 40, 255) : IM_COL32(230, 230, 230, 170);
    std::vector<bool> seen(n);
    const bool centre_seen = visible(o.centre);
    bool all = centre_seen;
    for (std::size_t k = 0; k < n; ++k) all &= (seen[k] = visible(o.world[k]));
    if ((start || goal) && all) dl->AddConvexPolyFilled(o.window.data(), static_cast<int>(n), fill);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t next = (k + 1) % n;
      if (!seen[k] || !seen[next]) continue;
      if ((start || goal) && !all && centre_seen) dl->AddTriangleFilled(c, o.window[k], o.window[next], fill);
      dl->AddLine(o.window[k], o.window[next], line, start || goal ? 2.0f : 1.0f);
    }
  }
  draw_text_box("study", ImVec2(10, 10), text, 1.0f);
  win_.end_frame();
}

Result<std::optional<study::Pointed>> TargetingScreen::point(const study::TrialStimulus& t, const std::string& head,
                                                             const std::string& title,
                                                             const std::function<bool()>& stopping) {
  if (Status s = use_condition(t.condition); !s) return s.error();
  if (t.step == 0) last_.reset();  // a new ring: it starts with a touch
  std::string shown;
  for (;;) {
    win_.poll_events();
    if (stopping()) return std::optional<study::Pointed>();
    poll_device();
    if (std::optional<Selection> s = take_selection()) {
      if (last_) {
        const study::Pointed made{last_->at, s->at, s->time_s - last_->time_s};
        last_ = s;
        return std::optional<study::Pointed>(made);
      }
      last_ = s;  // the ring's start: the clock runs from here
    }
    if (const std::string now = title + (last_ ? ", touch the target" : ", touch to start"); now != shown)
      win_.set_title(shown = now);
    HapticState st;
    if (Status s = drive_frame(*renderer_, loop_->loop(), frame_++, st); !s) return s.error();
    draw(t, head + (last_ ? "Touch the orange target." : "Touch the green target to start the ring.") +
                (win_.input() && win_.input()->kind() == GlfwInputDevice::Kind::kGamepad
                    ? "\nThe left stick moves the probe; the triggers lift and lower it."
                    : "\nMove with the mouse; the wheel or PageUp/PageDown lift and lower the probe."));
  }
}

}  // namespace ps
