// `pseudoshadow bench --first-image`: time to the first image as a user meets it (issue
// "fast where users feel it", docs/benchmarks.md "Time to the first image"). Every shipped
// scene's one-frame `render` as a whole process, under the default "auto" strategy and with
// every textured material forced to "naive" (per-pixel sum) and to "baked" (tile first); and a
// 301-frame `replay` of a stroke under the same three. CPU seconds (user + sys of the child, so
// a loaded machine skews it less than wall time), median of alternating repetitions, reported
// as ratios against the faster of naive and baked (target <= 1.15 for one frame; the replay at
// the baked speed).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/result.h"

namespace ps::bench {

struct ChildTimes {
  double cpu_s = 0.0;   // user + sys
  double wall_s = 0.0;
};

// Runs this program (/proc/self/exe) with `args` (without argv[0]), its output to /dev/null;
// an error if it does not exit 0 (naming the command line).
Result<ChildTimes> run_self(const std::vector<std::string>& args);

struct FirstImageRow {
  std::string name;  // scene file stem, or "replay 301 frames (default)"
  double auto_s = 0.0, naive_s = 0.0, baked_s = 0.0;  // median CPU seconds
  double ratio() const;  // auto / min(naive, baked)
};

struct FirstImageOptions {
  std::string scenes_dir;  // every *.toml directly inside (not the material library below it)
  std::string work_dir;    // renders and the replay's frames go here (removed after)
  std::vector<std::string> gl_args = {"--backend", "auto"};  // --backend and --gpu for each child
  int reps = 3;            // one-frame renders: median of this many alternating runs
  bool replay = true;      // also the 301-frame replay (once per strategy)
  std::function<void(const std::string&)> progress;
};

Result<std::vector<FirstImageRow>> run_first_image(const FirstImageOptions& o);
// Markdown table: scene, auto, naive, baked, auto / min, within the target.
std::string first_image_markdown(const std::vector<FirstImageRow>& rows, int reps);

}  // namespace ps::bench
