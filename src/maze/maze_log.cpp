#include "maze/maze_log.h"

#include <cerrno>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <fcntl.h>
#include <unistd.h>
#include <utility>

#include <nlohmann/json.hpp>

namespace ps::maze {

namespace {

using json = nlohmann::ordered_json;  // keys in the order written: "type" and the ids first

json per_kind(const auto& values) {
  json o = json::object();
  for (int k = 0; k < 4; ++k) o[surface_kind_name(static_cast<SurfaceKind>(k))] = values[static_cast<std::size_t>(k)];
  return o;
}

json trial_json(const SessionInfo& info, const Trial& t) {
  return {{"type", ""},
          {"participant", info.participant},
          {"pass", t.pass + 1},
          {"room", t.index + 1},
          {"cue", cue_name(t.cue)},
          {"label", cue_label(t.cue)}};
}

// A room left by an exit: the trial's choice, its time and its contacts.
json branch_json(const SessionInfo& info, const Trial& t) {
  json j = trial_json(info, t);
  j["type"] = "branch";
  j["exit"] = exit_name(t.chosen);
  j["correct_exit"] = exit_name(t.correct);
  j["correct"] = t.ok;
  j["time_s"] = t.exit_s;
  j["enter_s"] = t.enter_s;
  j["room_time_s"] = t.time_s();
  j["path_mm"] = t.path_mm;
  j["contacts"] = per_kind(t.contacts);
  j["contact_s"] = per_kind(t.contact_s);
  j["force_mean_n"] = t.force_mean_n;
  j["force_max_n"] = t.force_max_n;
  j["field_force_max_n"] = t.field_force_max_n;
  return j;
}

// A pass's end: its score, room by room.
json pass_end_json(const PassScore& s) {
  json score = json::array();
  for (const Trial& t : s.trials)
    score.push_back({{"room", t.index + 1}, {"cue", cue_name(t.cue)}, {"exit", exit_name(t.chosen)}, {"correct", t.ok}});
  return json{{"type", "pass_end"},
              {"pass", s.pass + 1},
              {"correct", s.correct()},
              {"rooms", kRoomsPerPass},
              {"pass_time_s", s.end_s - s.start_s},
              {"time_s", s.end_s},
              {"score", score}};
}

// Now, UTC, to the millisecond ("2025-03-01T10:22:33.123Z"): session_start's `started_at`, which
// tells two runs of one participant's session apart (`maze summarize` refuses one given twice).
std::string utc_now() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t secs = std::chrono::system_clock::to_time_t(now);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm tm{};
  gmtime_r(&secs, &tm);
  char buf[40];
  const std::size_t n = std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  std::snprintf(buf + n, sizeof buf - n, ".%03dZ", static_cast<int>(ms));
  return buf;
}

}  // namespace

Result<SessionLog> SessionLog::open(const std::string& path, LogSyscalls sys) {
  // O_EXCL: a participant's log is never overwritten by a later run into the same directory.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0 && errno == EEXIST)
    return make_error(path + ": a session log is already there (a participant's data is never overwritten); "
                             "give another --out, or move that one away");
  if (fd < 0) return make_error(path + ": cannot create the session log: " + std::strerror(errno));
  return SessionLog(fd, path, std::move(sys));
}

Result<SessionLog> SessionLog::open_existing(const std::string& path, LogSyscalls sys) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd < 0) return make_error(path + ": cannot open the session log to resume: " + std::strerror(errno));
  SessionLog log(fd, path, std::move(sys));
  // A line cut off (SIGKILL or a power cut in its write(2), a disk that filled up): the next
  // line must start on a line of its own, and the fragment must not stay between two whole
  // lines. It moves to PATH.torn (kept: nothing is lost) and the log ends at its last whole line.
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (const std::optional<std::string> cut = torn_last_line(text)) {
    std::ofstream(path + ".torn", std::ios::binary | std::ios::app) << *cut << '\n';
    if (::ftruncate(fd, static_cast<off_t>(text.size() - cut->size())) != 0)
      return make_error(path + ": cannot cut off the torn last line: " + std::strerror(errno));
  } else if (!text.empty() && text.back() != '\n' && ::write(fd, "\n", 1) != 1) {
    return make_error(path + ": cannot append to the session log: " + std::strerror(errno));
  }
  return log;
}

SessionLog::~SessionLog() {
  if (fd_ >= 0) ::close(fd_);
}

Status SessionLog::append(const std::string& json_line) {
  const std::string line = json_line + "\n";
  // One write of the whole line: with O_APPEND it lands whole or (on a full disk) is reported.
  const long n = sys_.write ? sys_.write(fd_, line.data(), line.size()) : ::write(fd_, line.data(), line.size());
  if (n != static_cast<long>(line.size()))
    return make_error(path_ + ": cannot append to the session log: " + (n < 0 ? std::strerror(errno) : "short write"));
  // Synced before append() returns: once a line is reported written, a power cut keeps it.
  if ((sys_.fsync ? sys_.fsync(fd_) : ::fsync(fd_)) != 0)
    return make_error(path_ + ": cannot sync the session log: " + std::strerror(errno));
  ++lines_;
  return ok_status();
}

