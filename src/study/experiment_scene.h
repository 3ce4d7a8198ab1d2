// Whether an experiment's stimuli are scenes the program can draw (docs/study.md, "Experiment
// files"): the scene loaded with the overrides of every condition (and material), the varied keys
// at the reference and at the largest comparison. A misspelt key, a value the scene refuses, a
// missing scene file: an error naming the experiment's file:line and the scene's own message.
#pragma once

#include "core/result.h"
#include "study/experiment.h"

namespace ps::study {

Status check_experiment_scene(const Experiment& e);

}  // namespace ps::study
