#include "devices/sample_log.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/file_io.h"

namespace ps {

namespace {

Result<double> parse_number(const std::string& word, const std::string& where, const char* what) {
  char* end = nullptr;
  const double v = std::strtod(word.c_str(), &end);
  if (word.empty() || end != word.c_str() + word.size())
    return make_error(where + ": " + what + ": not a number: '" + word + "'");
  return v;
}

// The five fields of a log line; the names differ between the mm logs and the pointer log.
struct LogFields {
  const char* names[4];
  const char* line;  // the whole line, for the messages
};
constexpr LogFields kSampleFields{{"time_s", "x", "y", "z"}, "time_s x y z buttons"};
constexpr LogFields kPointerFields{{"time_s", "x_px", "y_px", "height_mm"}, "time_s x_px y_px height_mm buttons"};

Result<DeviceSample> parse_line(const std::string& line, const std::string& where, const LogFields& fields) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  if (words.size() != 5)
    return make_error(where + ": expected 5 fields '" + fields.line + "', got " + std::to_string(words.size()));
  double v[4];
  for (int i = 0; i < 4; ++i) {
    auto r = parse_number(words[static_cast<size_t>(i)], where, fields.names[i]);
    if (!r) return r.error();
    v[i] = r.value();
  }
  char* end = nullptr;
  const unsigned long b = std::strtoul(words[4].c_str(), &end, 10);
  if (end != words[4].c_str() + words[4].size() || words[4][0] == '-' || b > 0xffffffffUL)
    return make_error(where + ": buttons: expected a bitmask 0..4294967295, got '" + words[4] + "'");
  return DeviceSample{v[0], {v[1], v[2], v[3]}, static_cast<std::uint32_t>(b), true};
}

Result<std::vector<DeviceSample>> parse_log(std::string_view text, const std::string& source, const LogFields& fields) {
  std::vector<DeviceSample> out;
  std::istringstream in{std::string(text)};
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    auto s = parse_line(line, source + ":" + std::to_string(line_no), fields);
    if (!s) return s.error();
    out.push_back(s.value());
  }
  if (out.empty()) return make_error(source + ": no samples (expected lines '" + fields.line + "')");
  return out;
}

Result<std::vector<DeviceSample>> load_log(const std::string& path, const LogFields& fields) {
  const std::optional<std::string> text = read_whole_file(path);
  if (!text) return make_error(path + ": cannot open device log: " + std::strerror(errno));
  return parse_log(*text, path, fields);
}

}  // namespace

Result<std::vector<DeviceSample>> parse_sample_log(std::string_view text, const std::string& source) {
  return parse_log(text, source, kSampleFields);
}

Result<std::vector<DeviceSample>> load_sample_log(const std::string& path) { return load_log(path, kSampleFields); }

Result<std::vector<DeviceSample>> parse_pointer_log(std::string_view text, const std::string& source) {
  return parse_log(text, source, kPointerFields);
}

std::string format_sample(const DeviceSample& s) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %.17g %u\n", s.time_s, s.position_mm.x,
                s.position_mm.y, s.position_mm.z, s.buttons);
  return buf;
}

SampleRecorder::SampleRecorder(std::string path) : path_(std::move(path)) {
  pending_ = "# pseudoshadow device log: time_s x_mm y_mm z_mm buttons\n";
}

SampleRecorder::~SampleRecorder() {
  if (partial_ != nullptr) std::fclose(partial_);
}

void SampleRecorder::append(const DeviceSample& s) {
  if (!s.valid) return;
  const std::string line = format_sample(s);  // format outside the lock
  std::lock_guard<std::mutex> lock(mutex_);
  pending_ += line;
  ++count_;
}

std::size_t SampleRecorder::count() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return count_;
}

Status SampleRecorder::flush() {
  if (failed_) return make_error(path_ + ": cannot write device log (an earlier write failed)");
  std::string text;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    text.swap(pending_);
  }
  if (partial_ == nullptr) {
    if (Status s = prepare_output_dir(path_); !s) {  // the rule of every output (core/file_io.h)
      failed_ = true;
      return s;
    }
    partial_ = std::fopen(partial_path().c_str(), "wb");
    if (partial_ == nullptr) {
      failed_ = true;
      return make_error(partial_path() + ": cannot write device log: " + std::strerror(errno));
    }
  }
  if (std::fwrite(text.data(), 1, text.size(), partial_) != text.size() || std::fflush(partial_) != 0 ||
      fsync(fileno(partial_)) != 0) {
    failed_ = true;
    return make_error(partial_path() + ": cannot write device log: " + std::strerror(errno));
  }
  return ok_status();
}

