#include "app/bench_report.h"

#include "core/file_io.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
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
  o << "| group | value | frame ms | surface ms | error metric | error | Pareto |\n";
  o << "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const BenchRow& r : rows)
    o << "| " << r.group << " | " << r.value << " | " << g(r.m.frame_ms) << " | " << g(r.m.surface_ms)
      << " | " << r.metric << " | " << g(r.error) << " | " << (r.pareto ? "yes" : "") << " |\n";
  // Gabor strategies against the naive sum, all from this run: whole frame, surface pass, and
  // the Gabor evaluation alone (time above the "none" row, i.e. the same frame untextured).
  const BenchRow *naive = nullptr, *none = nullptr;
  for (const BenchRow& r : rows)
    if (r.group == "gabor_strategy") {
      if (r.value == "naive") naive = &r;
      if (r.value == "none") none = &r;
    }
  if (naive && none) {
    o << "\n| Gabor strategy | frame ms | speed-up: frame | surface pass | Gabor evaluation | RMS vs naive (sigma) | <= 1 % |\n"
      << "| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const BenchRow& r : rows) {
      if (r.group != "gabor_strategy" || &r == none) continue;
      const double gabor_naive = naive->m.surface_ms - none->m.surface_ms, gabor_r = r.m.surface_ms - none->m.surface_ms;
      o << "| " << r.value << " | " << g(r.m.frame_ms) << " | " << g(naive->m.frame_ms / r.m.frame_ms) << "x | "
        << g(naive->m.surface_ms / r.m.surface_ms) << "x | "
        << (gabor_r > 0.0 ? g(gabor_naive / gabor_r) + "x" : std::string("(at noise level)")) << " | "
        << g(r.error) << " | " << (r.error <= 0.01 ? "yes" : "no") << " |\n";
    }
  }
  o << "\n| skip check | measured | target |\n| --- | --- | --- |\n";
  o << "| probe beyond influence: frame / plain shading pass | " << g(skip.beyond_influence) << "x | <= 1.1x |\n";
  o << "| untextured (PS_TEXTURED=0) / textured with no Gabor pixel | " << g(skip.untextured) << "x | <= 1.05x |\n";
  o << "| surface pass slope vs textured footprint | " << g(skip.ms_per_kpx_footprint) << " ms per 1000 px | - |\n";
  o << "| surface pass slope vs screen size, fixed footprint | " << g(skip.ms_per_kpx_screen) << " ms per 1000 px | much smaller |\n";
  o << "\n| peak RSS of `pseudoshadow render` | 512x512 | 2048x2048 |\n| --- | --- | --- |\n";
  o << "| MiB | " << g(rss.kib_512 / 1024.0) << " | " << g(rss.kib_2048 / 1024.0) << " |\n";
  return o.str();
}

namespace {

// One data block per group (all points) and one per group's Pareto front, sorted by time.
std::string plot_data(const std::vector<BenchRow>& rows, std::vector<std::string>& groups) {
  std::map<std::string, std::vector<const BenchRow*>> by_group;
  for (const BenchRow& r : rows) {
    if (!by_group.count(r.group)) groups.push_back(r.group);
    by_group[r.group].push_back(&r);
  }
  std::ostringstream o;
  for (const std::string& name : groups) {
    auto v = by_group[name];
    std::sort(v.begin(), v.end(), [](auto* a, auto* b) { return a->m.frame_ms < b->m.frame_ms; });
    // Errors of exactly 0 cannot sit on a log axis: floor them at 1e-7.
    for (const BenchRow* r : v) o << r->m.frame_ms << ' ' << std::max(r->error, 1e-7) << " \"" << r->value << "\"\n";
    o << "\n\n";
    for (const BenchRow* r : v)
      if (r->pareto) o << r->m.frame_ms << ' ' << std::max(r->error, 1e-7) << " \"" << r->value << "\"\n";
    o << "\n\n";
  }
  return o.str();
}

}  // namespace

Status write_plot(const std::string& png, const std::string& dir, const std::vector<BenchRow>& rows) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    return make_error("gnuplot not found (install gnuplot-nox): no plot written, the CSV has the data");
  std::vector<std::string> groups;
  std::map<std::string, std::string> metric;
  for (const BenchRow& r : rows) metric[r.group] = r.metric;
  const std::string dat = dir + "/bench_plot.dat", gp = dir + "/bench_plot.gp";
  if (Status s = write_file_atomic(dat, plot_data(rows, groups)); !s) return s;
  std::ostringstream o;
  o << "set terminal pngcairo size 1100,750 noenhanced\nset output '" << png << "'\n"
    << "set logscale xy\nset xlabel 'frame time, ms (median of warm frames)'\n"
    << "set ylabel 'error (per group: see legend; relative or sigma or mm)'\n"
    << "set key outside right\nset grid\nset title 'pseudoshadow bench: time vs error, lines = Pareto fronts'\n"
    << "plot ";
  for (size_t i = 0; i < groups.size(); ++i) {
    o << (i ? ", " : "") << "'" << dat << "' index " << 2 * i << " using 1:2 with points pt " << 5 + i
      << " lc " << i + 1 << " title '" << groups[i] << " (" << metric[groups[i]] << ")', '' index " << 2 * i
      << " using 1:2:3 with labels offset 0.8,0.6 font ',7' notitle, '' index " << 2 * i + 1
      << " using 1:2 with lines lc " << i + 1 << " notitle";
  }
  o << "\n";
  if (Status s = write_file_atomic(gp, o.str()); !s) return s;
  if (std::system(("gnuplot '" + gp + "'").c_str()) != 0) return make_error("gnuplot failed on " + gp);
  return ok_status();
}

Result<long long> render_peak_rss_kib(int size, const std::string& backend, const std::string& dir) {
  const std::string sz = std::to_string(size) + "x" + std::to_string(size);
  const std::string out = dir + "/rss_" + std::to_string(size) + ".png";
  const pid_t pid = fork();
  if (pid < 0) return make_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    execl("/proc/self/exe", "pseudoshadow", "render", "--size", sz.c_str(), "--backend", backend.c_str(),
          "--out", out.c_str(), "-q", static_cast<char*>(nullptr));
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
