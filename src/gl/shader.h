// GLSL from disk: `#include "file"` resolved by the host (recursively, relative to the
// including file, then to the glsl/ root), `#line` directives inserted so compiler messages
// map back to file:line, and variants built by prepending `#define NAME VALUE` lines after
// `#version`. The same preprocessor is used by the build-time validator (glslang) and at run
// time, so a shader that passed the build compiles the same text at run time.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/result.h"
#include "gl/objects.h"

namespace ps::gl {

using Defines = std::vector<std::pair<std::string, std::string>>;

inline constexpr int kMaxIncludeDepth = 16;
// Larger shader files are refused (ours are a few KiB; a runaway file must not exhaust memory).
inline constexpr std::size_t kMaxShaderFileBytes = 1u << 20;
// Included file i is numbered `#line i*kIncludeLineStride+n i` (source string i AND an offset
// line): Mesa 22.3 reports source string 0 for most errors inside includes, so the offset is
// what map_shader_log trusts. Files must stay below this many lines.
inline constexpr int kIncludeLineStride = 100000;

struct ShaderSource {
  std::string text;                 // ready to compile
  std::vector<std::string> files;   // index i = GLSL source-string number used in #line; [0] = the root file
  // Every file read (root + includes), for watching; same as `files`.
};

// Errors: "<file>:<line>: cannot open include \"x\"", "<file>:<line>: include depth > 16
// (cycle?)", "<file>: cannot open shader: <reason>", "<file>: missing #version".
Result<ShaderSource> preprocess_shader(const std::string& path, const Defines& defines,
                                       const std::string& glsl_root);

// The file index (into ShaderSource::files) and that file's own line of a position numbered by
// the #line directives above: a line number from kIncludeLineStride up carries the index itself,
// which wins over `source` (Mesa may report source string 0).
struct SourceLine {
  unsigned long long file = 0, line = 0;
};
SourceLine decode_source_line(unsigned long long source, unsigned long long line);

// Rewrites a driver/glslang info log so "0:12(3): error: ..." / "ERROR: 0:12: ..." read
// "<file>:12: error: ..." using `files`.
std::string map_shader_log(const std::string& log, const std::vector<std::string>& files);

enum class Stage { kVertex, kFragment, kCompute };
Stage stage_from_path(const std::string& path);  // .vert / .frag / .comp

struct ProgramDesc {
  std::vector<std::string> stages;  // paths relative to glsl_root, e.g. {"surface.vert", "surface.frag"}
  Defines defines;
};

// Preprocesses, compiles and links; errors carry mapped file:line and the driver's log.
Result<Program> build_program(const ProgramDesc& desc, const std::string& glsl_root);

// Directory holding the shaders: $PSEUDOSHADOW_GLSL_DIR if set, else share/pseudoshadow/glsl
// found from the binary's own location (core/install_layout.h; in the build tree a link to glsl/).
std::string default_glsl_root();

}  // namespace ps::gl
