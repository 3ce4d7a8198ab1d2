#include "app/cli/cli.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "scene/scene_keys.h"

namespace ps::cli {

namespace {

constexpr std::size_t kHelpWidth = 100;  // columns of --help text

// CLI11's help with our usage line first ("usage: pseudoshadow NAME [options]"), then the
// description, the option groups (descriptions wrapped to kHelpWidth) and the footer.
class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(const std::string& usage) : usage_(usage) {
    label("Usage", "usage");
    label("OPTIONS", "options");
    label("Positionals", "arguments");
    column_width(26);
  }
  std::string make_group(std::string group, bool is_positional, std::vector<const CLI::Option*> opts) const override {
    std::string out = group + ":\n";
    for (const CLI::Option* opt : opts) out += make_option(opt, is_positional);
    return out;
  }
  std::string make_option_desc(const CLI::Option* opt) const override {
    const std::size_t width = kHelpWidth - get_column_width();
    std::string out, line;
    std::istringstream words(opt->get_description());
    for (std::string w; words >> w;) {
      if (!line.empty() && line.size() + 1 + w.size() > width) {
        out += line + "\n";
        line.clear();
      }
      line += (line.empty() ? "" : " ") + w;
    }
    return out + line;
  }
  std::string make_usage(const CLI::App* app, std::string name) const override {
    return usage_.empty() ? CLI::Formatter::make_usage(app, name) : "usage: " + usage_ + "\n";
  }
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override {
    const std::string positionals = make_positionals(app);
    return make_usage(app, name) + "\n" + make_description(app) + "\n" + positionals +
           (positionals.empty() ? "" : "\n") + make_groups(app, mode) + "\n" + make_footer(app);
  }
  std::string usage_;
};

// CLI11's own parse messages, reworded to ours (the option first, then what to do).
std::string parse_message(const CLI::ParseError& e) {
  const std::string what = e.what();
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) && what.find(" missing") != std::string::npos)
    return what.substr(0, what.find(':')) + " needs a value";
  return what;
}

bool parse_double(std::string_view s, double& out) {
  if (s.empty()) return false;
  const std::string tmp(s);
  char* end = nullptr;
  out = std::strtod(tmp.c_str(), &end);
  return end == tmp.c_str() + tmp.size();
}

std::string in_quotes(std::string_view s) { return "'" + std::string(s) + "'"; }

}  // namespace

Command::Command(std::string name, std::string description)
    : name_(std::move(name)), prefix_("pseudoshadow " + name_ + ": "), app_(std::move(description), "pseudoshadow " + name_) {
  app_.formatter(std::make_shared<HelpFormatter>(""));
  // As before CLI11: a repeated single-value option takes the last value.
  app_.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)->group("options");
  app_.set_help_flag("-h,--help", "this text")->group("options");
  // Unknown arguments are reported by us (with a close match), not by CLI11.
  app_.allow_extras();
  app_.footer(kExitStatusHelp);
}

void Command::usage(std::string line) { app_.formatter(std::make_shared<HelpFormatter>(line)); }

int Command::fail(const Error& e, int exit_code) const {
  std::fprintf(stderr, "%s%s\n", prefix_.c_str(), e.message.c_str());
  return exit_code;
}

std::string Command::unknown_argument(const std::string& arg) const {
  const std::string see = "see pseudoshadow " + name_ + " --help";
  if (arg.size() < 2 || arg[0] != '-') return "unexpected argument " + in_quotes(arg) + " (" + see + ")";
  const std::string name = arg.substr(0, arg.find('='));
  std::vector<std::string> names;
  for (const CLI::Option* o : app_.get_options())
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
  const std::vector<std::string_view> views(names.begin(), names.end());
  const std::string hint = did_you_mean(name, views);
  return "unknown option " + in_quotes(name) + (hint.empty() ? "" : "; " + hint) + " (" + see + ")";
}

int Command::run(int argc, char** argv, const std::function<int()>& action) {
  args_.assign(argv + std::min(argc, 1), argv + argc);
  try {
    app_.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app_.help().c_str(), stdout);
    return kExitOk;
  } catch (const CLI::Success&) {  // an option that was the whole command (--gpu list)
    return kExitOk;
  } catch (const UsageError& e) {
    return usage_error(make_error(e.what()));
  } catch (const RuntimeFailure& e) {
    return fail(make_error(e.what()));
  } catch (const CLI::ParseError& e) {
    return usage_error(make_error(parse_message(e)));
  }
  if (!app_.remaining().empty()) return usage_error(make_error(unknown_argument(app_.remaining().front())));
  return action();
}

