// `pseudoshadow study plan | run | resume | summarize` (docs/study.md): an experiment file's
// participants planned, run headless with a simulated participant, resumed, summarized.
#pragma once

namespace ps {

// argv[0] is the subcommand ("plan", "run", "resume" or "summarize"); -1 when it is none of them.
int run_study_experiment(int argc, char** argv);

}  // namespace ps
