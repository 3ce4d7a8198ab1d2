// `pseudoshadow compare`: the pixel comparison behind the golden tests (tests/golden/run_golden.cmake).
#include "app/compare_cmd.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <system_error>

#include "image/image.h"

namespace ps {
namespace {

constexpr int kExitPass = 0;
constexpr int kExitFail = 1;
constexpr int kExitError = 2;

constexpr const char* kUsage =
    "usage: pseudoshadow compare A B [--fail T] [--failpercent P] [--hardfail H] [--diff OUT]\n"
    "\n"
    "Compares the pixels of two images of equal size and channel count (PNG, EXR, any format\n"
    "OpenImageIO reads; 8-bit files are read as [0,1]). File bytes are never compared.\n"
    "\n"
    "  A, B              the two images (usually: golden, then actual)\n"
    "  --fail T          a pixel fails if any channel differs by more than T, on the [0,1]\n"
    "                    scale (default 0.0039 = 1/255, one 8-bit step); 0 <= T <= 1\n"
    "  --failpercent P   the comparison fails if more than P % of the pixels fail\n"
    "                    (default 0); 0 <= P <= 100\n"
    "  --hardfail H      the comparison fails if ANY pixel differs by more than H, whatever\n"
    "                    --failpercent allows (default: no cap); 0 <= H <= 1\n"

    "  --diff OUT        always write |A-B| x10, clamped to [0,1], to OUT (PNG or EXR)\n"
    "  -h, --help        print this help and exit 0\n"    "\n"
    "When both images are 8-bit files, pixels are compared in whole 8-bit levels and each\n"
    "threshold is rounded to the nearest level (0.004 -> 1 level, 0.0078 -> 2 levels).\n"
    "\n"
    "Prints one line: compare: PASS|FAIL  max_abs=... mean_abs=... failing=N (x.xx%)\n"
    "  then max_levels=L (both 8-bit), beyond_hardfail=N (if any) and [limits: ...]\n"
    "Exit codes: 0 pass, 1 fail, 2 error (unreadable file, size mismatch, bad arguments).\n";

struct CompareArgs {
  std::string path_a, path_b, diff_path;
  CompareOptions options;
  bool help = false;
};

// Whole-string, finite, non-negative, at most `max`: rejects "1.5x", "nan", "inf", "-0.1", "".
Result<double> parse_limit(std::string_view flag, std::string_view text, double max) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value) || value < 0.0 ||
      std::signbit(value) || value > max) {
    std::string hint = flag != "--failpercent" ? " (the [0,1] scale: for 2/255 write 0.0078)" : "";
    return make_error(std::string(flag) + " needs a number from 0 to " + (max == 1.0 ? "1" : "100") +
                      ", got '" + std::string(text) + "'" + hint);
  }
  return value;
}

// Applies one option with its value; returns an error naming the option on bad input.
Status apply_option(std::string_view flag, std::string_view value, CompareArgs& args) {
  if (flag == "--diff") {
    if (value.empty()) return make_error("--diff needs an output path");
    args.diff_path = std::string(value);
    return ok_status();
  }
  Result<double> limit = parse_limit(flag, value, flag == "--failpercent" ? 100.0 : 1.0);
  if (!limit) return limit.error();
  if (flag == "--fail") args.options.fail_threshold = static_cast<float>(*limit);
  else if (flag == "--hardfail") args.options.hard_fail_threshold = static_cast<float>(*limit);
  else args.options.fail_percent = *limit;
  return ok_status();
}

bool is_option(std::string_view flag) {
  return flag == "--fail" || flag == "--failpercent" || flag == "--hardfail" || flag == "--diff";
}

Result<CompareArgs> parse_args(int argc, char** argv) {
  CompareArgs args;
  int positional = 0;
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      args.help = true;
      return args;
    }
    const size_t eq = arg.find('=');
    std::string_view flag = arg.substr(0, eq);  // accepts "--fail 0.1" and "--fail=0.1"
    if (arg.starts_with("--") && is_option(flag)) {
      if (eq == std::string_view::npos && i + 1 >= argc) return make_error(std::string(flag) + " needs a value");
      std::string_view value = eq == std::string_view::npos ? std::string_view(argv[++i]) : arg.substr(eq + 1);
      if (Status applied = apply_option(flag, value, args); !applied) return applied.error();
    } else if (arg.starts_with("-") && arg.size() > 1) {
      return make_error("unknown option '" + std::string(arg) + "' (see compare --help)");
    } else if (positional < 2) {
      (positional++ == 0 ? args.path_a : args.path_b) = std::string(arg);
    } else {
      return make_error("unexpected extra argument '" + std::string(arg) + "'; give exactly two images");
    }
  }
  if (positional != 2) return make_error("need two images: compare A B [options] (see compare --help)");
  return args;
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

int report_error(const std::string& message) {
  std::fprintf(stderr, "compare: error: %s\n", message.c_str());
  return kExitError;
}

int run_compare_checked(int argc, char** argv) {
  Result<CompareArgs> args = parse_args(argc, argv);
  if (!args) return report_error(args.error().message);
  if (args->help) {
    std::fputs(kUsage, stdout);
    return kExitPass;
  }
  Result<Image> a = read_image(args->path_a);
  if (!a) return report_error(a.error().message);
  Result<Image> b = read_image(args->path_b);
  if (!b) return report_error(b.error().message);
  Result<CompareResult> result = compare_images(*a, *b, args->options);
  if (!result) return report_error(args->path_a + " vs " + args->path_b + ": " + result.error().message);
  print_summary(*result, args->options);
  if (!args->diff_path.empty()) {
    if (Status written = write_image(args->diff_path, result->diff); !written) {
      return report_error(written.error().message);
    }
  }
  return result->passed ? kExitPass : kExitFail;
}

}  // namespace

int run_compare(int argc, char** argv) {
  // OIIO and the standard library may throw (bad_alloc, ...); nothing escapes the CLI entry point.
  try {
    return run_compare_checked(argc, argv);
  } catch (const std::exception& e) {
    return report_error(std::string("unexpected failure: ") + e.what());
  }
}

}  // namespace ps
