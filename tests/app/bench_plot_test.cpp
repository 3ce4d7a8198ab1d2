// The data shaping behind `bench`'s plots (app/bench/bench_plot.h): CSV reading, panels, short
// labels, axis choice, label placement and the strategy speed-ups. No GL, no gnuplot.
#include "app/bench/bench_plot.h"

#include <gtest/gtest.h>

#include <cmath>

#include "app/bench/bench_report.h"

namespace ps::bench {
namespace {

BenchRow row(std::string group, std::string value, double frame_ms, double surface_ms, double error, bool pareto) {
  BenchRow r;
  r.group = std::move(group);
  r.value = std::move(value);
  r.metric = "texture_vs_target";
  r.m.frame_ms = frame_ms;
  r.m.surface_ms = surface_ms;
  r.m.texture_vs_target = error;
  r.error = error;
  r.pareto = pareto;
  r.m.footprint_pixels = 143044;
  return r;
}

TEST(BenchPlotTest, CsvRoundTripsThroughTheWriter) {
  const std::vector<BenchRow> rows = {row("gabor_strategy", "naive", 34.76, 31.1, 0.000177, true),
                                      row("gabor_strategy", "baked_linear_24", 9.761, 6.348, 0.007932, true)};
  auto back = parse_csv(csv_text(rows), "bench.csv");
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->size(), 2u);
  EXPECT_EQ((*back)[1].group, "gabor_strategy");
  EXPECT_EQ((*back)[1].value, "baked_linear_24");
  EXPECT_EQ((*back)[1].metric, "texture_vs_target");
  EXPECT_EQ((*back)[1].m.frame_ms, 9.761);  // csv_text writes 4 significant digits: these have 4
  EXPECT_EQ((*back)[1].error, 0.007932);
  EXPECT_TRUE((*back)[1].pareto);
  EXPECT_EQ((*back)[1].m.footprint_pixels, 143044);
  EXPECT_EQ((*back)[1].m.texture_vs_ideal, 0.0);
}

TEST(BenchPlotTest, CsvErrorsNameFileAndLine) {
  const std::string header =
      "group,value,frame_ms,surface_ms,error_metric,error,pareto,texture_rms_sigma,texture_vs_ideal,"
      "texture_vs_target,displacement_rel,distance_max_mm,normal_deg,footprint_pixels\n";
  const std::string good = "depth_map,64,34.41,31.01,distance_max_mm,1.084,1,0.0001771,n/a,0.0001771,0.1336,1.084,0,142932\n";
  auto ok = parse_csv(header + good, "b.csv");
  ASSERT_TRUE(ok.ok()) << ok.error().message;
  EXPECT_TRUE(std::isnan((*ok)[0].m.texture_vs_ideal));  // "n/a": not measured for this group
  auto bad_number = parse_csv(header + good + "depth_map,128,fast,31,distance_max_mm,0.5,1,0,n/a,0,0,0.5,0,1\n", "b.csv");
  ASSERT_FALSE(bad_number.ok());
  EXPECT_EQ(bad_number.error().message.rfind("b.csv:3: bad frame_ms value", 0), 0u) << bad_number.error().message;
  auto short_line = parse_csv(header + "depth_map,64,34.41\n", "b.csv");
  ASSERT_FALSE(short_line.ok());
  EXPECT_EQ(short_line.error().message.rfind("b.csv:2: 3 fields, expected 14", 0), 0u) << short_line.error().message;
  auto bad_pareto = parse_csv(header + "depth_map,64,34.41,31.01,distance_max_mm,1.084,yes,0,n/a,0,0,1,0,1\n", "b.csv");
  ASSERT_FALSE(bad_pareto.ok());
  EXPECT_EQ(bad_pareto.error().message.rfind("b.csv:2: bad pareto value", 0), 0u) << bad_pareto.error().message;
  auto no_header = parse_csv(good, "b.csv");
  ASSERT_FALSE(no_header.ok());
  EXPECT_EQ(no_header.error().message.rfind("b.csv:1: not a bench.csv header", 0), 0u);
  EXPECT_FALSE(parse_csv(header, "b.csv").ok());  // a header and no rows: nothing to plot
  EXPECT_FALSE(parse_csv("", "b.csv").ok());
}

TEST(BenchPlotTest, ShortLabels) {
  EXPECT_EQ(short_label("gabor_strategy", "baked_linear_24"), "lin 24");
  EXPECT_EQ(short_label("gabor_strategy", "baked_16"), "bake 16");
  EXPECT_EQ(short_label("gabor_strategy", "stratified_4"), "strat 4");
  EXPECT_EQ(short_label("gabor_strategy", "naive"), "naive");
  EXPECT_EQ(short_label("displacement", "weighted_c10"), "c=10");
  EXPECT_EQ(short_label("displacement", "exact_max"), "exact max");
  EXPECT_EQ(short_label("depth_map", "depth_map_64"), "64");  // the group's own name is stripped
  EXPECT_EQ(short_label("depth_map", "1024"), "1024");
}

TEST(BenchPlotTest, AxesAreLogarithmicOnlyOverAWideSpan) {
  const Axis wide = fit_axis({3.5, 10.3, 35.0, 134.5});  // reduction_base times: 38x
  EXPECT_TRUE(wide.log);
  EXPECT_LT(wide.lo, 3.5);
  EXPECT_GT(wide.hi, 134.5);
  const Axis narrow = fit_axis({16.7, 19.0, 22.9, 34.7, 53.0});  // gabor_n times: 3.2x
  EXPECT_FALSE(narrow.log);
  EXPECT_LT(narrow.lo, 16.7);
  EXPECT_GT(narrow.hi, 53.0);
  // Padded by the same fraction on both sides, so the ends map to the same distance from the frame.
  EXPECT_NEAR(wide.unit(3.5), 1.0 - wide.unit(134.5), 1e-12);  // exact up to rounding of log10/pow
  EXPECT_NEAR(narrow.unit(16.7), 1.0 - narrow.unit(53.0), 1e-12);
  EXPECT_TRUE(fit_axis({7.9, 10.0, 62.6}).log);  // gabor_strategy times: 7.9x, the 10 ms cluster needs the room
  const Axis flat = fit_axis({0.000782, 0.000782});
  EXPECT_LT(flat.lo, 0.000782);
  EXPECT_GT(flat.hi, 0.000782);
}

TEST(BenchPlotTest, PanelsGroupRowsInOrderAndSortByTime) {
  const std::vector<BenchRow> rows = {row("gabor_n", "25", 34.65, 30.87, 0.2956, true),
                                      row("gabor_n", "2", 16.67, 13.14, 1.197, true),
                                      row("depth_map", "64", 34.41, 31.01, 1.084, true),
                                      row("gabor_n", "50", 52.97, 49.01, 0.7732, false),
                                      row("depth_map", "128", 34.49, 31.05, 0.0, true)};
  const std::vector<Panel> p = group_panels(rows);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].group, "gabor_n");
  EXPECT_EQ(p[1].group, "depth_map");
  ASSERT_EQ(p[0].points.size(), 3u);
  EXPECT_EQ(p[0].points[0].label, "2");
  EXPECT_EQ(p[0].points[1].label, "25");
  EXPECT_EQ(p[0].points[2].label, "50");
  EXPECT_FALSE(p[0].points[2].pareto);
  EXPECT_EQ(p[1].points[1].error, kErrorFloor);  // an error of 0 cannot sit on a log axis
}

