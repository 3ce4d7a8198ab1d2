// The vibrotactile signal of the texture under the probe (docs/vibration.md): one definition for
// every output (the live sound channel, the gamepad's rumble, `replay --vibration`'s WAV) and
// for the tests. A pure function of the haptic loop's ticks (haptics/tick_feed.h) and the
// scene: the same ticks give the same samples, bit for bit. No GL; it never waits for a frame.
//
// The model (units: mm, mm/s, N, Hz; samples in full scale [-1, 1]):
//   the texture point follows the contact point: each tick it moves with the hand's velocity
//   along the surface and is pulled toward the contact point with a time constant of
//   follow_s (the proxy slides in stick-slip steps of the friction model, ~0.2 mm every few
//   ticks, which would chop the texture into bursts at the break-away rate; the hand's velocity
//   is smooth, and the pull keeps the point where the proxy is); between two ticks in contact
//   with the same textured surface it moves on a straight line, and the material's Gabor noise
//   (reference/gabor.h, the renderer's texture: plane coordinates (u, v) in the frame of the
//   contact normal, the scene's seed) is evaluated at every audio sample's sub-tick position on
//   that line, so a stroke at speed v across a texture of wavelength lambda at angle phi to its
//   stripes' normal gives a peak at v |cos phi| / lambda, with no aliasing from the tick rate;
//   x = clamp(noise / (clip_sigmas sigma), -1, 1)                    (sigma: the noise's std-dev)
//   amplitude = vibration_gain * texture_peak * (1 - exp(-F / force_ref_n))   (F: normal force)
//             * speed_gain(material, v)      (the renderer's speed modulation, at the hand's speed)
//             * v^2 / (v^2 + rest_speed^2)   (silence at rest: exactly 0 when the point stands)
//   interpolated linearly between ticks (no zipper noise). Out of contact, on an untextured
//   surface or at vibration_gain = 0: 0.
//   Transients, added: a contact start rings a decaying sine whose peak follows the approach
//   speed; a scene button that fires adds a short bright click.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "haptics/tick_feed.h"
#include "reference/basis.h"
#include "reference/gabor.h"
#include "scene/scene.h"

namespace ps::vibration {

struct SignalParams {
  int sample_rate_hz = 48000;
  double tick_rate_hz = 1000.0;     // the haptic loop's rate (48 samples a tick)
  double texture_peak = 0.8;        // texture amplitude at gain 1, full force and speed gain 1
  double clip_sigmas = 3.0;         // the noise's +-3 sigma maps to +-1
  double force_ref_n = 1.0;         // 63 % of the full amplitude at this normal force
  double rest_speed_mm_s = 2.0;     // half the amplitude at this speed along the surface, 0 at rest
  double follow_s = 0.02;           // the texture point's pull toward the contact point
  // Contact start: peak impact_max (1 - exp(-v / impact_ref)), a sine at impact_hz decaying
  // with impact_decay_s, cut after impact_length_s.
  double impact_max = 0.6, impact_ref_mm_s = 60.0, impact_hz = 250.0;
  double impact_decay_s = 0.006, impact_length_s = 0.03;
  // Button click: click_peak, click_hz, decay click_decay_s, cut after click_length_s.
  double click_peak = 0.4, click_hz = 1000.0, click_decay_s = 0.002, click_length_s = 0.012;
};

// What the signal needs of one surface's material.
struct SurfaceTexture {
  bool textured = false;  // a Gabor texture to follow (material textured and gain > 0)
  double gain = 0.0;      // vibration_gain (0: the surface is silent, transients too)
  Material material;      // Gabor parameters, speed modulation
  GaborSetup setup;
  double sigma = 1.0;     // the noise's standard deviation (A included)
};

class SignalModel {
 public:
  explicit SignalModel(const Scene& scene, const SignalParams& params = {});
  const SignalParams& params() const { return params_; }
  std::uint32_t seed() const { return seed_; }
  // Null for an index out of range (a tick of another scene during a switch): silence.
  const SurfaceTexture* surface(int index) const;
  // The texture term at the plane coordinates (u, v), mm: clamp(noise / (clip sigma), -1, 1).
  double texture_value(const SurfaceTexture& s, double u, double v) const;
  // The amplitude of the texture term for a normal force and a path velocity (world, mm/s).
  double amplitude(const SurfaceTexture& s, const PlaneFrame& frame, double force_n,
                   const glm::dvec3& velocity_mm_s) const;

 private:
  SignalParams params_;
  std::uint32_t seed_ = 1;
  std::vector<SurfaceTexture> surfaces_;
};

// Turns ticks into samples. add_tick(s) appends the samples up to and including the one at the
// tick's time: sample index round(time_s * rate); tick k of a 1 kHz loop is sample 48 k. The
// first tick gives the samples from index 0 (zeros before it). A gap (dropped ticks) restarts the
// path: the samples in it are silent.
class SignalSynth {
 public:
  explicit SignalSynth(std::shared_ptr<const SignalModel> model);
  // A new scene (live reload, a button's scene switch): the next tick starts a new path.
  void set_model(std::shared_ptr<const SignalModel> model);
  void add_tick(const TickSample& s, std::vector<float>& out);
  std::uint64_t samples_done() const { return next_sample_; }

 private:
  struct Transient {
    double peak = 0.0, hz = 0.0, decay_s = 1.0;
    std::uint64_t start = 0, length = 0;  // first sample, samples
  };
  struct Segment {
    double amp0 = 0.0, amp1 = 0.0;            // amplitude at the previous tick and at this one
    double u0 = 0.0, v0 = 0.0, u1 = 0.0, v1 = 0.0;  // the texture point's (u, v) there, mm
    double from = 0.0;                        // sample position of the previous tick
  };
  Segment follow(const TickSample& s, const SurfaceTexture& tex);
  void start_transients(const TickSample& s, const SurfaceTexture* tex, std::uint64_t at);
  double transient_sum(std::uint64_t index);
  std::shared_ptr<const SignalModel> model_;
  bool have_prev_ = false;
  TickSample prev_;
  double prev_amp_ = 0.0;
  glm::dvec3 point_{0.0};  // the texture point at the previous tick (on its surface)
  std::uint64_t next_sample_ = 0;
  std::vector<Transient> transients_;  // few at once; finished ones are dropped
};

}  // namespace ps::vibration
