// `pseudoshadow maze summarize` (docs/maze.md, "maze summarize"): session logs, participants'
// folders or a study folder into tables and plots. Pilots and aborted sessions summarize without
// failing (a plot with nothing to draw is skipped with a note, a mean of nobody is "—"); a
// session given twice is refused.
#pragma once

namespace ps {

// `pseudoshadow maze summarize ...` (argv[0] is "summarize").
int run_maze_summarize(int argc, char** argv);

}  // namespace ps
