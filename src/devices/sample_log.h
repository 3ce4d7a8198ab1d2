// Device logs: the text format shared by scripted trajectories and recordings.
//   # comment
//   time_s x_mm y_mm z_mm buttons
// One sample per line, whitespace separated (a pointer log: time_s x_px y_px height_mm buttons); numbers are written with 17 significant digits so
// a recording reads back bit-exactly. nan/inf parse (so bad data can be tested) and are then
// rejected by the DeviceSanitizer; malformed lines are errors "file:line: what".
#pragma once

#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "core/snapshot.h"
#include "devices/device.h"
#include "devices/device_spec.h"
#include "devices/pointer_map.h"

namespace ps {

Result<std::vector<DeviceSample>> parse_sample_log(std::string_view text, const std::string& source);
Result<std::vector<DeviceSample>> load_sample_log(const std::string& path);
std::string format_sample(const DeviceSample& s);  // one line with '\n'
// A pointer log: position_mm holds (x_px, y_px, height_mm) of each line.
Result<std::vector<DeviceSample>> parse_pointer_log(std::string_view text, const std::string& source);

// Records a device stream without losing more than the last flush interval on a crash:
//   append()  (haptic thread) formats the sample into a pending buffer under a mutex that is
//             held for a string append only - no file I/O on the haptic thread;
//   flush()   (any other thread, about once a second) appends the pending text to
//             "<path>.partial" and fsyncs it;
//   close()   flushes and renames "<path>.partial" to <path>, so <path> only ever holds a
//             complete log (a previous recording there stays intact until then). After a crash
//             "<path>.partial" holds everything up to the last flush and can be replayed.
class SampleRecorder {
 public:
  explicit SampleRecorder(std::string path);
  ~SampleRecorder();
  SampleRecorder(const SampleRecorder&) = delete;
  SampleRecorder& operator=(const SampleRecorder&) = delete;

  void append(const DeviceSample& s);
  Status flush();
  Status close();
  std::size_t count() const;
  std::string partial_path() const { return path_ + ".partial"; }

 private:
  std::string path_;
  mutable std::mutex mutex_;  // guards pending_ and count_
  std::string pending_;
  std::size_t count_ = 0;
  std::FILE* partial_ = nullptr;  // flush()/close() only (one thread at a time)
  bool failed_ = false;
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
// The same, parsed (devices/device_spec.h): its kind trajectory or playback.
Result<std::unique_ptr<LogDevice>> open_log_device(const DeviceSpec& spec);

}  // namespace ps

namespace ps {

// A scripted pointer ("pointer:FILE"): lines 'time_s x_px y_px height_mm buttons', linearly
// interpolated like a trajectory, then mapped by the absolute pointer mapping (PointerMap) with
// the view the render thread last set, exactly as `run`'s mouse is. Until the first set_view()
// its samples are invalid. The height is used as scripted (no HeightControl limits).
class PointerLogDevice final : public Device {
 public:
  PointerLogDevice(std::vector<DeviceSample> samples, std::string name);
  // Render thread (the one writer): the camera, window and plane the pointer is mapped with.
  // The floor is the render thread's (not owned, not thread-safe): it never crosses to the
  // haptic thread, which maps from the plane.
  void set_view(const PointerView& view) {
    PointerView published = view;
    published.floor = nullptr;
    view_.publish({published, true});
  }
  DeviceSample read(double now_s) override;  // haptic thread
  double duration_s() const override { return log_.duration_s(); }
  std::string name() const override { return name_; }

 private:
  struct ViewState {
    PointerView view;
    bool set = false;
  };
  LogDevice log_;
  PointerMap map_;  // haptic thread only
  Snapshot<ViewState> view_;
  std::string name_;
};

// "pointer:FILE" -> PointerLogDevice (errors name the file and line).
Result<std::unique_ptr<PointerLogDevice>> open_pointer_device(const std::string& spec);
// The same, parsed (devices/device_spec.h): its kind pointer.
Result<std::unique_ptr<PointerLogDevice>> open_pointer_device(const DeviceSpec& spec);

}  // namespace ps
