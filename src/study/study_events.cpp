#include "study/study_events.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/file_io.h"

namespace ps::study {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;  // the sidecar's members in the columns' order

std::string bids_label(const std::string& name) {
  std::string out;
  bool upper = false;
  for (const char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 || static_cast<unsigned char>(c) >= 0x80) {
      upper = !out.empty();
      continue;
    }
    out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return out;
}

namespace {

// One column: its name in the table (a trial line's member of the same name, but for trial_type,
// which is the member "condition") and its sidecar entry.
struct Column {
  std::string name, member;
  ojson description;
};

ojson describe(const std::string& long_name, const std::string& description, const std::string& units = "",
               const ojson& levels = ojson()) {
  ojson d = {{"LongName", long_name}, {"Description", description}};
  if (!units.empty()) d["Units"] = units;
  if (!levels.is_null()) d["Levels"] = levels;
  return d;
}

std::string joined(const json& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n.get<std::string>();
  return out;
}

// A cell: a log member's value as text. Missing, null or empty is "n/a" (BIDS); true and false
// are 1 and 0; numbers as the log writes them; tabs and line breaks in a name become spaces.
std::string cell(const json& trial, const std::string& member) {
  const auto it = trial.find(member);
  if (it == trial.end() || it->is_null()) return "n/a";
  if (it->is_boolean()) return it->get<bool>() ? "1" : "0";
  if (!it->is_string()) return it->dump();
  std::string s = it->get<std::string>();
  for (char& c : s)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return s.empty() ? "n/a" : s;
}

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", s);
  return b;
}

std::vector<Column> columns_of(const json& start) {
  const std::string task = start.at("task");
  const json& conditions = start.at("conditions");
  ojson condition_levels = ojson::object();
  for (const auto& c : conditions) condition_levels[c.get<std::string>()] = "condition '" + c.get<std::string>() + "' of the experiment";
  const json& keys = start.at("response_keys");
  std::vector<Column> cols = {
      {"onset", "", describe("Onset", "Start of the trial from the start of the session. The simulated run logs no times: this is its "
                                      "simulated clock, one trial per " + seconds(kSimulatedTrialSeconds) + " s, trial k at (k - 1) s.", "s")},
      {"duration", "", describe("Duration", "How long the trial lasted; n/a: the simulated run logs no times.", "s")},
      {"trial_type", "condition",
       describe("Condition", "The experiment's condition the trial belongs to (the log's \"condition\").", "", condition_levels)},
      {"trial", "trial", describe("Trial number", "The trial's number in the session, from 1, practice trials included.")},
      {"practice", "practice",
       describe("Practice trial", "Whether the trial was a practice trial (never fitted).", "",
                {{"1", "practice trial"}, {"0", "trial of a block"}})},
      {"block", "block", describe("Block", "The block the trial belongs to, from 1; 0 for practice trials.")},
  };
  if (task == "threshold") {
    const json& t = start.at("threshold");
    const std::string unit = "in the unit of the scene key(s) " + joined(t.at("keys"));
    ojson intervals = {{"1", "interval 1"}, {"2", "interval 2"}};
    ojson key_levels = ojson::object();
    for (std::size_t i = 0; i < keys.size(); ++i) key_levels[keys[i].get<std::string>()] = "names interval " + std::to_string(i + 1);
    cols.push_back({"level", "level", describe("Level", "The difference shown: the comparison minus the reference, " + unit + ".")});
    cols.push_back({"reference", "reference", describe("Reference", "The reference level, " + unit + ".")});
    cols.push_back({"comparison", "comparison", describe("Comparison", "The comparison level: the reference plus the difference, " + unit + ".")});
    cols.push_back({"interval", "interval", describe("Comparison interval", "The interval that showed the comparison.", "", intervals)});
    cols.push_back({"response", "response", describe("Response", "The interval the participant named.", "", intervals)});
    cols.push_back({"key", "key", describe("Response key", "The key of the response.", "", key_levels)});
  } else if (task == "targeting") {
    cols.push_back({"sequence", "sequence", describe("Sequence", "The (D, W) sequence of the block and condition the movement belongs to, from 1.")});
    cols.push_back({"ring_diameter", "ring_diameter", describe("Ring diameter", "D: the diameter of the ring of targets.", "mm")});
    cols.push_back({"distance", "distance", describe("Movement distance", "The centre-to-centre distance from the target left to the one selected (the ring's chord).", "mm")});
    cols.push_back({"width", "width", describe("Target width", "W: the targets' diameter.", "mm")});
    cols.push_back({"from", "from", describe("Target left", "The index on the ring of the target the movement started from.")});
    cols.push_back({"target", "target", describe("Target", "The index on the ring of the target to select.")});
    cols.push_back({"movement_time_s", "movement_time_s", describe("Movement time", "From leaving the last target to the selection.", "s")});
    cols.push_back({"hit", "hit", describe("Hit", "Whether the selection was inside the target.", "", {{"1", "inside"}, {"0", "a miss"}})});
    return cols;  // no "correct": a selection is a hit or a miss
  } else {
    const json& materials = start.at("materials");
    ojson names = ojson::object(), indices = ojson::object(), key_levels = ojson::object();
    for (std::size_t i = 0; i < materials.size(); ++i) {
      const std::string m = materials[i].get<std::string>();
      names[m] = "material '" + m + "'";
      indices[std::to_string(i)] = "material '" + m + "'";
      if (i < keys.size()) key_levels[keys[i].get<std::string>()] = "names material '" + m + "'";
    }
    cols.push_back({"shown", "shown", describe("Material shown", "The material the trial showed.", "", names)});
    cols.push_back({"shown_index", "shown_index", describe("Material shown, index", "The shown material's place in the experiment's list, from 0.", "", indices)});
    cols.push_back({"answered", "answered", describe("Material named", "The material the participant named.", "", names)});
    cols.push_back({"answered_index", "answered_index", describe("Material named, index", "The named material's place in the experiment's list, from 0.", "", indices)});
    cols.push_back({"key", "key", describe("Response key", "The key of the response.", "", key_levels)});
  }
  cols.push_back({"correct", "correct", describe("Correct", "Whether the response was correct.", "", {{"1", "correct"}, {"0", "wrong"}})});
  return cols;
}

}  // namespace

