// GLSL ES 3.00 (WebGL2) text from the desktop GLSL 4.50 sources, after preprocess_shader: the
// shaders stay one set, and this rewrite gives the browser build its variants (docs/gl-stack.md,
// "GLSL ES 3.00"). What 3.00 lacks and the rewrite takes out, each recorded for the host to set
// through the API instead:
//   - `layout(binding = N) uniform sampler2D s;` -> `uniform sampler2D s;`  (sampler_units: s, N)
//   - `layout(std140, binding = N) uniform B {` -> `layout(std140) uniform B {` (block_bindings)
//   - `layout(location = N) uniform T u;` -> `uniform T u;`          (uniform_locations: u, N)
//   - `layout(location = N)` on a fragment shader's inputs or a vertex shader's outputs (3.00
//     matches varyings by name; ours have the same names in both stages);
//   - `precise` (3.00 has no such qualifier; the Kahan row sums may then be simplified to plain
//     float sums, about 1e-8 of the mean normal instead of 1e-9, docs/gl-stack.md).
// `#version 450 core` becomes `#version 300 es` with highp defaults for float, int and
// sampler2D. Compute shaders and storage buffers have no 3.00 form: an error naming file:line
// (the fragment path of the reductions, ReductionMethod::kFragment, replaces them).
// No GL needed: ps_glslcheck --es validates the result with glslang's ES 3.00 rules at build time.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/result.h"
#include "gl/shader.h"

namespace ps::gl {

struct EsShader {
  std::string text;                // ready to compile as GLSL ES 3.00
  std::vector<std::string> files;  // as ShaderSource::files (the #line numbering is kept)
  std::vector<std::pair<std::string, int>> sampler_units;      // glUniform1i(location of name, unit)
  std::vector<std::pair<std::string, int>> block_bindings;     // glUniformBlockBinding(index of name, binding)
  std::vector<std::pair<std::string, int>> uniform_locations;  // the desktop location of a loose uniform
};

Result<EsShader> to_glsl_es(const ShaderSource& desktop, Stage stage);

}  // namespace ps::gl
