#include "app/bench/bench_report.h"

#include "app/bench/bench_plot.h"
#include "core/file_io.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace ps::bench {

namespace {

std::string g(double v) {
  if (!std::isfinite(v)) return "n/a";
  char b[32];
  std::snprintf(b, sizeof(b), "%.4g", v);
  return b;
}

}  // namespace

std::string csv_text(const std::vector<BenchRow>& rows) {
  std::ostringstream o;
  o << "group,value,frame_ms,surface_ms,error_metric,error,pareto,texture_rms_sigma,"
       "texture_vs_ideal,texture_vs_target,displacement_rel,distance_max_mm,normal_deg,footprint_pixels\n";
  for (const BenchRow& r : rows)
    o << r.group << ',' << r.value << ',' << g(r.m.frame_ms) << ',' << g(r.m.surface_ms) << ','
      << r.metric << ',' << g(r.error) << ',' << (r.pareto ? 1 : 0) << ',' << g(r.m.texture_rms_sigma)
      << ',' << g(r.m.texture_vs_ideal) << ',' << g(r.m.texture_vs_target) << ',' << g(r.m.displacement_rel) << ',' << g(r.m.distance_max_mm) << ',' << g(r.m.normal_deg)
      << ',' << r.m.footprint_pixels << '\n';
  return o.str();
}

std::string summary_markdown(const std::vector<BenchRow>& rows, const SkipRatios& skip,
                             const RssReport& rss, int size) {
  std::ostringstream o;
  o << "Image " << size << "x" << size << "; times are medians of warm frames (glFinish per pass).\n\n";
  o << "| group | value | frame ms | surface ms | error metric | error | Pareto | GPU timer frame ms |\n";
  o << "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const BenchRow& r : rows)
    o << "| " << r.group << " | " << r.value << " | " << g(r.m.frame_ms) << " | " << g(r.m.surface_ms)
      << " | " << r.metric << " | " << g(r.error) << " | " << (r.pareto ? "yes" : "") << " | "
      << (std::isnan(r.m.gpu_frame_ms) ? std::string("-") : g(r.m.gpu_frame_ms)) << " |\n";
  // Gabor strategies against the naive sum, all from this run: whole frame, surface pass, and
  // the Gabor evaluation alone (time above the "none" row, i.e. the same frame untextured).
  if (const std::vector<SpeedUp> speedups = strategy_speedups(rows); !speedups.empty()) {
    o << "\n| Gabor strategy | frame ms | speed-up: frame | surface pass | Gabor evaluation | RMS vs naive (sigma) | <= 1 % |\n"
      << "| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const SpeedUp& s : speedups)
      o << "| " << s.strategy << " | " << g(s.frame_ms) << " | " << g(s.frame) << "x | " << g(s.surface) << "x | "
        << (std::isfinite(s.gabor) ? g(s.gabor) + "x" : std::string("(at noise level)")) << " | " << g(s.error)
        << " | " << (s.meets_bar ? "yes" : "no") << " |\n";
  }
  o << "\n| skip check | measured | target |\n| --- | --- | --- |\n";
  o << "| probe beyond influence: frame / plain shading pass | " << g(skip.beyond_influence) << "x | <= 1.1x |\n";
  o << "| untextured (PS_TEXTURED=0) / textured with no Gabor pixel | " << g(skip.untextured) << "x | <= 1.05x |\n";
  o << "| surface pass slope vs textured footprint | " << g(skip.ms_per_kpx_footprint) << " ms per 1000 px | - |\n";
  o << "| surface pass slope vs screen size, fixed footprint | " << g(skip.ms_per_kpx_screen) << " ms per 1000 px | much smaller |\n";
  o << shadow_cost_rows(skip.shadow_cost);
  if (!skip.shadow_cost.empty()) o << "\n" << shadow_cost_table(skip.shadow_cost);
  o << "\n| peak RSS of `pseudoshadow render` | 512x512 | 2048x2048 |\n| --- | --- | --- |\n";
  o << "| MiB | " << g(rss.kib_512 / 1024.0) << " | " << g(rss.kib_2048 / 1024.0) << " |\n";
  return o.str();
}