Result<SessionEvents> session_events(const TrialLog& log, const std::string& log_path) {
  if (!log.torn.empty()) return make_error(log.torn + "; no events file for a log cut off (resume the participant)");
  const LogLine& start = log.lines.front();
  bool ended = false;
  for (const LogLine& l : log.lines) ended |= l.json.value("type", "") == "session_end";
  if (!ended) return make_error(log_path + ": the session has not ended (no session_end line): no events file until it has");
  SessionEvents ev;
  std::vector<Column> cols;
  try {
    const std::string participant = bids_label(start.json.at("participant"));
    const std::string task = bids_label(start.json.at("experiment"));
    if (participant.empty() || task.empty())
      return make_error(log_path + ":1: the participant or experiment name holds no letter or digit for a BIDS label");
    ev.stem = "sub-" + participant + "_task-" + task + "_events";
    cols = columns_of(start.json);
  } catch (const std::exception& e) {
    return make_error(log_path + ":1: not a study log's session_start line (" + e.what() + "); docs/study.md lists the schema");
  }
  std::ostringstream tsv;
  ojson sidecar = ojson::object();
  for (std::size_t i = 0; i < cols.size(); ++i) {
    tsv << (i ? "\t" : "") << cols[i].name;
    sidecar[cols[i].name] = cols[i].description;
  }
  tsv << "\n";
  for (const LogLine& l : log.lines) {
    if (l.json.value("type", "") != "trial") continue;
    const json& trial_number = l.json.value("trial", json());
    if (!trial_number.is_number_integer() || trial_number.get<long long>() < 1)
      return make_error(log_path + ":" + std::to_string(l.number) + ": a trial line without its \"trial\" number");
    tsv << json((trial_number.get<long long>() - 1) * kSimulatedTrialSeconds).dump() << "\tn/a";
    for (std::size_t i = 2; i < cols.size(); ++i) tsv << "\t" << cell(l.json, cols[i].member);
    tsv << "\n";
  }
  ev.tsv = tsv.str();
  ev.json = sidecar.dump(2) + "\n";
  return ev;
}

Result<EventsFiles> write_session_events(const std::string& log_path) {
  Result<TrialLog> log = read_trial_log(log_path);
  if (!log) return log.error();
  return write_session_events(log.value(), log_path);
}

Result<EventsFiles> write_session_events(const TrialLog& log, const std::string& log_path) {
  Result<SessionEvents> ev = session_events(log, log_path);
  if (!ev) return ev.error();
  const std::filesystem::path dir = std::filesystem::path(log_path).parent_path();
  EventsFiles f{(dir / (ev->stem + ".tsv")).string(), (dir / (ev->stem + ".json")).string()};
  if (Status s = write_file_atomic(f.json, ev->json); !s) return s.error();
  if (Status s = write_file_atomic(f.tsv, ev->tsv); !s) return s.error();
  return f;
}

}  // namespace ps::study
