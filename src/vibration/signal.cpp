#include "vibration/signal.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/modulation.h"

namespace ps::vibration {

SignalModel::SignalModel(const Scene& scene, const SignalParams& params)
    : params_(params), seed_(scene.render.seed) {
  surfaces_.reserve(scene.surfaces.size());
  for (const Surface& surface : scene.surfaces) {
    SurfaceTexture t;
    const auto m = static_cast<std::size_t>(surface.material_index);
    if (m < scene.materials.size()) {
      t.material = scene.materials[m];
      t.gain = t.material.vibration_gain;
      t.textured = t.material.textured && t.gain > 0.0;
      t.setup = make_gabor_setup(t.material.gabor);
      const double a = t.material.gabor.a_min, b = t.material.gabor.a_max;
      const double a_rms = std::sqrt((a * a + a * b + b * b) / 3.0);  // A ~ U[a_min, a_max]
      t.sigma = std::max(1e-12, t.setup.sigma_unit * a_rms);
    }
    surfaces_.push_back(std::move(t));
  }
}

const SurfaceTexture* SignalModel::surface(int index) const {
  if (index < 0 || static_cast<std::size_t>(index) >= surfaces_.size()) return nullptr;
  return &surfaces_[static_cast<std::size_t>(index)];
}

double SignalModel::texture_value(const SurfaceTexture& s, double u, double v) const {
  const double noise = gabor_noise(s.material.gabor, s.setup, seed_, u, v);
  return std::clamp(noise / (params_.clip_sigmas * s.sigma), -1.0, 1.0);
}

double SignalModel::amplitude(const SurfaceTexture& s, const PlaneFrame& frame, double force_n,
                              const glm::dvec3& velocity_mm_s) const {
  if (!s.textured) return 0.0;
  const glm::dvec3 tangential = velocity_mm_s - glm::dot(velocity_mm_s, frame.n) * frame.n;
  const double v2 = glm::dot(tangential, tangential);
  const double rest2 = params_.rest_speed_mm_s * params_.rest_speed_mm_s;
  const double moving = v2 > 0.0 ? v2 / (v2 + rest2) : 0.0;
  const double force = 1.0 - std::exp(-std::max(0.0, force_n) / params_.force_ref_n);
  return s.gain * params_.texture_peak * force * speed_gain(s.material, frame, tangential) * moving;
}

SignalSynth::SignalSynth(std::shared_ptr<const SignalModel> model) : model_(std::move(model)) {}

void SignalSynth::set_model(std::shared_ptr<const SignalModel> model) {
  model_ = std::move(model);
  have_prev_ = false;  // surface indices of the old scene mean nothing in the new one
  prev_amp_ = 0.0;
}

void SignalSynth::start_transients(const TickSample& s, const SurfaceTexture* tex, std::uint64_t at) {
  const SignalParams& p = model_->params();
  const double rate = p.sample_rate_hz;
  const double gain = tex != nullptr ? tex->gain : 1.0;  // a click off every surface still clicks
  if (s.impact_mm_s > 0.0 && tex != nullptr && gain > 0.0) {
    const double peak = gain * p.impact_max * (1.0 - std::exp(-s.impact_mm_s / p.impact_ref_mm_s));
    transients_.push_back({peak, p.impact_hz, p.impact_decay_s, at,
                           static_cast<std::uint64_t>(std::llround(p.impact_length_s * rate))});
  }
  if (s.click && gain > 0.0)
    transients_.push_back({gain * p.click_peak, p.click_hz, p.click_decay_s, at,
                           static_cast<std::uint64_t>(std::llround(p.click_length_s * rate))});
}

// A cosine under an exponential decay: at full level on its first sample (the tick's), like
// the event sounds (audio/synth.h).
double SignalSynth::transient_sum(std::uint64_t index) {
  const double rate = model_->params().sample_rate_hz;
  double sum = 0.0;
  for (const Transient& t : transients_) {
    if (index < t.start || index >= t.start + t.length) continue;
    const double time = static_cast<double>(index - t.start) / rate;
    sum += t.peak * std::exp(-time / t.decay_s) * std::cos(2.0 * std::numbers::pi * t.hz * time);
  }
  return sum;
}

void SignalSynth::add_tick(const TickSample& s, std::vector<float>& out) {
  const double rate = model_->params().sample_rate_hz;
  const auto target = static_cast<std::uint64_t>(std::llround(std::max(0.0, s.time_s) * rate));
  if (target < next_sample_) return;  // not after the last tick: nothing new to say
  const SurfaceTexture* tex = s.in_contact ? model_->surface(s.surface) : nullptr;
  const bool segment = have_prev_ && s.tick == prev_.tick + 1 && tex != nullptr && prev_.in_contact &&
                       prev_.surface == s.surface && s.time_s > prev_.time_s;
  start_transients(s, tex, target);
  const Segment g = segment ? follow(s, *tex) : Segment{};
  if (!segment) point_ = s.proxy_mm;  // a new path starts at the contact point
  const double span = static_cast<double>(target) - g.from;
  for (std::uint64_t i = next_sample_; i <= target; ++i) {
    double x = 0.0;
    if (segment && (g.amp0 > 0.0 || g.amp1 > 0.0) && span > 0.0) {
      const double a = std::clamp((static_cast<double>(i) - g.from) / span, 0.0, 1.0);
      const double level = g.amp0 + (g.amp1 - g.amp0) * a;
      x = level * model_->texture_value(*tex, g.u0 + a * (g.u1 - g.u0), g.v0 + a * (g.v1 - g.v0));
    }
    x += transient_sum(i);
    out.push_back(static_cast<float>(x));
  }
  next_sample_ = target + 1;
  std::erase_if(transients_, [this](const Transient& t) { return t.start + t.length <= next_sample_; });
  prev_ = s;
  prev_amp_ = g.amp1;
  have_prev_ = true;
}

// The texture point's step from the previous tick to this one (see the header), and the
// amplitude at its ends.
SignalSynth::Segment SignalSynth::follow(const TickSample& s, const SurfaceTexture& tex) {
  const double rate = model_->params().sample_rate_hz;
  const PlaneFrame frame = make_plane_frame(s.normal);
  const double dt = s.time_s - prev_.time_s;
  const glm::dvec3 along = s.velocity_mm_s - glm::dot(s.velocity_mm_s, frame.n) * frame.n;
  const glm::dvec3 last = point_, predicted = point_ + along * dt;
  const double pull = std::min(1.0, dt / std::max(model_->params().follow_s, 1e-9));
  const glm::dvec3 off = predicted + pull * (s.proxy_mm - predicted) - s.proxy_mm;
  point_ = s.proxy_mm + off - glm::dot(off, frame.n) * frame.n;  // kept on the surface's plane
  Segment g;
  g.amp0 = prev_amp_;
  g.amp1 = model_->amplitude(tex, frame, s.normal_force_n, along);
  g.u0 = glm::dot(last, frame.t), g.v0 = glm::dot(last, frame.b);
  g.u1 = glm::dot(point_, frame.t), g.v1 = glm::dot(point_, frame.b);
  g.from = static_cast<double>(std::llround(prev_.time_s * rate));
  return g;
}

}  // namespace ps::vibration
