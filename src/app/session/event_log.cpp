#include "app/session/event_log.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/file_io.h"

namespace ps {

Result<std::unique_ptr<EventLog>> EventLog::open(const std::string& path) {
  if (Status s = prepare_output_dir(path); !s) return s.error();
  std::unique_ptr<EventLog> log(new EventLog(path));
  log->file_ = std::fopen(log->partial_path().c_str(), "wb");
  if (log->file_ == nullptr)
    return make_error(log->partial_path() + ": cannot write event log: " + std::strerror(errno));
  return log;
}

EventLog::~EventLog() {
  if (file_ != nullptr) std::fclose(file_);  // not closed: "<path>.partial" stays, as after a crash
}

Status EventLog::failure(const char* what) {
  failed_ = true;
  return make_error(partial_path() + ": cannot write event log (" + what + "): " + std::strerror(errno));
}

void EventLog::append(const HapticEvent& e) {
  if (file_ == nullptr || failed_) return;
  const std::string line = event_json(e) + '\n';
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size()) failed_ = true;
  ++lines_;
  pending_ = true;
}

Status EventLog::flush() {
  if (failed_) return make_error(partial_path() + ": cannot write event log (disk full?)");
  if (file_ == nullptr || !pending_) return ok_status();
  pending_ = false;
  if (std::fflush(file_) != 0) return failure("flush");
  return ok_status();
}

Status EventLog::close() {
  if (file_ == nullptr) return ok_status();
  pending_ = true;
  if (Status s = flush(); !s) return s;
  if (fsync(fileno(file_)) != 0) return failure("fsync");
  std::fclose(file_);
  file_ = nullptr;
  return rename_durable(partial_path(), path_);
}

}  // namespace ps

namespace ps {

void EventLog::discard() {
  if (file_ == nullptr) return;
  std::fclose(file_);
  file_ = nullptr;
  std::error_code ignored;  // best effort: the command is failing with its own message already
  std::filesystem::remove(partial_path(), ignored);
}

}  // namespace ps