bool overlaps(const PlacedLabel& a, const PlacedLabel& b) {
  return std::min(a.x1, b.x1) > std::max(a.x0, b.x0) && std::min(a.y1, b.y1) > std::max(a.y0, b.y0);
}

// The example: baked_linear_32 and baked_32 (and the baked/auto cluster around 10 ms,
// 0.008-0.2 sigma) drawn on top of each other. Placed, no two labels meet, none covers a
// marker, and every label stays inside the panel.
TEST(BenchPlotTest, LabelsOfTheStrategyClusterDoNotCollide) {
  const std::vector<BenchRow> rows = {
      row("gabor_strategy", "naive", 34.76, 31.1, 0.000177, true),
      row("gabor_strategy", "stratified_1", 25.24, 21.2, 1.421, false),
      row("gabor_strategy", "stratified_2", 30.07, 26.34, 1.438, false),
      row("gabor_strategy", "stratified_4", 40.5, 36.78, 1.45, false),
      row("gabor_strategy", "stratified_8", 62.61, 58.37, 1.406, false),
      row("gabor_strategy", "none", 7.946, 4.629, 1.013, true),
      row("gabor_strategy", "auto", 10.08, 6.538, 0.007932, false),
      row("gabor_strategy", "baked_8", 10.86, 7.497, 0.01326, false),
      row("gabor_strategy", "baked_16", 13.19, 9.652, 0.009425, false),
      row("gabor_strategy", "baked_32", 13.06, 9.5, 0.2123, false),
      row("gabor_strategy", "baked_linear_16", 10.01, 6.488, 0.01076, false),
      row("gabor_strategy", "baked_linear_24", 9.761, 6.348, 0.007932, true),
      row("gabor_strategy", "baked_linear_32", 9.987, 6.533, 0.2121, false)};
  const Panel p = group_panels(rows)[0];
  const LabelGeometry geo;
  const std::vector<PlacedLabel> labels = place_labels(p, geo);
  ASSERT_EQ(labels.size(), p.points.size());
  const double mw = 0.5 * geo.marker_px / geo.plot_w_px, mh = 0.5 * geo.marker_px / geo.plot_h_px;
  for (size_t i = 0; i < labels.size(); ++i) {
    EXPECT_EQ(labels[i].text, p.points[i].label);
    EXPECT_GE(labels[i].x0, 0.0) << labels[i].text;
    EXPECT_LE(labels[i].x1, 1.0) << labels[i].text;
    EXPECT_GE(labels[i].y0, 0.0) << labels[i].text;
    EXPECT_LE(labels[i].y1, 1.0) << labels[i].text;
    for (size_t j = 0; j < i; ++j)
      EXPECT_FALSE(overlaps(labels[i], labels[j])) << labels[i].text << " over " << labels[j].text;
    for (const PlotPoint& q : p.points) {
      const double x = p.x.unit(q.time_ms), y = p.y.unit(q.error);
      EXPECT_FALSE(overlaps(labels[i], PlacedLabel{"", x - mw, y - mh, x + mw, y + mh}))
          << labels[i].text << " over the marker of " << q.label;
    }
  }
}