std::string shadow_cost_rows(const std::vector<ShadowCost>& costs) {
  std::ostringstream o;
  for (const ShadowCost& c : costs)
    o << "| pseudo-shadow frame / plain shading of the same view (default scene, " << c.size << "x" << c.size
      << ") | " << g(c.ratio) << "x | <= 1.3x |\n";
  return o.str();
}

std::string shadow_cost_table(const std::vector<ShadowCost>& costs) {
  std::ostringstream o;
  o << "| default scene | plain frame ms | pseudo-shadow frame ms | ratio |";
  if (!costs.empty())
    for (const auto& [pass, ms] : costs.front().shadow_pass_ms) o << " " << pass << " ms |";
  o << " shadow pixels | ratio of CPU time | GPU timer: plain / pseudo-shadow frame ms |\n| --- | --- | --- | --- |";
  if (!costs.empty())
    for (size_t i = 0; i < costs.front().shadow_pass_ms.size(); ++i) o << " --- |";
  o << " --- | --- | --- |\n";
  for (const ShadowCost& c : costs) {
    o << "| " << c.size << "x" << c.size << " | " << g(c.plain_frame_ms) << " | " << g(c.shadow_frame_ms) << " | "
      << g(c.ratio) << "x |";
    for (const auto& [pass, ms] : c.shadow_pass_ms) o << " " << g(ms) << " |";
    o << " " << c.shadow_pixels << " | " << g(c.cpu_ratio) << "x | "
      << (std::isnan(c.gpu_shadow_frame_ms) ? std::string("-") : g(c.gpu_plain_frame_ms) + " / " + g(c.gpu_shadow_frame_ms))
      << " |\n";
  }
  return o.str();
}

namespace {

// A string as a gnuplot double-quoted literal: quotes and backslashes escaped, a line break
// written as \n (a single-quoted gnuplot string cannot hold one).
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += c == '\n' ? std::string("\\n") : c == '"' || c == '\\' ? std::string{'\\', c} : std::string(1, c);
  return out + "\"";
}

// The grid of panels: kColumns across, fixed pixels per panel, so that the label placement
// knows each plotting area's size. Fractions of the canvas, as `set multiplot ... margins`
// takes them; the gaps leave room for the tick labels, axis labels and the next title.
struct GridLayout {
  static constexpr int kColumns = 3;
  static constexpr int kWidthPx = 1320, kRowPx = 400, kTopPx = 85, kBottomPx = 60;
  int rows = 1;
  int height_px() const { return kTopPx + kBottomPx + rows * kRowPx; }
  double left() const { return 75.0 / kWidthPx; }
  double right() const { return 1.0 - 25.0 / kWidthPx; }
  double bottom() const { return double(kBottomPx) / height_px(); }
  double top() const { return 1.0 - double(kTopPx) / height_px(); }
  double gap_x() const { return 95.0 / kWidthPx; }
  double gap_y() const { return 110.0 / height_px(); }
  LabelGeometry geometry() const {
    LabelGeometry g;
    g.plot_w_px = (right() - left() - (kColumns - 1) * gap_x()) / kColumns * kWidthPx;
    g.plot_h_px = (top() - bottom() - (rows - 1) * gap_y()) / rows * height_px();
    return g;
  }
};

// What the short labels of a group stand for, under its panel's title.
std::string panel_title(const Panel& p) {
  std::string t = p.group + "  (error: " + p.metric + ")";
  if (p.group == "gabor_strategy") t += "\nbake = baked_ (Hermite), lin = baked_linear_, strat = stratified_";
  if (p.group == "displacement") t += "\nc= : weighted average (1 - d)^c";
  return t;
}

