// The maze session log (docs/maze.md, "The session log"): JSON lines, one object per line, each
// with a "type". Every line is written whole by one write(2) on an O_APPEND descriptor and then
// fsync'd, so a process killed at any moment leaves a file of complete lines up to the last one
// written (never a line lost once append() returned; half a line only where the write itself
// was cut: a power cut, a full disk, which the readers leave out with a warning). Lines are few (one per
// room entered and left, one per pass), so the fsync costs nothing the session would notice.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/result.h"
#include "maze/maze_track.h"

namespace ps::maze {

inline constexpr const char* kLogSchema = "pseudoshadow-maze/1";

// Why a session ended: session_end's `reason`. kCriterion and kMaxPasses end it by the study's
// rule; the others cut it short (`maze --resume` goes on from them).
enum class EndReason {
  kCriterion,      // a pass with every room right
  kMaxPasses,      // the description's max_passes without one
  kDeviceEnded,    // a log device played to its end
  kQuit,           // Esc or Q in the window
  kPracticeEnded,  // Space or Enter ended the practice pass (DIR/practice/ only)
  kTerminated,     // SIGTERM, SIGINT or SIGHUP (docs/maze.md, "A signal")
  kDisplayLost,    // the window's X display went away (docs/maze.md, "A signal")
};
const char* end_reason_name(EndReason r);  // "criterion", "max_passes", ...
bool parse_end_reason(const std::string& name, EndReason& out);
// Ended by the study's rule (criterion, max_passes): complete, nothing to resume.
inline bool completes_session(EndReason r) { return r == EndReason::kCriterion || r == EndReason::kMaxPasses; }

// The text's last line if it was cut off while written: no newline after it and not JSON (none:
// the text ends with a whole line).
std::optional<std::string> torn_last_line(const std::string& text);

// Reads a session log: each non-empty line parsed and handed to `on_line` with its
// "file:line: " prefix (for its own errors: an exception it throws becomes one); the first line
// must be the session_start line. Returns how many lines the file has. Errors name file:line;
// `open_hint` ends the message when the file cannot be opened, `empty_hint` when it holds no
// session_start line.
// A last line cut off (no newline after it, and not JSON: SIGKILL or a power cut in the middle
// of its write; one write(2) per line makes that rare, a full disk can do it too) is no error:
// it is left out and `torn` (if given) gets a warning naming file:line.
Result<int> read_session_log(const std::string& path, const std::string& open_hint, const std::string& empty_hint,
                             const std::function<void(const nlohmann::json&, const std::string& where)>& on_line,
                             std::string* torn = nullptr);

struct SessionInfo {
  std::string participant;
  bool cues = true;
  std::uint64_t seed = 0;
  std::string maze_path;     // the description
  std::string device;        // as given: trajectory:FILE, playback:FILE, mouse, ...
  std::string device_log;    // the device stream's file name, next to the log
  int max_passes = 10;
  // Which session of this participant: 1 the first, 2 a retest "after a short time"
  // (Sepulveda-Cervantes et al. §VII), ... `maze summarize` compares a participant's sessions.
  int session = 1;
};

// The two system calls each line takes, injectable so a test can observe them: a kill test
// cannot see a missing fsync (the page cache keeps the data either way). Empty: write(2) and
// fsync(2) themselves.
struct LogSyscalls {
  std::function<long(int fd, const char* data, std::size_t size)> write;
  std::function<int(int fd)> fsync;
};

class SessionLog {
 public:
  // Creates `path` (its directory must exist); an existing file is an error, never truncated.
  static Result<SessionLog> open(const std::string& path, LogSyscalls sys = {});
  // Opens an existing log to append to (`maze --resume`): never created; a torn last line
  // (torn_last_line) moves to PATH.torn and is cut off, nothing else.
  static Result<SessionLog> open_existing(const std::string& path, LogSyscalls sys = {});
  SessionLog(SessionLog&& o) noexcept
      : fd_(o.fd_), path_(std::move(o.path_)), lines_(o.lines_), sys_(std::move(o.sys_)) {
    o.fd_ = -1;
  }
  SessionLog(const SessionLog&) = delete;
  SessionLog& operator=(const SessionLog&) = delete;
  SessionLog& operator=(SessionLog&&) = delete;
  ~SessionLog();

  Status session_start(const SessionInfo& info, const Route& route);
  Status pass_start(int pass, const std::array<Cue, kRoomsPerPass>& order, double time_s);
  Status event(const SessionInfo& info, const TrackEvent& e);
  // The live window's clutch: the hand, run on past a wall by overshoot_mm, was put back under
  // the probe (positions on the floor, x and y in mm).
  Status clutch(double time_s, double overshoot_mm, const glm::dvec3& hand_mm, const glm::dvec3& probe_mm);
  // `maze --resume`: the session goes on at `pass`, `room` (from 0) at session time time_s, with
  // `device`, its stream in device_log (the resume's own file); resume counts from 1.
  Status resumed(int resume, int pass, int room, double time_s, const std::string& device, const std::string& device_log);
  Status session_end(EndReason reason, int passes, int trials_to_criterion, double time_s);
  // Any other JSON line, written and fsync'd as every line above (`study run`'s trials).
  Status append_line(const std::string& json_line) { return append(json_line); }
  const std::string& path() const { return path_; }
  int lines() const { return lines_; }

 private:
  SessionLog(int fd, std::string path, LogSyscalls sys) : fd_(fd), path_(std::move(path)), sys_(std::move(sys)) {}
  Status append(const std::string& json_line);
  int fd_ = -1;
  std::string path_;
  int lines_ = 0;
  LogSyscalls sys_;
};

}  // namespace ps::maze
