// Scripted tuning sessions (glslViewer-style): commands read line by line, e.g. from stdin,
// so a session replays from a text file:
//   set KEY VALUE     edit a scene value (a --set; rebuilds, keeps the last good on error)
//   render [N]        render N frames (default 1)
//   save FILE         write the last frame (.png/.exr; renders first if needed), or the edits
//                     as an override file if FILE ends in .toml
//   stats             print the last frame's numbers
//   reload            re-read the scene and shaders from disk
//   help              list the commands
//   quit              stop reading
//   # comment         ignored, as are blank lines
// An error prints "<source>:<line>: <message>" on `err` and the session continues.
#pragma once

#include <istream>
#include <ostream>
#include <string>

#include "tune/tune_session.h"

namespace ps {

struct ConsoleResult {
  int commands = 0;  // executed (comments and blank lines excluded)
  int errors = 0;
};

ConsoleResult run_console(TuneSession& session, std::istream& in, std::ostream& out, std::ostream& err,
                          const std::string& source_name = "<stdin>");

}  // namespace ps