// Range and ticks. On a log axis gnuplot labels only the powers of ten, which leaves a panel
// that spans less than a decade or two with one labelled tick or none: label 1, 2 and 5 times
// each power of ten instead when the axis spans under three decades.
void axis_commands(std::ostringstream& o, const char* name, const Axis& a) {
  o << (a.log ? "set logscale " : "unset logscale ") << name << "\nset " << name << "range [" << a.lo << ':' << a.hi
    << "]\nset " << name << "tics autofreq\n";
  if (!a.log || std::log10(a.hi / a.lo) >= 3.0) return;
  o << "set " << name << "tics (";
  const char* sep = "";
  for (int e = static_cast<int>(std::floor(std::log10(a.lo))); e <= static_cast<int>(std::ceil(std::log10(a.hi))); ++e)
    for (double m : {1.0, 2.0, 5.0})
      if (const double v = m * std::pow(10.0, e); v >= a.lo && v <= a.hi) {
        o << sep << v;
        sep = ", ";
      }
  o << ")\n";
}

// One panel: Pareto points filled and joined, dominated points open, every point labelled.
void panel_commands(std::ostringstream& o, const Panel& p, const LabelGeometry& geo, int index) {
  const std::string front = "$front" + std::to_string(index), off = "$off" + std::to_string(index);
  o << front << " << EOD\n";
  for (const PlotPoint& q : p.points)
    if (q.pareto) o << q.time_ms << ' ' << q.error << '\n';
  o << "EOD\n" << off << " << EOD\n";
  for (const PlotPoint& q : p.points)
    if (!q.pareto) o << q.time_ms << ' ' << q.error << '\n';
  o << "EOD\nset title " << quoted(panel_title(p)) << "\nset ylabel " << quoted(p.metric) << "\n";
  axis_commands(o, "x", p.x);
  axis_commands(o, "y", p.y);
  o << "unset label\nunset arrow\n";
  int n = 0;
  for (const PlacedLabel& l : place_labels(p, geo)) {
    ++n;
    o << "set label " << n << ' ' << quoted(l.text) << " at graph " << l.x0 + 0.25 * geo.char_w_px / geo.plot_w_px
      << ',' << 0.5 * (l.y0 + l.y1) << " left front\n";
    if (l.leader)  // from the point to the nearest point of the label's box
      o << "set arrow " << n << " from graph " << l.px << ',' << l.py << " to graph " << std::clamp(l.px, l.x0, l.x1)
        << ',' << std::clamp(l.py, l.y0, l.y1) << " nohead lw 0.8 lc rgb '#7f7f7f' back\n";
  }
  const bool has_front = std::any_of(p.points.begin(), p.points.end(), [](auto& q) { return q.pareto; });
  const bool has_off = std::any_of(p.points.begin(), p.points.end(), [](auto& q) { return !q.pareto; });
  o << "plot ";
  if (has_front) o << front << " using 1:2 with linespoints pt 7 ps 1.1 lw 1.5 lc rgb '#1f5fa8' notitle";
  if (has_off) o << (has_front ? ", " : "") << off << " using 1:2 with points pt 6 ps 1.1 lc rgb '#c0392b' notitle";
  o << "\n";
}

std::string panels_script(const std::string& png, const std::vector<Panel>& panels) {
  GridLayout grid;
  grid.rows = static_cast<int>((panels.size() + GridLayout::kColumns - 1) / GridLayout::kColumns);
  std::ostringstream o;
  o << "set terminal pngcairo size " << GridLayout::kWidthPx << ',' << grid.height_px()
    << " noenhanced font 'Sans,10'\nset output " << quoted(png) << "\nset grid\nset format x '%g'\n"
    << "set format y '%g'\nset xlabel 'frame time, ms'\nset multiplot layout " << grid.rows << ','
    << GridLayout::kColumns << " rowsfirst margins " << grid.left() << ',' << grid.right() << ',' << grid.bottom()
    << ',' << grid.top() << " spacing " << grid.gap_x() << ',' << grid.gap_y()
    << " title 'pseudoshadow bench: time vs error per knob group. Filled and joined: the Pareto front; "
       "open: dominated (another setting is faster and at least as accurate)'\n";
  for (size_t i = 0; i < panels.size(); ++i) panel_commands(o, panels[i], grid.geometry(), static_cast<int>(i));
  o << "unset multiplot\n";
  return o.str();
}

