// pseudoshadow: makes touch visible. Entry point: finds the command in kCommands and runs it.
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli/cli.h"
#include "app/commands.h"

namespace {

std::string top_help() {
  std::string h =
      "usage: pseudoshadow <command> [options]\n\n"
      "Draws the pseudo-shadow of a probe on virtual surfaces: a translucent shadow-like projection\n"
      "whose opacity shows proximity, whose Gabor texture shows the surface's tactile texture\n"
      "(amplitude following probe speed), and whose displacement pushes the probe out of the surface.\n"
      "The method is that of the thesis \"Augmenting Visual Feedback Using Sensory Substitution\".\n"
      "Its worlds follow Sandia's \"A Virtual Universe\" (scenes/universe), Hanson & Zhang's\n"
      "\"Multimodal Exploration of the Fourth Dimension\" (scenes/fourd) and Sepulveda-Cervantes et\n"
      "al.'s \"Haptic Cues for Effective Learning in 3D Maze Navigation\" (`maze`); docs/references.md.\n\n"
      "commands:\n";
  for (const ps::CommandInfo& c : ps::kCommands) {
    std::string name(c.name);
    name.resize(std::max<std::size_t>(name.size() + 2, 15), ' ');
    h += "  " + name + std::string(c.summary) + "\n";
  }
  h += "\nRun `pseudoshadow <command> --help` for the options of a command.\n"
       "Units: lengths in mm, speeds in mm/s, frequencies in Hz (docs/scene-format.md).\n";
  h += std::string(ps::cli::kExitStatusHelp) + "\n";
  return h;
}

int unknown_command(std::string_view cmd) {
  std::vector<std::string_view> names;
  std::string list;
  for (const ps::CommandInfo& c : ps::kCommands) {
    names.push_back(c.name);
    list += (list.empty() ? "" : ", ") + std::string(c.name);
  }
  const std::string hint = ps::cli::did_you_mean(cmd, names);
  std::fprintf(stderr, "pseudoshadow: unknown command '%.*s'%s (commands: %s; see pseudoshadow --help)\n",
               static_cast<int>(cmd.size()), cmd.data(), hint.empty() ? "" : ("; " + hint).c_str(), list.c_str());
  return ps::cli::kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  // A file grown past the file-size limit (`ulimit -f`, a quota set that way) gets a write error
  // the logs report and stop on ("File too large"), as a full disk does, instead of SIGXFSZ
  // killing the process mid-session with no word (docs/hardening.md, "Faults").
  std::signal(SIGXFSZ, SIG_IGN);
  const std::string_view first = argc < 2 ? "" : argv[1];
  if (argc < 2 || first == "-h" || first == "--help" || first == "help") {
    std::fputs(top_help().c_str(), argc < 2 ? stderr : stdout);
    return argc < 2 ? ps::cli::kExitUsage : ps::cli::kExitOk;
  }
  if (first == "--version") {
    std::puts("pseudoshadow " PS_VERSION);
    return ps::cli::kExitOk;
  }
  for (const ps::CommandInfo& c : ps::kCommands)
    if (c.name == first) return c.run(argc - 1, argv + 1);
  return unknown_command(first);
}
