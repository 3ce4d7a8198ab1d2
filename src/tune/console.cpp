#include "tune/console.h"

#include <cstdio>
#include <sstream>

#include "image/image.h"
#include "tune/overrides_file.h"

namespace ps {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// The commands, once: `help` prints this and an unknown command lists their names.
struct ConsoleCommand {
  const char* name;
  const char* usage;
};
constexpr ConsoleCommand kCommands[] = {
    {"set", "set KEY VALUE      edit a scene value, as --set KEY=VALUE (rebuilds; keeps the last good on error)"},
    {"render", "render [N]         render N frames (default 1)"},
    {"save", "save FILE          write the last frame (.png/.exr), or the edits as an override file (.toml)"},
    {"stats", "stats              print the last frame's numbers"},
    {"reload", "reload             re-read the scene and shaders from disk"},
    {"help", "help               this list"},
    {"quit", "quit               stop reading (also: exit)"},
};

std::string command_names() {
  std::string names;
  for (const ConsoleCommand& c : kCommands) names += (names.empty() ? "" : ", ") + std::string(c.name);
  return names;
}

class Console {
 public:
  Console(TuneSession& s, std::ostream& out) : session_(s), out_(out) {}

  // Returns false on `quit`; errors in `status`.
  bool execute(const std::string& verb, const std::string& rest, Status& status) {
    if (verb == "quit" || verb == "exit") return false;
    if (verb == "set") status = cmd_set(rest);
    else if (verb == "render") status = cmd_render(rest);
    else if (verb == "save") status = cmd_save(rest);
    else if (verb == "stats") status = cmd_stats();
    else if (verb == "reload") status = cmd_reload();
    else if (verb == "help") cmd_help();
    else status = make_error("unknown command '" + verb + "' (commands: " + command_names() + ")");
    return true;
  }

 private:
  void cmd_help() {
    for (const ConsoleCommand& c : kCommands) out_ << c.usage << "\n";
    out_ << "# starts a comment; blank lines are ignored\n";
  }
  Status cmd_set(const std::string& rest) {
    const auto sp = rest.find_first_of(" \t=");
    if (rest.empty() || sp == std::string::npos || trim(rest.substr(sp + 1)).empty())
      return make_error("set: expected KEY VALUE, e.g. set materials.wood.lambda_min 0.4");
    if (Status s = session_.set(rest.substr(0, sp), trim(rest.substr(sp + 1))); !s) return s;
    rendered_ = false;
    return ok_status();
  }
  Status cmd_render(const std::string& rest) {
    int frames = 1;
    if (!rest.empty()) {
      char* end = nullptr;
      const long n = std::strtol(rest.c_str(), &end, 10);
      if (end != rest.c_str() + rest.size() || n < 1 || n > 100000)
        return make_error("render: N must be a whole number in [1, 100000] (got '" + rest + "')");
      frames = static_cast<int>(n);
    }
    for (int i = 0; i < frames; ++i)
      if (Status s = session_.renderer().render_frame(); !s) return s;
    rendered_ = true;
    return ok_status();
  }
  Status cmd_save(const std::string& file) {
    if (file.empty()) return make_error("save: expected a file name (image, or .toml for the overrides)");
    if (file.size() > 5 && file.compare(file.size() - 5, 5, ".toml") == 0) {
      if (Status s = session_.save_overrides(file); !s) return s;
    } else {
      if (!rendered_)
        if (Status s = cmd_render(""); !s) return s;
      if (Status s = write_image(file, session_.renderer().read_color()); !s) return s;
    }
    out_ << "saved " << file << "\n";
    return ok_status();
  }
  Status cmd_stats() {
    if (!rendered_) return make_error("stats: nothing rendered yet (use render first)");
    const FrameStats& st = session_.renderer().stats();
    double ms = 0.0;
    for (const auto& [name, t] : st.timings_ms) ms += t;
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "shadow_pixels %u penetrating_pixels %u max_penetration_mm %.6g speed_gain %.6g frame_ms %.2f\n",
                  st.shadow_pixels, st.penetrating_pixels, st.max_penetration_mm, st.speed_gain, ms);
    out_ << buf;
    return ok_status();
  }
  Status cmd_reload() {
    if (Status s = session_.reload(); !s) return s;
    rendered_ = false;
    out_ << "reloaded\n";
    return ok_status();
  }

  TuneSession& session_;
  std::ostream& out_;
  bool rendered_ = false;
};

}  // namespace

ConsoleResult run_console(TuneSession& session, std::istream& in, std::ostream& out, std::ostream& err,
                          const std::string& source_name) {
  Console console(session, out);
  ConsoleResult result;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto sp = t.find_first_of(" \t");
    const std::string verb = t.substr(0, sp);
    const std::string rest = sp == std::string::npos ? std::string() : trim(t.substr(sp + 1));
    ++result.commands;
    Status status = ok_status();
    const bool go_on = console.execute(verb, rest, status);
    if (!status) {
      ++result.errors;
      err << source_name << ":" << n << ": " << status.error().message << "\n";
    }
    out.flush();
    if (!go_on) break;
  }
  return result;
}

}  // namespace ps
