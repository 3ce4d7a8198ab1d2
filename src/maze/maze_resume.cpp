#include "maze/maze_resume.h"

#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/json_int.h"

namespace ps::maze {

namespace {

using nlohmann::json;

template <class E>
E parse_name(const json& j, bool (*parse)(const std::string&, E&), const char* what) {
  E out{};
  if (!j.is_string() || !parse(j.get<std::string>(), out)) throw std::runtime_error(std::string("unknown ") + what + " " + j.dump());
  return out;
}

void read_start(const json& j, ResumePoint& r) {
  SessionInfo& info = r.info;
  if (j.contains("planned_orders"))
    for (const json& order : j.at("planned_orders")) {
      std::array<Cue, 5> o{};
      for (std::size_t k = 0; k < 5; ++k) o[k] = parse_name<Cue>(order.at(k), &parse_cue, "cue");
      r.planned.push_back(o);
    }
  info.participant = j.at("participant").get<std::string>();
  info.session = json_int_or(j, "session", 1);
  info.cues = j.at("cues").get<bool>();
  info.seed = json_int<std::uint64_t>(j.at("seed"), "seed");
  info.maze_path = j.at("maze").get<std::string>();
  info.device = j.at("device").get<std::string>();
  info.device_log = j.at("device_log").get<std::string>();
  info.max_passes = json_int<int>(j.at("max_passes"), "max_passes");
}

// A branch line back into the trial the tracker logged (the fields the score and the summary use).
Trial read_trial(const json& j) {
  Trial t;
  t.pass = json_int<int>(j.at("pass"), "pass") - 1;
  t.index = json_int<int>(j.at("room"), "room") - 1;
  t.cue = parse_name<Cue>(j.at("cue"), &parse_cue, "cue");
  t.chosen = parse_name<Exit>(j.at("exit"), &parse_exit, "exit");
  t.correct = parse_name<Exit>(j.at("correct_exit"), &parse_exit, "exit");
  t.ok = j.at("correct").get<bool>();
  t.enter_s = j.at("enter_s").get<double>();
  t.exit_s = j.at("time_s").get<double>();
  t.path_mm = j.at("path_mm").get<double>();
  return t;
}

void read_line(const json& j, ResumePoint& r) {
  const std::string type = j.at("type").get<std::string>();
  if (type == "session_start") {
    read_start(j, r);
  } else if (type == "pass_start") {
    r.current_started = json_int<int>(j.at("pass"), "pass") == static_cast<int>(r.done.size()) + 1;
    r.time_s = std::max(r.time_s, j.at("time_s").get<double>());
  } else if (type == "branch") {
    const Trial t = read_trial(j);
    if (t.pass != r.current.pass || t.index != static_cast<int>(r.current.trials.size()))
      throw std::runtime_error("branch out of order (pass " + std::to_string(t.pass + 1) + ", room " + std::to_string(t.index + 1) + ")");
    if (r.current.trials.empty()) r.current.start_s = t.enter_s;
    r.current.trials.push_back(t);
    r.time_s = std::max(r.time_s, t.exit_s);
  } else if (type == "pass_end") {
    r.current.end_s = j.at("time_s").get<double>();
    r.done.push_back(r.current);
    r.current = PassScore{};
    r.current.pass = static_cast<int>(r.done.size());
    r.current_started = false;
  } else if (type == "session_end") {
    r.ended = parse_name<EndReason>(j.at("reason"), &parse_end_reason, "session_end reason");
  } else if (type == "resumed") {
    ++r.resumes;
    r.ended.reset();  // a quit (or terminated) session resumed is open again
  }
}

}  // namespace

glm::dvec3 resume_place(const MazeDesc& desc, const ResumePoint& r) {
  const RoomGeometry g = room_geometry(desc);
  const int slot = r.current.pass * kRoomsPerPass + static_cast<int>(r.current.trials.size()) - 1;
  if (slot < 0) return g.start(desc.probe_radius_mm);
  return {0.0, g.hall_y(slot), desc.probe_radius_mm + 1.0};
}

Result<ResumePoint> read_resume_point(const std::string& log_path) {
  ResumePoint r;
  auto n = read_session_log(log_path, "give the DIR a `maze` run wrote", ", nothing to resume (start the session again)",
                            [&](const json& j, const std::string&) { read_line(j, r); }, &r.torn);
  if (!n) return n.error();
  if (r.ended && completes_session(*r.ended))
    return make_error(log_path + ":" + std::to_string(n.value()) + ": the session ended (" + end_reason_name(*r.ended) +
                      "): nothing to resume");
  // Its last pass met the criterion but the session_end line after it is missing (the process
  // stopped, or that line was cut off in its write): the session ended all the same.
  if (!r.ended && !r.done.empty() && r.done.back().correct() == kRoomsPerPass)
    return make_error(log_path + ":" + std::to_string(n.value()) + ": the session ended (criterion: pass " +
                      std::to_string(r.done.size()) + " had every room right; its session_end line is missing" +
                      (r.torn.empty() ? "" : ", cut off") + "): nothing to resume");
  return r;
}

}  // namespace ps::maze
