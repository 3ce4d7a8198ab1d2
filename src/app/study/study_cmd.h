// `pseudoshadow study` (docs/study.md): simulate, plan, run, resume, summarize.
#pragma once

namespace ps {

// `pseudoshadow study SUBCOMMAND ...` (argv[0] is "study").
int run_study(int argc, char** argv);

}  // namespace ps
