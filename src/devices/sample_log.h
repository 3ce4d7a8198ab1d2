// Device logs: the text format shared by scripted trajectories and recordings.
//   # comment
//   time_s x_mm y_mm z_mm buttons
// One sample per line, whitespace separated; numbers are written with 17 significant digits so
// a recording reads back bit-exactly. nan/inf parse (so bad data can be tested) and are then
// rejected by the DeviceSanitizer; malformed lines are errors "file:line: what".
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "devices/device.h"

namespace ps {

Result<std::vector<DeviceSample>> parse_sample_log(std::string_view text, const std::string& source);
Result<std::vector<DeviceSample>> load_sample_log(const std::string& path);
std::string format_sample(const DeviceSample& s);  // one line with '\n'

// Appends samples in memory (no file I/O on the haptic thread) and writes the file atomically
// on close(); the caller closes after the haptic thread has been joined.
class SampleRecorder {
 public:
  explicit SampleRecorder(std::string path);
  void append(const DeviceSample& s);
  Status close();
  std::size_t count() const { return count_; }

 private:
  std::string path_, text_;
  std::size_t count_ = 0;
};

// Replays a log. interpolate = false (playback): sample-and-hold of the last sample whose time
// is <= now, exactly as recorded (H3DAPI's PlaybackHapticsDevice). interpolate = true
// (trajectory): positions linearly interpolated between script lines, time = now.
class LogDevice final : public Device {
 public:
  LogDevice(std::vector<DeviceSample> samples, bool interpolate, std::string name);
  DeviceSample read(double now_s) override;
  double duration_s() const override;
  std::string name() const override { return name_; }

 private:
  std::vector<DeviceSample> samples_;
  std::size_t index_ = 0;
  bool interpolate_;
  std::string name_;
};

// "trajectory:FILE" or "playback:FILE" -> LogDevice (errors name the file and line).
Result<std::unique_ptr<LogDevice>> open_log_device(const std::string& spec);

}  // namespace ps
