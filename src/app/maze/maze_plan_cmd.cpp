#include "app/maze/maze_plan_cmd.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "core/file_io.h"
#include "maze/maze_plan.h"

namespace ps {

namespace {

struct PlanArgs {
  long long participants = 0, first_seed = 101, sessions = 2;
  std::string conditions = "on,off", out;
  bool quiet = false;
};

void declare_plan(cli::Command& cmd, PlanArgs& a) {
  CLI::App& app = cmd.app();
  cli::add_int(app, "--participants", "N", a.participants, 1LL, 999LL, "how many participants (required)");
  app.add_option("--conditions", a.conditions, "the conditions, alternated over participants (default on,off)")
      ->type_name("on,off");
  cli::add_int(app, "--first-seed", "S", a.first_seed, 0LL, 9'007'199'254'740'000LL,
               "participant i (from 0) gets seed S + i (default 101)");
  cli::add_int(app, "--sessions", "K", a.sessions, 1LL, 10LL, "sessions per participant: 1 + retests (default 2)");
  cli::add_output(app, "--out", a.out, "FILE.csv", "the plan CSV to write (required)");
  cli::add_quiet_option(app, a.quiet);
  cmd.usage("pseudoshadow maze plan --participants N --conditions on,off --out plan.csv");
}

int plan_main(const cli::Command& cmd, const PlanArgs& a) {
  if (a.participants <= 0 || a.out.empty())
    return cmd.usage_error(make_error("--participants N and --out FILE are required (e.g. --participants 12 --out plan.csv)"));
  maze::PlanSpec spec;
  spec.participants = static_cast<int>(a.participants);
  spec.first_seed = static_cast<std::uint64_t>(a.first_seed);
  spec.sessions = static_cast<int>(a.sessions);
  spec.conditions.clear();
  for (std::size_t at = 0; at <= a.conditions.size();) {
    const std::size_t comma = std::min(a.conditions.find(',', at), a.conditions.size());
    const std::string c = a.conditions.substr(at, comma - at);
    if (c != "on" && c != "off")
      return cmd.usage_error(make_error("--conditions: expected on and off separated by commas, e.g. on,off (got '" + c + "')"));
    spec.conditions.push_back(c == "on");
    at = comma + 1;
  }
  const auto rows = maze::make_plan(spec);
  if (Status s = prepare_output_dir(a.out); !s) return cmd.fail(s.error());
  if (Status s = write_file_atomic(a.out, maze::plan_csv(rows)); !s) return cmd.fail(s.error());
  if (!a.quiet)
    std::printf("plan: %lld participants, %zu rows (%lld session%s each) -> %s\n", a.participants, rows.size(), a.sessions,
                a.sessions == 1 ? "" : "s", a.out.c_str());
  return cli::kExitOk;
}

// A field of a session_start line as written by SessionLog (compact JSON, no spaces): the text
// between `"key":` and the next ',' or '}', quotes dropped.
std::string field(const std::string& line, const std::string& key) {
  const std::string tag = "\"" + key + "\":";
  const std::size_t at = line.find(tag);
  if (at == std::string::npos) return "";
  std::size_t b = at + tag.size(), e = line.find_first_of(",}", b);
  std::string v = line.substr(b, e == std::string::npos ? std::string::npos : e - b);
  if (v.size() >= 2 && v.front() == '"') v = v.substr(1, v.size() - 2);
  return v;
}

}  // namespace

int run_maze_plan(int argc, char** argv) {
  return cli::run_command<PlanArgs>(argc, argv, "maze plan",
                                    "Writes a study plan: participant IDs, seeds, alternated conditions and "
                                    "counterbalanced room orders (a balanced Latin square), one row per session "
                                    "(docs/maze.md, \"Planning a study\"). Run a row with `maze --plan FILE "
                                    "--participant ID`.",
                                    declare_plan, plan_main);
}

Status check_study_folder(const std::string& out_dir, const std::string& participant, int session, std::uint64_t seed) {
  namespace fs = std::filesystem;
  const fs::path out = fs::path(out_dir).lexically_normal();
  const fs::path study = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::error_code ec;
  for (const fs::directory_entry& d : fs::directory_iterator(study, ec)) {
    if (!d.is_directory(ec) || d.path().filename() == out.filename()) continue;
    const fs::path log = d.path() / "session.jsonl";
    std::ifstream in(log);
    std::string first;
    if (!in || !std::getline(in, first) || field(first, "type") != "session_start") continue;
    const std::string who = field(first, "participant"), their_session = field(first, "session");
    if (who == participant && their_session == std::to_string(session))
      return make_error(log.string() + ": participant " + participant + " already has session " + their_session +
                        " in this study folder; give --session K for a retest, another --participant, or --force");
    if (who != participant && field(first, "seed") == std::to_string(seed))
      return make_error(log.string() + ": seed " + std::to_string(seed) + " is already " + who +
                        "'s in this study folder; every participant needs a seed of their own (or give --force)");
  }
  return ok_status();
}

void warn_device_seed(const DeviceSpec& device, std::uint64_t seed) {
  if (device.kind != DeviceKind::kTrajectory) return;
  std::ifstream in(device.file);
  std::string line;
  for (int n = 0; n < 3 && std::getline(in, line) && !line.empty() && line[0] == '#'; ++n) {
    const std::size_t at = line.find("--seed ");
    if (at == std::string::npos) continue;
    const std::string theirs = line.substr(at + 7, line.find_first_not_of("0123456789", at + 7) - (at + 7));
    if (theirs != std::to_string(seed))
      std::fprintf(stderr,
                   "pseudoshadow maze: warning: %s was written for --seed %s, this session has --seed %llu: it walks "
                   "another route (and may end as device_ended)\n",
                   device.text().c_str(), theirs.c_str(), static_cast<unsigned long long>(seed));
    return;
  }
}

}  // namespace ps
