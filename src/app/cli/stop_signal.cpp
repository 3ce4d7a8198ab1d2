#include "app/cli/stop_signal.h"

#include <array>
#include <atomic>
#include <cassert>
#include <csignal>

#include "gl/context.h"

namespace ps::cli {

namespace {

// Written by the handler, read by the loops. A lock-free atomic is async-signal-safe to store
// (a plain int would not be guaranteed visible to the other threads: the haptic thread may be
// the one the kernel interrupts).
std::atomic<int> g_received{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free atomic");
bool g_installed = false;

constexpr std::array<int, 3> kSignals = {SIGTERM, SIGINT, SIGHUP};
std::array<struct sigaction, kSignals.size()> g_previous{};

extern "C" void on_stop_signal(int signo) {
  // The first signal wins: a SIGHUP after a SIGTERM does not change what the message says.
  int none = 0;
  g_received.compare_exchange_strong(none, signo, std::memory_order_relaxed);
}

}  // namespace

StopSignals::StopSignals() {
  assert(!g_installed && "StopSignals: one at a time (the handlers are process-wide)");
  g_installed = true;
  g_received.store(0, std::memory_order_relaxed);
  struct sigaction sa {};
  sa.sa_handler = &on_stop_signal;
  sigemptyset(&sa.sa_mask);
  // SA_RESTART: a read or write the signal interrupts goes on (the loops see the flag next
  // time round); SA_RESETHAND: a second signal of the kind ends the process.
  sa.sa_flags = SA_RESTART | SA_RESETHAND;
  for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &sa, &g_previous[i]);
}

StopSignals::~StopSignals() {
  for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
  g_installed = false;
}

int StopSignals::received() const { return g_received.load(std::memory_order_relaxed); }

bool StopSignals::display_lost() const { return gl::display_lost(); }

std::function<bool()> StopSignals::predicate() const {
  return [] { return g_received.load(std::memory_order_relaxed) != 0 || gl::display_lost(); };
}

std::string signal_name(int signo) {
  switch (signo) {
    case SIGTERM: return "SIGTERM";
    case SIGINT: return "SIGINT";
    case SIGHUP: return "SIGHUP";
    default: return "signal " + std::to_string(signo);
  }
}

namespace {

std::string stopped_line(const std::string& command, const std::string& cause, const std::string& what,
                         const std::string& path, const std::string& next) {
  return command + ": " + cause + (what.empty() ? "" : "; " + what + " flushed to " + path) + (next.empty() ? "" : "; " + next);
}

}  // namespace

std::string stop_line(const std::string& command, int signo, const std::string& what, const std::string& path,
                      const std::string& next) {
  return stopped_line(command, "terminated by " + signal_name(signo), what, path, next);
}

std::string stop_line(const std::string& command, const StopSignals& stop, const std::string& what,
                      const std::string& path, const std::string& next) {
  if (stop.received() != 0) return stop_line(command, stop.received(), what, path, next);
  return stopped_line(command, "the display went away (the X server ended or the connection dropped)", what, path, next);
}

namespace {

std::string shell_word(const std::string& w) {
  const bool plain = !w.empty() && w.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                       "0123456789_./:=,+-@%") == std::string::npos;
  if (plain) return w;
  std::string q = "'";
  for (const char c : w) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string command_with(const std::string& command, const std::vector<std::string>& args, const std::string& option,
                         const std::string& value) {
  std::string line = "pseudoshadow " + command;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == option) {
      ++i;  // and its value
      continue;
    }
    if (args[i].rfind(option + "=", 0) == 0) continue;
    line += " " + shell_word(args[i]);
  }
  return line + " " + option + " " + shell_word(value);
}

}  // namespace ps::cli
