// SIGTERM, SIGINT and SIGHUP as a request to stop, for the commands that hold a participant's
// or a person's data open (`maze`, `calibrate`, `run`): the handler only stores the signal's
// number in a lock-free atomic (async-signal-safe); the command's loops check it and end the
// session through their normal end path, which flushes and closes every log, and the command
// then prints where the data is and how to go on (stop_line) and exits 128 + the signal's
// number (exit_code), as a shell reports a process the signal ended.
//
// SA_RESETHAND: the first signal of a kind is a request; a second one of that kind finds the
// default action again and ends the process at once (a loop that never checks cannot trap it).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace ps::cli {

// The line the --help of those commands adds under the exit statuses.
inline constexpr const char* kExitSignalHelp =
    "\n128 + N: stopped by signal N (SIGTERM 143, SIGINT 130, SIGHUP 129) after ending the session and "
    "flushing its logs";

class StopSignals {
 public:
  // Installs the handlers; one StopSignals at a time (asserted).
  StopSignals();
  // Puts back the handlers that were there before.
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal that asked to stop (SIGTERM, SIGINT, SIGHUP); 0: none yet.
  int received() const;
  // The window's X display went away (gl::display_lost): the session ends as on a signal, and
  // the command exits 1 (no signal's number: nothing sent it one).
  bool display_lost() const;
  bool requested() const { return received() != 0 || display_lost(); }
  // For loops below the app layer (maze::SessionOptions::stop, calibrate::run_simulated): they
  // take a predicate, not this class, so they hold no signal state of their own.
  std::function<bool()> predicate() const;
  // 128 + received(): 143 for SIGTERM, 130 for SIGINT, 129 for SIGHUP; 1 for a lost display.
  int exit_code() const { return received() != 0 ? 128 + received() : 1; }
};

// "SIGTERM", "SIGINT", "SIGHUP" ("signal N" for any other).
std::string signal_name(int signo);

// The one line a stopped command prints on stderr:
// "COMMAND: terminated by SIGTERM; WHAT flushed to PATH; NEXT" (NEXT e.g. "resume with: ...";
// an empty WHAT or NEXT is left out with its part).
std::string stop_line(const std::string& command, int signo, const std::string& what, const std::string& path,
                      const std::string& next);
// The same for what stopped it: "terminated by SIGTERM", or "the display went away" (signo 0
// and the display lost).
std::string stop_line(const std::string& command, const StopSignals& stop, const std::string& what,
                      const std::string& path, const std::string& next);

// "pseudoshadow COMMAND ARGS... OPTION VALUE": the command line given (`args`: after the
// command's name, Command::args()) with OPTION (and its value, as "OPTION V" or "OPTION=V")
// replaced by OPTION VALUE; words with characters a shell treats specially are single-quoted.
std::string command_with(const std::string& command, const std::vector<std::string>& args, const std::string& option,
                         const std::string& value);

}  // namespace ps::cli
