// A session's BIDS-style events file (docs/study.md, "events.tsv (BIDS)"): from a participant's
// checked trial log (study_log.h), DIR/PARTICIPANT/sub-<participant>_task-<experiment>_events.tsv
// with one row per trial (onset, duration, trial_type, then the trial's own members) and its JSON
// sidecar of the same stem describing every column. `study summarize` writes them for every log
// it reads, after the log's checksums are checked, so they cannot disagree with it; a log that
// does not check (a changed, removed or torn line) or a session not yet ended gets none.
#pragma once

#include <string>

#include "core/result.h"
#include "study/study_log.h"

namespace ps::study {

// The simulated run logs no times: its events have onsets on a clock of one trial per this many
// seconds (trial k at (k - 1) s) and no duration ("n/a").
inline constexpr double kSimulatedTrialSeconds = 1.0;

// A BIDS label (letters and digits only) from a name: other characters dropped, the letter after
// each dropped run upper-cased ("lambda_threshold" -> "lambdaThreshold"). Empty when nothing is left.
std::string bids_label(const std::string& name);

struct SessionEvents {
  std::string stem;  // sub-<participant>_task-<experiment>_events
  std::string tsv;   // the table: header, one row per trial
  std::string json;  // the sidecar: every column's LongName, Description, Units, Levels
};

// The events of a checked log; `log_path` only names it in errors. An error when the log is not a
// study log or its session did not end (no session_end line, or a last line cut off).
Result<SessionEvents> session_events(const TrialLog& log, const std::string& log_path);

struct EventsFiles {
  std::string tsv, json;  // the paths written, beside the log
};

// Reads and checks the log at `log_path` (read_trial_log), then writes its events files beside
// it, each atomically. A log that does not check is that error and writes nothing.
Result<EventsFiles> write_session_events(const std::string& log_path);
// The same from a log already read and checked (`study summarize` reads each log once).
Result<EventsFiles> write_session_events(const TrialLog& log, const std::string& log_path);

}  // namespace ps::study
