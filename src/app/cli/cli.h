// The frame every `pseudoshadow` command runs in: one CLI11 parser per command, its help,
// its messages ("pseudoshadow <command>: ...", one line) and its exit status:
//   0 ok, 1 runtime error (bad scene file, no GL context, write failure),
//   2 usage error (unknown option, bad value, malformed or misspelt --set).
// A command declares its options on `Command::app()` (shared concerns through the option
// groups in app/cli/cli_groups.h), then hands `run()` its action. Value parsers below throw
// UsageError from an option callback; the frame turns that into one line and exit 2.
#pragma once

#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include "core/result.h"

namespace ps::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRuntime = 1;
inline constexpr int kExitUsage = 2;

// The exit-status paragraph of every command's --help (docs/errors.md says the same).
inline constexpr const char* kExitStatusHelp =
    "exit status: 0 success, 1 runtime error (bad scene or input file, no GL context, write failure),\n"
    "2 usage error (unknown option, bad value, malformed or misspelt --set)";

// Thrown by option callbacks for a bad value; the message names the option and the fix.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// From an option callback that does the command's whole work and fails at run time (--gpu list
// on an EGL without devices): one line and exit 1.
struct RuntimeFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Command {
 public:
  // `name` as typed after `pseudoshadow`; `description` is the help's paragraph under usage.
  Command(std::string name, std::string description);

  CLI::App& app() { return app_; }
  const std::string& name() const { return name_; }
  // Replaces the help's "usage:" line (default: "pseudoshadow NAME [options]").
  void usage(std::string line);

  // Parses argv (argv[0] is the command's name), prints --help, maps every parse failure to one
  // line and exit 2, then calls `action` and returns its exit status.
  int run(int argc, char** argv, const std::function<int()>& action);

  // The arguments after the command's name, as given (set by run()): a stopped command prints
  // them back in its resume line (app/cli/stop_signal.h).
  const std::vector<std::string>& args() const { return args_; }

  // "pseudoshadow NAME: MESSAGE" on stderr (one line); returns the exit status to pass on.
  int fail(const Error& e, int exit_code = kExitRuntime) const;
  int usage_error(const Error& e) const { return fail(e, kExitUsage); }

 private:
  std::string unknown_argument(const std::string& arg) const;

  std::string name_, prefix_;
  CLI::App app_;
  std::vector<std::string> args_;
};

// Adds an option whose value is handed to `apply` as it is met on the command line, so
// options that feed one ordered list (--set, --overrides, --probe, ...) keep their order.
// `apply` throws UsageError for a bad value.
CLI::Option* add_ordered(CLI::App& app, const std::string& name, const std::string& value_name,
                         const std::string& help, std::function<void(const std::string&)> apply);

// Runs a command whose options live in an `Args` struct: declare(cmd, args) adds them, then
// action(cmd, args) runs after a successful parse. The entry point of every command.
template <class Args>
int run_command(int argc, char** argv, std::string name, std::string description,
                void (*declare)(Command&, Args&), int (*action)(const Command&, const Args&)) {
  Command cmd(std::move(name), std::move(description));
  Args args;
  declare(cmd, args);
  return cmd.run(argc, argv, [&] { return action(cmd, args); });
}

// Typed values; each throws UsageError whose message names `option` and shows a right input.
// "1,2,3" -> three finite doubles.
glm::dvec3 parse_vec3(std::string_view option, std::string_view text, std::string_view example);
// "512x384" -> (512, 384), each side in [1, max_side], w*h <= max_pixels.
glm::ivec2 parse_size(std::string_view text, int max_side, long long max_pixels);
// Whole number in [lo, hi].
long long parse_int(std::string_view option, std::string_view text, long long lo, long long hi);
// Finite number in (lo, hi].
double parse_positive(std::string_view option, std::string_view text, double hi, std::string_view example);

// An option taking a whole number in [lo, hi], or a number in (0, hi], stored in `out`.
template <class Int>
CLI::Option* add_int(CLI::App& app, const std::string& name, const std::string& value_name, Int& out,
                     long long lo, long long hi, const std::string& help) {
  return app.add_option_function<std::string>(
                name, [name, &out, lo, hi](const std::string& v) { out = static_cast<Int>(parse_int(name, v, lo, hi)); },
                help)
      ->type_name(value_name);
}
CLI::Option* add_positive(CLI::App& app, const std::string& name, const std::string& value_name, double& out,
                          double hi, const std::string& example, const std::string& help);
// An option taking one of `choices`, stored in `out`; a choice "prefix:FILE" takes any value that
// starts with "prefix:". Anything else: "NAME: expected A, B or C, e.g. NAME EXAMPLE (got 'V')".
CLI::Option* add_choice(CLI::App& app, const std::string& name, const std::string& value_name, std::string& out,
                        const std::vector<std::string>& choices, const std::string& example, const std::string& help);

// The one spelling of a vector as an override value: "[x,y,z]", each at %.17g (round-trips).
std::string override_value(const glm::dvec3& v);

// "did you mean 'X'?" for the closest of `candidates`, or "" when none is close.
std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace ps::cli
