// Every TOML file the program reads (scenes, included material files, maze descriptions, --set
// values) is parsed here, so the one workaround below applies to all of them.
//
// toml++ 3.3.0 (Debian 12's libtomlplusplus) reaches `__builtin_unreachable()` - undefined
// behaviour - when it asks whether some non-ASCII code points are whitespace (U+00A7 after a
// key, a value, or a multi-line string's line-ending backslash: upstream issues #190 and #295,
// fixed after 3.3.0). Found by fuzz_maze_desc. TOML allows non-ASCII characters only inside
// strings and comments, so such text is refused here, with its line, before toml++ sees it;
// every valid document passes unchanged.
#pragma once

#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "core/result.h"

namespace ps {

// "<source_name>:<line>: syntax error: ..." for a non-ASCII character outside strings and
// comments, or right after a multi-line string's line-ending backslash; ok otherwise.
Status check_toml_text(std::string_view text, const std::string& source_name);

// check_toml_text, then toml::parse; errors are "<source_name>:<line>: syntax error: ...".
Result<toml::table> parse_toml(std::string_view text, const std::string& source_name);

}  // namespace ps
