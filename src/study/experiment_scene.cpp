#include "study/experiment_scene.h"

#include "scene/scene_io.h"

namespace ps::study {

namespace {

Status try_load(const Experiment& e, int line, const std::string& what, const std::vector<std::string>& overrides) {
  const Result<Scene> scene = load_scene(e.scene, overrides);
  if (scene) return ok_status();
  return make_error(e.path + ":" + std::to_string(std::max(1, line)) + ": the scene with " + what + " does not load: " +
                    scene.error().message);
}

}  // namespace

Status check_experiment_scene(const Experiment& e) {
  for (const Variant& c : e.conditions) {
    const int line = c.line > 0 ? c.line : e.threshold.keys_line;
    const std::string in = "condition '" + c.name + "'";
    if (e.task == Task::kThreshold) {
      const ThresholdSpec& t = e.threshold;
      if (Status s = try_load(e, line, in + " at the reference", threshold_overrides(e, c, t.reference)); !s) return s;
      if (Status s = try_load(e, t.keys_line, in + " at reference + level_max",
                              threshold_overrides(e, c, t.reference + t.level_max));
          !s)
        return s;
      continue;
    }
    if (e.task == Task::kTargeting) {
      if (Status s = try_load(e, std::max(1, c.line), in, condition_overrides(e, c)); !s) return s;
      continue;
    }
    for (const Variant& m : e.materials)
      if (Status s = try_load(e, m.line, in + " and material '" + m.name + "'", material_overrides(e, c, m)); !s) return s;
  }
  return ok_status();
}

}  // namespace ps::study