TEST(BenchPlotTest, SpeedUpsAgainstNaiveAndUntextured) {
  const std::vector<BenchRow> rows = {row("gabor_strategy", "naive", 40.0, 30.0, 0.0, true),
                                      row("gabor_strategy", "none", 8.0, 5.0, 1.0, true),
                                      row("gabor_strategy", "auto", 10.0, 7.5, 0.008, true),
                                      row("gabor_strategy", "noisy", 9.0, 4.9, 0.02, true),
                                      row("depth_map", "64", 1.0, 1.0, 1.0, true)};
  const std::vector<SpeedUp> s = strategy_speedups(rows);
  ASSERT_EQ(s.size(), 3u);  // naive, auto, noisy: not `none`, not other groups
  EXPECT_EQ(s[0].strategy, "naive");
  EXPECT_DOUBLE_EQ(s[0].frame, 1.0);
  EXPECT_EQ(s[1].strategy, "auto");
  EXPECT_DOUBLE_EQ(s[1].frame, 4.0);     // 40 / 10
  EXPECT_DOUBLE_EQ(s[1].surface, 4.0);   // 30 / 7.5
  EXPECT_DOUBLE_EQ(s[1].gabor, 10.0);    // (30 - 5) / (7.5 - 5)
  EXPECT_TRUE(s[1].meets_bar);           // 0.8 % <= 1 %
  EXPECT_TRUE(std::isnan(s[2].gabor));   // surface below the untextured one: noise level
  EXPECT_FALSE(s[2].meets_bar);
  EXPECT_TRUE(strategy_speedups({rows[0], rows[2]}).empty());  // no `none` row: no ratios
}

}  // namespace
}  // namespace ps::bench