Status SessionLog::session_start(const SessionInfo& info, const Route& route) {
  json correct = json::object(), labels = json::object();
  for (int c = 0; c <= static_cast<int>(Cue::kExternalForce); ++c) {
    correct[cue_name(static_cast<Cue>(c))] = exit_name(route.correct_exit(static_cast<Cue>(c)));
    labels[cue_name(static_cast<Cue>(c))] = cue_label(static_cast<Cue>(c));
  }
  json planned = json::array();  // a study plan's orders (maze --plan); none: drawn from the seed
  for (const auto& order : route.planned) {
    json names = json::array();
    for (const Cue c : order) names.push_back(cue_name(c));
    planned.push_back(names);
  }
  return append(json{{"type", "session_start"},
                     {"schema", kLogSchema},
                     {"participant", info.participant},
                     {"session", info.session},
                     {"condition", info.cues ? "cues_on" : "cues_off"},
                     {"cues", info.cues},
                     {"seed", info.seed},
                     {"maze", info.maze_path},
                     {"device", info.device},
                     {"device_log", info.device_log},
                     {"max_passes", info.max_passes},
                     {"correct_route", correct},
                     {"labels", labels},
                     {"planned_orders", planned},
                     {"started_at", utc_now()},
                     {"time_s", 0.0}}
                    .dump());
}

Status SessionLog::pass_start(int pass, const std::array<Cue, kRoomsPerPass>& order, double time_s) {
  json rooms = json::array();
  for (const Cue c : order) rooms.push_back(cue_name(c));
  return append(json{{"type", "pass_start"}, {"pass", pass + 1}, {"order", rooms}, {"time_s", time_s}}.dump());
}

Status SessionLog::event(const SessionInfo& info, const TrackEvent& e) {
  switch (e.kind) {
    case TrackEvent::Kind::kRoomEntered: {
      json j = trial_json(info, e.trial);
      j["type"] = "room_enter";
      j["time_s"] = e.trial.enter_s;
      return append(j.dump());
    }
    case TrackEvent::Kind::kBranch: return append(branch_json(info, e.trial).dump());
    case TrackEvent::Kind::kPassEnd: return append(pass_end_json(e.score).dump());
    case TrackEvent::Kind::kFinished: return ok_status();  // session_end says it
  }
  return ok_status();
}

Status SessionLog::clutch(double time_s, double overshoot_mm, const glm::dvec3& hand_mm, const glm::dvec3& probe_mm) {
  return append(json{{"type", "clutch"},
                     {"time_s", time_s},
                     {"overshoot_mm", overshoot_mm},
                     {"hand_mm", {hand_mm.x, hand_mm.y}},
                     {"probe_mm", {probe_mm.x, probe_mm.y}}}
                    .dump());
}

Status SessionLog::resumed(int resume, int pass, int room, double time_s, const std::string& device,
                           const std::string& device_log) {
  return append(json{{"type", "resumed"},
                     {"resume", resume},
                     {"pass", pass + 1},
                     {"room", room + 1},
                     {"time_s", time_s},
                     {"device", device},
                     {"device_log", device_log}}
                    .dump());
}

namespace {
constexpr std::pair<EndReason, const char*> kEndReasons[] = {
    {EndReason::kCriterion, "criterion"}, {EndReason::kMaxPasses, "max_passes"},
    {EndReason::kDeviceEnded, "device_ended"}, {EndReason::kQuit, "quit"},
    {EndReason::kPracticeEnded, "practice_ended"}, {EndReason::kTerminated, "terminated"},
    {EndReason::kDisplayLost, "display_lost"}};
}  // namespace

const char* end_reason_name(EndReason r) {
  for (const auto& [reason, name] : kEndReasons)
    if (reason == r) return name;
  return "?";
}

bool parse_end_reason(const std::string& name, EndReason& out) {
  for (const auto& [reason, text] : kEndReasons)
    if (name == text) {
      out = reason;
      return true;
    }
  return false;
}

Status SessionLog::session_end(EndReason reason, int passes, int trials_to_criterion, double time_s) {
  return append(json{{"type", "session_end"},
                     {"reason", end_reason_name(reason)},
                     {"passes", passes},
                     {"trials_to_criterion", trials_to_criterion > 0 ? json(trials_to_criterion) : json(nullptr)},
                     {"time_s", time_s}}
                    .dump());
}

std::optional<std::string> torn_last_line(const std::string& text) {
  if (text.empty() || text.back() == '\n') return std::nullopt;
  const std::size_t from = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  std::string last = text.substr(from);
  if (json::accept(last)) return std::nullopt;  // whole, only its newline missing
  return last;
}

Result<int> read_session_log(const std::string& path, const std::string& open_hint, const std::string& empty_hint,
                             const std::function<void(const nlohmann::json&, const std::string& where)>& on_line,
                             std::string* torn) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return make_error(path + ": cannot open the session log (" + open_hint + ")");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::optional<std::string> cut = torn_last_line(text);
  if (cut) text.resize(text.size() - cut->size());
  std::istringstream lines(text);
  bool started = false;
  int n = 0;
  for (std::string line; std::getline(lines, line);) {
    const std::string where = path + ":" + std::to_string(++n) + ": ";
    if (line.empty()) continue;
    try {
      const nlohmann::json j = nlohmann::json::parse(line);
      started |= j.at("type") == "session_start";
      if (!started) return make_error(where + "the first line must be the session_start line");
      on_line(j, where);
    } catch (const std::exception& e) {
      return make_error(where + "not a maze log line (" + e.what() + "); docs/maze.md lists the schema");
    }
  }
  if (cut && torn)
    *torn = path + ":" + std::to_string(n + 1) + ": the last line is cut off (" + std::to_string(cut->size()) +
            " bytes: the process stopped while writing it): left out";
  if (!started) return make_error(path + ":1: empty log: no session_start line" + empty_hint);
  return n;
}

}  // namespace ps::maze
