// Adaptive resolution while the view moves (docs/adaptive.md): which scale the next live frame's
// surface pass is drawn at, from the cost of the last frames. Pure CPU, no GL: the window's frame
// loop feeds it each frame's wall time and whether the view moved, and hands the renderer the
// scales it gives (Renderer::set_surface_scale). Headless commands never use it: their frames
// are always drawn whole, at full resolution.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace ps {

struct AdaptiveScaleParams {
  double budget_ms = 16.7;  // the frame time to hold while the view moves (60 frames a second)
  // The scales a moving frame may be drawn at, largest first: each halves the pixels or so of
  // the one before it (0.75^2 = 0.56, 0.5^2 = 0.25, 0.35^2 = 0.12).
  std::vector<double> steps{1.0, 0.75, 0.5, 0.35};
  // How long after the view's last move the frames stay reduced, ms: a mouse drag's events do
  // not come every frame, and a full frame between two moving ones (38 ms at 1280x720 on
  // llvmpipe) would be a stutter. Two frames at 60 a second; the rest frame then comes within
  // 100 ms wherever a whole frame takes under 50 ms (1280x720 on 2-core llvmpipe: 38 ms).
  double rest_ms = 30.0;
  std::size_t window = 5;  // the last full-redraw frames the cost estimate is the median of
  // A step's own measured cost (the median of its last `window` frames within memory_ms) wins
  // over the estimate scaled from other steps: a frame's fixed part (the upsample to the whole
  // image, the footprint's rectangle at full resolution, the reductions) does not shrink with the
  // scale, so scaling by pixels alone would keep a cheap view at the smallest step for good.
  double memory_ms = 1000.0;
  // When the chosen step's measured cost is at most this part of the budget, a frame tries the
  // whole scale, or (whole measured in memory_ms) the step above: the way back up once the view
  // gets cheaper. Whole first, since a reduced frame's upsample can make it dearer than a whole
  // one. A try that misses the budget costs one frame, and is not repeated within memory_ms.
  double probe_fraction = 0.8;
};

// The scale for a frame whose view moves and for one whose view stays (the renderer picks by
// what its frame input did to the camera).
struct SurfaceScale {
  double moving = 1.0;
  double still = 1.0;
  bool operator==(const SurfaceScale&) const = default;
};

class AdaptiveScale {
 public:
  explicit AdaptiveScale(AdaptiveScaleParams params = {});
  // A frame ended at `now_ms`: its wall time, the scale it was drawn at, whether its view moved
  // and whether it redrew every pixel (an incremental frame says nothing about a full one's cost).
  void frame(double now_ms, double frame_ms, double scale, bool view_moved, bool full_redraw);
  // For the next frame: `moving` the largest step whose predicted cost fits the budget (the
  // smallest step when none does; 1 until a full redraw has been measured), or a larger one on a
  // try (AdaptiveScaleParams::probe_fraction); `still` the same within rest_ms of the last
  // move, else 1. A step's predicted cost is its own measured one where it has one in
  // memory_ms, else the whole cost scaled by its pixels.
  SurfaceScale next(double now_ms) const;
  // The cost a full-scale redraw is estimated at now, ms (0: none measured yet).
  double full_cost_ms() const;
  const AdaptiveScaleParams& params() const { return params_; }

 private:
  AdaptiveScaleParams params_;
  struct Measured {
    double at_ms = 0.0, cost_ms = 0.0;
  };
  // The median cost of step i's frames within memory_ms of now; negative when there is none.
  double step_cost_ms(std::size_t i, double now_ms) const;

  std::vector<double> full_costs_;  // per full redraw: its cost divided by its scale squared
  std::size_t next_slot_ = 0;       // ring index into full_costs_
  std::vector<std::vector<Measured>> step_costs_;  // per step: its last `window` full redraws
  double last_move_ms_ = -1e300;
};

}  // namespace ps
