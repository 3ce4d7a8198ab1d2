// `pseudoshadow compare`: the pixel comparison behind the golden tests (tests/golden/run_golden.cmake).
#include "app/commands/compare_cmd.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <system_error>

#include "app/cli/cli.h"
#include "image/image.h"

namespace ps {
namespace {

constexpr int kExitPass = 0;
constexpr int kExitFail = 1;
constexpr int kExitError = 2;

struct CompareArgs {
  std::string path_a, path_b, diff_path;
  CompareOptions options;
};

// Whole-string, finite, non-negative, at most `max`: rejects "1.5x", "nan", "inf", "-0.1", "".
double parse_limit(std::string_view flag, std::string_view text, double max) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value) || value < 0.0 ||
      std::signbit(value) || value > max) {
    std::string hint = flag != "--failpercent" ? " (the [0,1] scale: for 2/255 write 0.0078)" : "";
    throw cli::UsageError(std::string(flag) + " needs a number from 0 to " + (max == 1.0 ? "1" : "100") +
                          ", got '" + std::string(text) + "'" + hint);
  }
  return value;
}

void declare(cli::Command& cmd, CompareArgs& args) {
  CLI::App& app = cmd.app();
  app.add_option("A", args.path_a, "the golden image")->type_name("");
  app.add_option("B", args.path_b, "the actual image")->type_name("");
  // A limit option: its value checked on [0, max], then stored by `store`.
  auto limit = [&app](const std::string& name, const char* value_name, double max, auto store,
                      const std::string& help) {
    app.add_option_function<std::string>(name, [=](const std::string& v) { store(parse_limit(name, v, max)); }, help)
        ->type_name(value_name);
  };
  limit("--fail", "T", 1.0, [&args](double v) { args.options.fail_threshold = static_cast<float>(v); },
        "a pixel fails if any channel differs by more than T, on the [0,1] scale (default 0.0039 = "
        "1/255, one 8-bit step); 0 <= T <= 1");
  limit("--failpercent", "P", 100.0, [&args](double v) { args.options.fail_percent = v; },
        "the comparison fails if more than P % of the pixels fail (default 0); 0 <= P <= 100");
  limit("--hardfail", "H", 1.0, [&args](double v) { args.options.hard_fail_threshold = static_cast<float>(v); },
        "the comparison fails if ANY pixel differs by more than H, whatever --failpercent allows "
        "(default: no cap); 0 <= H <= 1");
  app.add_option_function<std::string>(
         "--diff",
         [&args](const std::string& v) {
           if (v.empty()) throw cli::UsageError("--diff needs an output path");
           args.diff_path = v;
         },
         "always write |A-B| x10, clamped to [0,1], to OUT (PNG or EXR)")
      ->type_name("OUT");
  cmd.usage("pseudoshadow compare A B [--fail T] [--failpercent P] [--hardfail H] [--diff OUT]");
  app.footer(
      "Compares the pixels of two images of equal size and channel count (PNG, EXR, any format\n"
      "OpenImageIO reads; 8-bit files are read as [0,1]). File bytes are never compared.\n"
      "When both images are 8-bit files, pixels are compared in whole 8-bit levels and each\n"
      "threshold is rounded to the nearest level (0.004 -> 1 level, 0.0078 -> 2 levels).\n"
      "\n"
      "Prints one line: compare: PASS|FAIL  max_abs=... mean_abs=... failing=N (x.xx%)\n"
      "  then max_levels=L (both 8-bit), beyond_hardfail=N (if any) and [limits: ...]\n"
      "Exit codes: 0 pass, 1 fail, 2 error (unreadable file, size mismatch, bad arguments).");
}

void print_summary(const CompareResult& r, const CompareOptions& o) {
  std::printf("compare: %s  max_abs=%.6g mean_abs=%.6g failing=%ld (%.2f%%)", r.passed ? "PASS" : "FAIL",
              r.max_abs, r.mean_abs, r.failing_pixels, r.failing_percent);
  if (r.in_levels) std::printf(" max_levels=%d", r.max_levels);
  if (r.hard_failing_pixels > 0) std::printf(" beyond_hardfail=%ld", r.hard_failing_pixels);
  std::printf("  [limits: fail=%.6g failpercent=%.6g", static_cast<double>(o.fail_threshold), o.fail_percent);
  if (std::isfinite(o.hard_fail_threshold)) std::printf(" hardfail=%.6g", static_cast<double>(o.hard_fail_threshold));
  std::printf("]\n");
  std::fflush(stdout);
}

int compare(const cli::Command& cmd, const CompareArgs& args) {
  const auto error = [&cmd](const Error& e) { return cmd.fail(e, kExitError); };
  if (args.path_b.empty()) return error(make_error("need two images: pseudoshadow compare A B [options] (see pseudoshadow compare --help)"));
  Result<Image> a = read_image(args.path_a);
  if (!a) return error(a.error());
  Result<Image> b = read_image(args.path_b);
  if (!b) return error(b.error());
  Result<CompareResult> result = compare_images(*a, *b, args.options);
  if (!result) return error(make_error(args.path_a + " vs " + args.path_b + ": " + result.error().message));
  print_summary(*result, args.options);
  if (!args.diff_path.empty())
    if (Status written = write_image(args.diff_path, result->diff); !written) return error(written.error());
  return result->passed ? kExitPass : kExitFail;
}

}  // namespace

int run_compare(int argc, char** argv) {
  cli::Command cmd("compare",
                   "Compares the pixels of two images of equal size and channel count (PNG, EXR, any format\n"
                   "OpenImageIO reads; 8-bit files are read as [0,1]). File bytes are never compared.");
  CompareArgs args;
  declare(cmd, args);
  // OIIO and the standard library may throw (bad_alloc, ...); nothing escapes the CLI entry point.
  try {
    return cmd.run(argc, argv, [&] { return compare(cmd, args); });
  } catch (const std::exception& e) {
    return cmd.fail(make_error(std::string("unexpected failure: ") + e.what()), kExitError);
  }
}

}  // namespace ps
