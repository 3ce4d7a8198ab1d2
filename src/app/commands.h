// CLI subcommands. argv[0] is the subcommand's name; each returns the process exit status.
#pragma once

namespace ps {
int run_render(int argc, char** argv);
int run_compare(int argc, char** argv);  // src/app/compare_cmd.cpp
int run_window(int argc, char** argv);   // `run`, src/app/run_cmd.cpp
int run_replay(int argc, char** argv);
int run_bench_haptics(int argc, char** argv);
int run_bench(int argc, char** argv);    // src/app/bench_cmd.cpp
int run_tune(int argc, char** argv);     // src/app/tune_cmd.cpp
}  // namespace ps
