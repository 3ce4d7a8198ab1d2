// An experiment file (docs/study.md, "Experiment files"): a TOML file that declares one study
// of `pseudoshadow study`: the task (a 2AFC threshold, by the Psi method or calibrate's
// staircase, or the identification of K materials), the scene and the scene value it varies as
// `--set`-style keys, the levels, trials, blocks, practice, the conditions counterbalanced across
// participants, the response keys and the instructions. Unknown keys, wrong types and values out
// of range are "file:line: ..." errors that say what is allowed. No GL, no scene: whether the
// keys exist in the scene is checked by experiment_scene.h.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"
#include "study/psychometric.h"

namespace ps::study {

enum class Task { kThreshold, kIdentification, kTargeting };
enum class Method { kPsi, kStaircase };
const char* task_name(Task t);      // "threshold", "identification", "targeting"
const char* method_name(Method m);  // "psi", "staircase"

// `--set`-style overrides ("KEY=VALUE"), each with the line of the file that gave it.
struct Override {
  std::string text;
  int line = 0;
};

// A condition (or, in identification, a material): a name and the overrides that make it.
struct Variant {
  std::string name;
  std::vector<Override> set;
  int line = 0;  // its [[conditions]] / [[identification.materials]] header
};

struct ThresholdSpec {
  Method method = Method::kPsi;
  std::vector<std::string> keys;  // the scene keys set to the compared value
  int keys_line = 0;
  std::string value = "{}";       // how a value is written: "{}" replaced by the number
  double reference = 1.0;         // the reference level (stimulus units)
  double offset = 0.0;            // written value = offset + level (e.g. a probe's radius)
  double level_min = 0.01;        // the difference shown: reference vs reference + level
  double level_max = 1.0;
  Shape shape = Shape::kWeibull;  // the psychometric function fitted (and Psi's grid)
  double criterion = 0.75;        // the threshold reported is psi^-1(criterion)
  double lapse = 0.02;            // the lapse rate Psi assumes
};

// The targeting task's design (docs/study.md, "Targeting"): ISO 9241-9's multidirectional task,
// `targets` round targets of diameter W on a ring of diameter D lying on a plane of the scene,
// selected across the ring one after another; each (D, W) is a sequence of `targets` movements.
struct TargetingSpec {
  std::vector<double> distances_mm{40.0, 80.0, 160.0};  // ring diameters D
  std::vector<double> widths_mm{5.0, 10.0};             // target diameters W
  int targets = 9;        // per ring; odd, so that selecting across visits every target
  int sequences = 1;      // each (D, W) per condition and block
  std::array<double, 3> centre{0.0, 0.0, 0.0};  // the ring's centre on the surface, mm
  std::array<double, 3> normal{0.0, 0.0, 1.0};  // the plane's normal (the ring lies across it)
};

struct Experiment {
  std::string path;        // the file, as given
  std::string name;        // [experiment] name
  Task task = Task::kThreshold;
  std::string instructions;
  int trials = 50;         // per condition and block
  int blocks = 1;          // each block runs every condition once, in the participant's order
  int practice = 0;        // practice trials before the first block (logged, never fitted)
  std::uint64_t first_seed = 1;  // participant i (from 0) gets first_seed + i
  std::string scene;       // the scene file, resolved against the experiment's directory
  std::vector<Override> scene_set;  // [scene] set: applied to every stimulus
  std::vector<std::string> response_keys;  // threshold: 2 (interval 1, 2); identification: K
  ThresholdSpec threshold;
  std::vector<Variant> conditions;  // at least one ("main" when the file names none)
  std::vector<Variant> materials;   // identification: the K stimuli
  TargetingSpec targeting;          // targeting: trials = sequences x |D| x |W| x targets (derived)
};

// Parses experiment text; `source_name` names the file in messages and anchors [scene] path.
Result<Experiment> parse_experiment(const std::string& text, const std::string& source_name);
Result<Experiment> load_experiment(const std::string& path);

// The overrides of one stimulus: the scene's, the condition's, then the threshold's keys at
// `level` (threshold: reference or reference + a difference) or the material's.
std::vector<std::string> threshold_overrides(const Experiment& e, const Variant& condition, double level);
std::vector<std::string> material_overrides(const Experiment& e, const Variant& condition, const Variant& material);
// A targeting condition's overrides: the scene's, then the condition's.
std::vector<std::string> condition_overrides(const Experiment& e, const Variant& condition);

}  // namespace ps::study
