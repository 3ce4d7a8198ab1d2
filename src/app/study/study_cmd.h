// `pseudoshadow study` (docs/study.md): its `simulate` subcommand so far.
#pragma once

namespace ps {

// `pseudoshadow study SUBCOMMAND ...` (argv[0] is "study").
int run_study(int argc, char** argv);

}  // namespace ps