CLI::Option* add_ordered(CLI::App& app, const std::string& name, const std::string& value_name,
                         const std::string& help, std::function<void(const std::string&)> apply) {
  return app.add_option_function<std::string>(name, std::move(apply), help)
      ->type_name(value_name)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->trigger_on_parse();  // the callback runs where the option stands on the command line
}

glm::dvec3 parse_vec3(std::string_view option, std::string_view text, std::string_view example) {
  const std::string opt(option), eg = opt + " " + std::string(example);
  glm::dvec3 v(0.0);
  size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t comma = text.find(',', start);
    const bool last = i == 2;
    if ((comma == std::string_view::npos) != last)
      throw UsageError(opt + ": expected three comma-separated numbers, e.g. " + eg);
    const std::string_view part = text.substr(start, last ? std::string_view::npos : comma - start);
    if (!parse_double(part, v[i])) throw UsageError(opt + ": " + in_quotes(part) + " is not a number (e.g. " + eg + ")");
    if (!std::isfinite(v[i]))
      throw UsageError(opt + ": component " + std::to_string(i + 1) + " is " + std::string(part) +
                       "; NaN and Inf are rejected (give finite numbers)");
    start = comma + 1;
  }
  return v;
}

long long parse_int(std::string_view option, std::string_view text, long long lo, long long hi) {
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size())
    throw UsageError(std::string(option) + ": " + in_quotes(text) + " is not a whole number");
  if (v < lo || v > hi)
    throw UsageError(std::string(option) + ": " + std::string(text) + " is outside [" + std::to_string(lo) +
                     ", " + std::to_string(hi) + "]");
  return v;
}

double parse_positive(std::string_view option, std::string_view text, double hi, std::string_view example) {
  double v = 0.0;
  if (!parse_double(text, v) || !(v > 0.0 && v <= hi))
    throw UsageError(std::string(option) + ": expected a number in (0, " + CLI::detail::to_string(hi) +
                     "], e.g. " + std::string(option) + " " + std::string(example));
  return v;
}

CLI::Option* add_positive(CLI::App& app, const std::string& name, const std::string& value_name, double& out,
                          double hi, const std::string& example, const std::string& help) {
  return app.add_option_function<std::string>(
                name, [name, &out, hi, example](const std::string& v) { out = parse_positive(name, v, hi, example); }, help)
      ->type_name(value_name);
}

namespace {

bool is_choice(const std::string& v, const std::vector<std::string>& choices) {
  for (const std::string& c : choices) {
    const std::size_t colon = c.find(':');
    if (colon == std::string::npos ? v == c : v.rfind(c.substr(0, colon + 1), 0) == 0) return true;
  }
  return false;
}

// "a", "a or b", "a, b or c".
std::string or_list(const std::vector<std::string>& words) {
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i) s += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return s;
}

}  // namespace

CLI::Option* add_choice(CLI::App& app, const std::string& name, const std::string& value_name, std::string& out,
                        const std::vector<std::string>& choices, const std::string& example, const std::string& help) {
  const auto check = [name, &out, choices, example](const std::string& v) {
    if (!is_choice(v, choices))
      throw UsageError(name + ": expected " + or_list(choices) + ", e.g. " + name + " " + example + " (got '" + v + "')");
    out = v;
  };
  return app.add_option_function<std::string>(name, check, help)->type_name(value_name);
}

glm::ivec2 parse_size(std::string_view text, int max_side, long long max_pixels) {
  const std::string limit = " refused: the limit is " + std::to_string(max_side) + " pixels per side (at least 1) and " +
                            std::to_string(max_pixels) + " pixels in all";
  const size_t x = text.find('x');
  const std::string_view w_text = text.substr(0, x);
  const std::string_view h_text = x == std::string_view::npos ? w_text : text.substr(x + 1);  // N: NxN
  long long w = 0, h = 0;
  const auto whole = [](std::string_view s, long long& out) {
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && ec == std::errc() && ptr == s.data() + s.size();
  };
  if (!whole(w_text, w) || !whole(h_text, h))
    throw UsageError("--size: expected WIDTHxHEIGHT (or N for NxN), e.g. --size 512x512; got " + in_quotes(text));
  if (w < 1 || h < 1 || w > max_side || h > max_side || w * h > max_pixels)
    throw UsageError("--size " + std::string(text) + limit);
  return {static_cast<int>(w), static_cast<int>(h)};
}

std::string override_value(const glm::dvec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "[%.17g,%.17g,%.17g]", v.x, v.y, v.z);
  return buf;
}

std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates) {
  const auto matches = scene_detail::close_matches(word, candidates);
  return matches.empty() ? std::string() : "did you mean " + in_quotes(matches.front()) + "?";
}

}  // namespace ps::cli
