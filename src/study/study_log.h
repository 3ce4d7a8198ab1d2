// A participant's trial log (docs/study.md, "The trial log"): DIR/PARTICIPANT/trials.jsonl, JSON
// lines written whole and fsync'd one by one through the maze's SessionLog (maze/maze_log.h), so
// a killed run leaves every trial it reported. Each line ends in a "sha256" member: the SHA-256
// (FIPS 180-4, OpenSSL's libcrypto) of the previous line's checksum followed by this line's text
// up to that member. The chain makes an edited, removed or reordered line show at the first line
// it breaks; `study summarize` refuses such a log naming file:line.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/result.h"

namespace ps::study {

inline constexpr const char* kStudyLogSchema = "pseudoshadow-study/1";

// The SHA-256 of `data`, 64 lowercase hex digits.
std::string sha256_hex(std::string_view data);
// The SHA-256 of a file's bytes (an experiment file's, written into its logs); that of no bytes
// when it cannot be read.
std::string file_sha256(const std::string& path);

// A participant's folder locked (flock) while a run writes its log: a second run of the same
// participant (a resume started while the first still writes) is refused instead of
// interleaving its trials. The kernel drops the lock when the process ends, however it ends.
class DirLock {
 public:
  explicit DirLock(const std::string& dir);
  ~DirLock();
  DirLock(const DirLock&) = delete;
  DirLock& operator=(const DirLock&) = delete;
  bool held() const { return fd_ >= 0; }

 private:
  int fd_;
};

// `payload` (a JSON object's text, "{...}") with its checksum member appended, chained to `prev`
// (the previous line's checksum; "" for the first line).
std::string seal_line(const std::string& payload, const std::string& prev);

struct LogLine {
  int number = 0;         // from 1
  nlohmann::json json;
  std::string checksum;   // its "sha256"
};

struct TrialLog {
  std::vector<LogLine> lines;
  std::string torn;  // a warning naming file:line when the last line was cut off (left out)
};

// Reads and checks a trial log: every line JSON with a checksum that matches its text and the
// line before. Errors name file:line; a last line cut off while it was written is left out with
// a warning in `torn` (maze::torn_last_line), never an error.
Result<TrialLog> read_trial_log(const std::string& path);

}  // namespace ps::study
