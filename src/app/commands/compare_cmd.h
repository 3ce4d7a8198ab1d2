// `pseudoshadow compare A B [--fail T] [--failpercent P] [--hardfail H] [--diff OUT]`: pixel comparison of two
// image files for golden tests. Exit codes: 0 pass, 1 fail, 2 error (unreadable file, size
// mismatch, bad arguments). Built as the library ps_compare_cmd (src/app/CMakeLists.txt).
#pragma once

namespace ps {

// argv[0] is "compare"; the rest are the options above. Prints one summary line on stdout and,
// on error, one line on stderr saying what to fix. Never throws.
int run_compare(int argc, char** argv);

}  // namespace ps