// Clustered bars per strategy: whole frame, surface pass, Gabor evaluation, each naive / strategy.
std::string ratios_script(const std::string& png, const std::vector<SpeedUp>& speedups) {
  std::ostringstream o;
  o << "$ratios << EOD\n";
  double top = 1.0;
  for (const SpeedUp& s : speedups) {
    o << quoted(s.strategy + (s.meets_bar ? " *" : "")) << ' ' << s.frame << ' ' << s.surface << ' '
      << (std::isfinite(s.gabor) ? s.gabor : 0.0) << '\n';
    top = std::max({top, s.frame, s.surface, std::isfinite(s.gabor) ? s.gabor : 0.0});
  }
  o << "EOD\nset terminal pngcairo size 1100,520 noenhanced font 'Sans,10'\nset output " << quoted(png) << "\n"
    << "set title 'Gabor strategies: speed-up over the naive per-pixel sum (same run). "
       "* = texture within 1 % sigma RMS of naive'\n"
    << "set ylabel 'naive time / strategy time (x)'\nset yrange [0:" << top * 1.12 << "]\nset grid ytics\n"
    << "set xrange [-0.6:" << speedups.size() - 0.4 << "]\n"
    << "set style data histogram\nset style histogram cluster gap 1\nset style fill solid 0.85 border -1\n"
    << "set boxwidth 0.9\nset xtics rotate by -25 nomirror\nset key top left\n"
    << "plot 1 with lines dashtype 2 lc rgb 'black' title 'naive = 1x', $ratios using 2:xtic(1) title 'whole frame' lc rgb '#8fb3d9', '' using 3 title 'surface pass' "
       "lc rgb '#3a78b8', '' using 4 title 'Gabor evaluation (surface pass above untextured)' lc rgb '#1b3f6b', "
       "'' using ($0 - 0.25):2:(sprintf('%.1f', $2)) with labels offset 0,0.6 font ',8' notitle, "
       "'' using 0:3:(sprintf('%.1f', $3)) with labels offset 0,0.6 font ',8' notitle, "
       "'' using ($0 + 0.25):4:(sprintf('%.1f', $4)) with labels offset 0,0.6 font ',8' notitle\n";
  return o.str();
}

Status run_gnuplot(const std::string& script_path, const std::string& script) {
  if (Status s = write_file_atomic(script_path, script); !s) return s;
  std::string shell_arg = "'";  // the path as one shell word: a quote inside becomes '\''
  for (char c : script_path) shell_arg += c == '\'' ? std::string("'\\''") : std::string(1, c);
  if (std::system(("gnuplot " + shell_arg + "'").c_str()) != 0)
    return make_error("gnuplot failed on " + script_path);
  return ok_status();
}

}  // namespace

Status write_plots(const std::string& dir, const std::vector<BenchRow>& rows) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    return make_error("gnuplot not found (install gnuplot-nox): no plot written, the CSV has the data");
  if (Status s = run_gnuplot(dir + "/bench_plot.gp", panels_script(dir + "/bench.png", group_panels(rows))); !s)
    return s;
  const std::vector<SpeedUp> speedups = strategy_speedups(rows);
  if (speedups.empty()) return make_error("no naive and untextured gabor_strategy rows: no bench_ratios.png");
  return run_gnuplot(dir + "/bench_ratios.gp", ratios_script(dir + "/bench_ratios.png", speedups));
}

Result<long long> render_peak_rss_kib(int size, const std::vector<std::string>& gl_args, const std::string& dir) {
  const std::string sz = std::to_string(size) + "x" + std::to_string(size);
  const std::string out = dir + "/rss_" + std::to_string(size) + ".png";
  std::vector<std::string> words = {"pseudoshadow", "render", "--size", sz, "--out", out, "-q"};
  words.insert(words.end(), gl_args.begin(), gl_args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return make_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    execv("/proc/self/exe", argv.data());
    _exit(127);
  }
  int status = 0;
  struct rusage ru {};
  if (wait4(pid, &status, 0, &ru) < 0) return make_error(std::string("wait4: ") + std::strerror(errno));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return make_error("render " + sz + " for the RSS measurement failed");
  return static_cast<long long>(ru.ru_maxrss);  // Linux: KiB
}

}  // namespace ps::bench
