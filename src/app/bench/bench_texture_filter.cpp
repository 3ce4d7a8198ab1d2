#include "app/bench/bench_texture_filter.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

#include "render/renderer.h"
#include "measure/texture_aliasing.h"

namespace ps::bench {

namespace {

using aliasing::View;
using Strategy = GaborParams::Strategy;
using Filter = GaborParams::Filter;

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One configuration: its renderer, its error, its timed frames.
struct Config {
  Strategy strategy;
  Filter filter;
  std::unique_ptr<Renderer> renderer;
  aliasing::Compare error;
  std::vector<double> frame_ms, surface_ms;
};

Status timed_frame(Config& c) {
  if (Status s = c.renderer->render_frame(); !s) return s;
  double total = 0.0, surface = 0.0;
  for (const auto& [name, ms] : c.renderer->stats().timings_ms) {
    total += ms;
    if (name == "surface") surface = ms;
  }
  c.frame_ms.push_back(total);
  c.surface_ms.push_back(surface);
  return ok_status();
}

const char* strategy_name(Strategy s) {
  return s == Strategy::kNaive ? "naive" : s == Strategy::kBakedLinear ? "baked_linear" : "baked";
}

// Warm frames, then rounds of timed frames over every configuration, in alternating order.
Status time_configs(const BenchOptions& o, std::vector<Config>& configs) {
  for (Config& c : configs)
    for (int i = 0; i < o.warm_frames; ++i)
      if (Status s = timed_frame(c); !s) return s;
  for (Config& c : configs) c.frame_ms.clear(), c.surface_ms.clear();
  const int rounds = std::max(o.rounds, 5), per_round = std::max(o.timed_frames, 3);
  for (int round = 0; round < rounds; ++round)
    for (size_t k = 0; k < configs.size(); ++k) {
      Config& c = configs[round % 2 ? configs.size() - 1 - k : k];  // alternate the order
      for (int i = 0; i < per_round; ++i)
        if (Status s = timed_frame(c); !s) return s;
    }
  return ok_status();
}

// The view's rows of the table: every configuration's error, then their times in rounds.
Status view_rows(const BenchOptions& o, View view, int size, std::string& table) {
  constexpr double kLambdaPx = 2.0;
  std::vector<Config> configs;
  for (const Strategy s : {Strategy::kNaive, Strategy::kBakedLinear, Strategy::kBaked}) {
    // The reference is the strategy's own texture (a tile repeats beyond its period).
    auto big = aliasing::render_texture(aliasing::scene(view, kLambdaPx, size, size * aliasing::kSuper, s, Filter::kNone));
    if (!big) return big.error();
    const std::vector<double> ref = aliasing::box_down(big.value(), size);
    for (const Filter f : {Filter::kNone, Filter::kAnalytic}) {
      Config c{s, f, nullptr, {}, {}, {}};
      auto img = aliasing::render_texture(aliasing::scene(view, kLambdaPx, size, size, s, f), nullptr, &c.renderer);
      if (!img) return img.error();
      c.error = aliasing::compare(img.value(), ref);
      configs.push_back(std::move(c));
    }
  }
  if (Status s = time_configs(o, configs); !s) return s;
  const double base = median_of(configs[0].frame_ms);  // naive, unfiltered
  for (size_t k = 0; k < configs.size(); ++k) {
    const Config& c = configs[k];
    const double own_unfiltered = median_of(configs[k - (c.filter == Filter::kAnalytic ? 1 : 0)].frame_ms);
    char line[256];
    std::snprintf(line, sizeof line, "| %s | %s | %s | %.2f ms | %.2f ms | %.2fx | %.2fx | %.3f | %.3f |\n",
                  view == View::kTopDown ? "top-down" : "grazing 15 deg", strategy_name(c.strategy),
                  c.filter == Filter::kAnalytic ? "analytic" : "none", median_of(c.frame_ms), median_of(c.surface_ms),
                  median_of(c.frame_ms) / base, median_of(c.frame_ms) / own_unfiltered, c.error.rms_over_sd,
                  c.error.var_ratio);
    table += line;
  }
  return ok_status();
}

}  // namespace

Result<std::string> run_texture_filter(const BenchOptions& o, int size) {
  std::string table =
      "| view | strategy | gabor_filter | frame | surface pass | frame vs naive none | frame vs same strategy none "
      "| RMS / sd of reference | variance ratio |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const View v : {View::kTopDown, View::kGrazing}) {
    if (o.progress) o.progress(std::string("texture filter, ") + (v == View::kTopDown ? "top-down" : "grazing") + " ...");
    if (Status s = view_rows(o, v, size, table); !s) return s.error();
  }
  return table;
}

}  // namespace ps::bench