Status SampleRecorder::close() {
  if (Status s = flush(); !s) return s;
  std::fclose(partial_);
  partial_ = nullptr;
  // The same publish step as every other output: fsync, rename, fsync of the directory.
  return rename_durable(partial_path(), path_);
}

LogDevice::LogDevice(std::vector<DeviceSample> samples, bool interpolate, std::string name)
    : samples_(std::move(samples)), interpolate_(interpolate), name_(std::move(name)) {}

double LogDevice::duration_s() const { return samples_.empty() ? 0.0 : samples_.back().time_s; }

DeviceSample LogDevice::read(double now_s) {
  if (samples_.empty()) return {};
  // Out-of-order timestamps are passed on as they are: the sanitizer counts and drops them.
  while (index_ + 1 < samples_.size() && !(samples_[index_ + 1].time_s > now_s)) ++index_;
  const DeviceSample& a = samples_[index_];
  if (!interpolate_ || index_ + 1 >= samples_.size() || now_s <= a.time_s) return a;
  const DeviceSample& b = samples_[index_ + 1];
  if (!(b.time_s > a.time_s)) return a;
  const double u = (now_s - a.time_s) / (b.time_s - a.time_s);
  DeviceSample s = a;
  s.time_s = now_s;
  s.position_mm = a.position_mm + (b.position_mm - a.position_mm) * u;
  return s;
}

Result<std::unique_ptr<LogDevice>> open_log_device(const std::string& spec) {
  auto parsed = parse_device_spec(spec, {DeviceKind::kTrajectory, DeviceKind::kPlayback});
  if (!parsed) return parsed.error();
  return open_log_device(parsed.value());
}

Result<std::unique_ptr<LogDevice>> open_log_device(const DeviceSpec& spec) {
  if (spec.kind != DeviceKind::kTrajectory && spec.kind != DeviceKind::kPlayback)
    return device_spec_error(spec.text(), {DeviceKind::kTrajectory, DeviceKind::kPlayback});
  auto samples = load_sample_log(spec.file);
  if (!samples) return samples.error();
  return std::make_unique<LogDevice>(std::move(samples.value()), spec.kind == DeviceKind::kTrajectory, spec.text());
}

}  // namespace ps

namespace ps {

PointerLogDevice::PointerLogDevice(std::vector<DeviceSample> samples, std::string name)
    : log_(std::move(samples), true, name), name_(std::move(name)) {}

DeviceSample PointerLogDevice::read(double now_s) {
  const ViewState v = view_.read();
  DeviceSample s = log_.read(now_s);
  if (!v.set) {  // nothing to map through yet
    s.valid = false;
    return s;
  }
  const glm::dvec3 script = s.position_mm;  // (x_px, y_px, height_mm)
  if (std::isfinite(script.x) && std::isfinite(script.y) && std::isfinite(script.z))
    s.position_mm = map_.absolute(v.view, {script.x, script.y}, script.z);
  else  // scripted bad data: handed on as NaN for the sanitizer to count and drop
    s.position_mm = glm::dvec3(std::nan(""));
  return s;
}

Result<std::unique_ptr<PointerLogDevice>> open_pointer_device(const std::string& spec) {
  auto parsed = parse_device_spec(spec, {DeviceKind::kPointer});
  if (!parsed) return parsed.error();
  return open_pointer_device(parsed.value());
}

Result<std::unique_ptr<PointerLogDevice>> open_pointer_device(const DeviceSpec& spec) {
  if (spec.kind != DeviceKind::kPointer) return device_spec_error(spec.text(), {DeviceKind::kPointer});
  auto samples = load_log(spec.file, kPointerFields);
  if (!samples) return samples.error();
  return std::make_unique<PointerLogDevice>(std::move(samples.value()), spec.text());
}

}  // namespace ps
