// The JSON-lines event log (`run --events`, `replay --events`): one event_json() line per event,
// in the order they are appended (time order: see app/session/event_dispatch.h). Written like a device
// recording (devices/sample_log.h):
//   open()    checks the directory rule and opens "<path>.partial";
//   append()  buffers a line;
//   flush()   hands the lines to the kernel (fflush): after a crash of the process
//             "<path>.partial" holds every event up to the last flush. `run` flushes once per
//             frame that had events; no fsync there, so the render thread never waits on a disk;
//   close()   flushes, fsyncs and renames "<path>.partial" to <path> (rename_durable).
#pragma once

#include <cstdio>
#include <memory>
#include <string>

#include "core/result.h"
#include "haptics/events.h"

namespace ps {

class EventLog {
 public:
  static Result<std::unique_ptr<EventLog>> open(const std::string& path);
  ~EventLog();
  EventLog(const EventLog&) = delete;
  EventLog& operator=(const EventLog&) = delete;

  void append(const HapticEvent& e);  // a write error is kept and reported by flush()/close()
  Status flush();
  Status close();
  // Closes and removes "<path>.partial": a command that fails leaves no log behind (`replay`).
  void discard();

  const std::string& path() const { return path_; }
  std::string partial_path() const { return path_ + ".partial"; }
  std::uint64_t lines() const { return lines_; }

 private:
  explicit EventLog(std::string path) : path_(std::move(path)) {}
  Status failure(const char* what);
  std::string path_;
  std::FILE* file_ = nullptr;
  std::uint64_t lines_ = 0;
  bool failed_ = false;
  bool pending_ = false;  // lines appended since the last flush
};

}  // namespace ps
