#include "app/window/readouts_log.h"

#include <cerrno>
#include <cmath>
#include <cstring>

namespace ps {

namespace {

std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();  // "1.5000" -> "1.5", "2.0000" -> "2."
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string vec(const glm::dvec3& v) { return "[" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + "]"; }
std::string vec(const std::optional<glm::dvec2>& v) { return v ? "[" + num(v->x) + ", " + num(v->y) + "]" : "null"; }

// Scene file names and flag names are plain, but a quote or backslash must not break the line.
std::string str(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out + "\"";
}

}  // namespace

double view_turn_deg(const glm::dmat3& r) {
  // glm is column-major: r[c][row]. 2 sin(angle) = |(r32 - r23, r13 - r31, r21 - r12)|.
  const glm::dvec3 twice_sin_axis(r[1][2] - r[2][1], r[2][0] - r[0][2], r[0][1] - r[1][0]);
  const double c = 0.5 * (r[0][0] + r[1][1] + r[2][2] - 1.0);
  return glm::degrees(std::atan2(0.5 * glm::length(twice_sin_axis), c));
}

std::string readouts_json_line(const ReadoutsFrame& f) {
  const ProbeReadout& p = f.probe;
  std::string distance = "null";
  if (p.state == ProbeState::kHovering) distance = num(p.hover_mm);
  if (p.state == ProbeState::kTouching) distance = "0";
  std::string button = "null";
  if (f.button >= 0)
    button = "{\"index\": " + std::to_string(f.button) + ", \"depth_mm\": " + num(f.button_depth_mm) +
             ", \"travel_mm\": " + num(f.button_travel_mm) + "}";
  std::string flags = "null";
  if (f.flags) {
    flags = "[";
    for (std::size_t i = 0; i < f.flags->size(); ++i) flags += (i ? ", " : "") + str((*f.flags)[i]);
    flags += "]";
  }
  return "{\"frame\": " + std::to_string(f.frame) + ", \"t_s\": " + num(f.t_s) + ", \"scene\": " + str(f.scene) +
         ", \"state\": " + str(probe_state_name(p.state)) + ", \"distance_mm\": " + distance +
         ", \"pressed_mm\": " + num(p.pressed_mm) + ", \"held_mm\": " + num(p.held_mm) + ", \"penetration_mm\": " + num(f.penetration_mm) + ", \"buried_mm\": " + num(f.buried_mm) +
         ", \"contact\": " + (p.state == ProbeState::kTouching ? "true" : "false") + ", \"force_n\": " + num(f.force_n) +
         ", \"view_offset_mm\": " + vec(f.view_offset_mm) + ", \"view_turn_deg\": " + num(f.view_turn_deg) +
         ", \"hand_mm\": " + vec(f.hand_mm) +
         ", \"proxy_mm\": " + vec(f.proxy_mm) + ", \"button\": " + button + ", \"flags\": " + flags +
         ", \"keys\": " + std::to_string(f.keys) +
         ", \"haptic_hz\": " + num(f.haptic_hz) + ", \"jitter_p99_us\": " + num(f.jitter_p99_us) +
         ", \"dent_mm\": " + (f.dent_mm ? num(*f.dent_mm) : std::string("null")) +
         ", \"pointer_px\": " + vec(f.pointer_px) + ", \"shadow_px\": " + vec(f.shadow_px) +
         ", \"surface_scale\": " + num(f.surface_scale) + ", \"view_moved\": " + (f.view_moved ? "true" : "false") +
         "}";
}

Status UiReportLog::open(const std::string& path) {
  if (Status st = prepare_output_dir(path); !st) return make_error("--ui-report: " + st.error().message);
  auto f = TempFile::create(path);
  if (!f) return make_error("--ui-report: " + f.error().message);
  file_.emplace(std::move(f.value()));
  pending_ = kUiReportHead;
  frames_ = 0;
  failed_ = ok_status();
  return ok_status();
}

void UiReportLog::add(const UiFrameReport& f) {
  if (!file_ || !failed_) return;
  append_ui_frame(pending_, frames_++, f);
  if (pending_.size() >= kBlockBytes) failed_ = flush();
}

Status UiReportLog::flush() {
  Status st = file_->write(pending_);
  pending_.clear();
  if (!st) return make_error("--ui-report: writing '" + file_->target() + "' failed: " + st.error().message);
  return ok_status();
}

Status UiReportLog::close(int window_w, int window_h) {
  if (!file_) return ok_status();
  Status st = failed_;
  if (st) {
    pending_ += ui_report_tail(window_w, window_h);
    st = flush();
  }
  if (st) st = file_->publish();
  file_.reset();  // unpublished: removed
  return st;
}

ReadoutsLog::~ReadoutsLog() { (void)close(); }

Status ReadoutsLog::open(const std::string& path) {
  (void)close();
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) return make_error("--readouts-log: cannot write '" + path + "': " + std::strerror(errno));
  path_ = path;
  return ok_status();
}

Status ReadoutsLog::write(const ReadoutsFrame& f) {
  if (file_ == nullptr) return ok_status();
  const std::string line = readouts_json_line(f) + "\n";
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0)
    return make_error("--readouts-log: writing '" + path_ + "' failed: " + std::strerror(errno));
  return ok_status();
}

Status ReadoutsLog::close() {
  if (file_ == nullptr) return ok_status();
  const bool ok = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok) return make_error("--readouts-log: closing '" + path_ + "' failed");
  return ok_status();
}

}  // namespace ps
