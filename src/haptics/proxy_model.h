// The proxy model of the haptic loop (haptic thread): where the probe is drawn and what force the
// hand feels, given the filtered hand. One interface, two implementations, chosen once per scene:
//   GodObjectProxy  the god-object in the haptic scene (docs/haptics.md, "Haptic geometry"):
//                   compute_proxy_force, with the effects' force on the probe as its coupling;
//   PlaneProxy      no haptic scene: the render thread's local plane (Snapshot<SurfaceModel>),
//                   compute_force (kept for callers with no scene: the plane-model tests).
#pragma once

#include <glm/glm.hpp>

#include "core/snapshot.h"
#include "haptics/force_model.h"
#include "world/god_object.h"

namespace ps {

class ProxyModel {
 public:
  virtual ~ProxyModel() = default;
  // One tick: the hand at x_mm moving at v_mm_s (world), session time t; on_probe_n is the force
  // the scene's effects put on the probe (N, world; the plane model has none).
  virtual ForceResult step(const HapticsParams& p, const glm::dvec3& x_mm, const glm::dvec3& v_mm_s, double t,
                           const glm::dvec3& on_probe_n) = 0;
  // The proxy starts over at `at_mm` (the hand placed there, or kept through a scene switch).
  virtual void place(const glm::dvec3& at_mm) = 0;
  virtual double probe_radius_mm() const = 0;
  // The sheet of a surface embedded in 4D the proxy keeps to: its surface index and 4D depth.
  virtual bool sheet(int& surface, double& w4) const = 0;
};

class GodObjectProxy final : public ProxyModel {
 public:
  explicit GodObjectProxy(const world::HapticScene& scene) : god_(scene) {}
  ForceResult step(const HapticsParams& p, const glm::dvec3& x_mm, const glm::dvec3& v_mm_s, double t,
                   const glm::dvec3& on_probe_n) override {
    return compute_proxy_force(p, god_, x_mm, v_mm_s, t, on_probe_n);
  }
  void place(const glm::dvec3& at_mm) override { god_.reset(at_mm); }
  double probe_radius_mm() const override { return god_.scene().probe_radius_mm(); }
  bool sheet(int& surface, double& w4) const override { return god_.sheet(surface, w4); }
  const world::GodObject& god() const { return god_; }

 private:
  world::GodObject god_;  // holds no heap memory: a scene switch frees nothing on the haptic thread
};

class PlaneProxy final : public ProxyModel {
 public:
  explicit PlaneProxy(const Snapshot<SurfaceModel>& surface) : surface_(surface) {}
  ForceResult step(const HapticsParams& p, const glm::dvec3& x_mm, const glm::dvec3& v_mm_s, double t,
                   const glm::dvec3&) override {
    const ForceResult f = compute_force(p, surface_.read(), x_mm, v_mm_s, proxy_mm_, t);
    proxy_mm_ = f.proxy_mm;
    return f;
  }
  void place(const glm::dvec3& at_mm) override { proxy_mm_ = at_mm; }
  double probe_radius_mm() const override { return surface_.read().probe_radius_mm; }
  bool sheet(int&, double&) const override { return false; }

 private:
  const Snapshot<SurfaceModel>& surface_;  // the render thread's, newest at each read
  glm::dvec3 proxy_mm_{0.0};               // the previous tick's: friction's stick point
};

}  // namespace ps
