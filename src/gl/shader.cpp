// Run-time program building (compile + link with mapped logs) and the shader directory.
#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "gl/shader.h"

#include "core/install_layout.h"
#include "gl/es30.h"
#include "gl/shader_es.h"

namespace ps::gl {
namespace {

namespace fs = std::filesystem;

GLenum gl_stage(Stage stage) {
  switch (stage) {
    case Stage::kVertex: return GL_VERTEX_SHADER;
    case Stage::kFragment: return GL_FRAGMENT_SHADER;
    case Stage::kCompute: return GL_COMPUTE_SHADER;
  }
  assert(false && "gl_stage: Stage value out of range");
  return GL_VERTEX_SHADER;
}

std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

std::string program_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

// Puts the first line that reads like an error first, so the message starts "file:line: ...";
// the rest of the (mapped) log follows on the next lines.
std::string error_first(const std::string& log) {
  std::istringstream in(log);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) lines.push_back(line);
  }
  auto first = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.find("error") != std::string::npos;
  });
  std::string out = first != lines.end() ? *first : std::string();
  for (auto it = lines.begin(); it != lines.end(); ++it) {
    if (it == first) continue;
    out += (out.empty() ? "" : "\n") + *it;
  }
  return out;
}

// What an ES program's stages had as layout qualifiers, set through the API after the link.
struct EsBindings {
  std::vector<std::pair<std::string, int>> sampler_units, block_bindings, uniform_locations;
};

Result<Shader> compile_stage(const std::string& path, const Defines& defines,
                             const std::string& glsl_root, EsBindings& es_bindings) {
  auto source = preprocess_shader(path, defines, glsl_root);
  if (!source) return source.error();
  const Stage stage = stage_from_path(path);
  if (dialect() == Dialect::kEs30) {  // the GLSL ES 3.00 text of the same source (gl/shader_es.h)
    auto es = to_glsl_es(source.value(), stage);
    if (!es) return es.error();
    source->text = std::move(es->text);
    source->files = std::move(es->files);
    auto append = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
    append(es_bindings.sampler_units, es->sampler_units);
    append(es_bindings.block_bindings, es->block_bindings);
    append(es_bindings.uniform_locations, es->uniform_locations);
  }
  Shader shader(glCreateShader(gl_stage(stage)));
  const char* text = source->text.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::string log = error_first(map_shader_log(shader_log(shader.id()), source->files));
    return make_error(log.empty() ? path + ": compile failed (empty log)" : log);
  }
  return shader;
}

// ES 3.00 has no `binding =` or uniform `location =` qualifiers: the units and bindings the
// desktop text names are set here, and the loose uniforms' names recorded for glProgramUniform*.
void set_es_bindings(GLuint program, const EsBindings& es) {
  GLint previous = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
  glUseProgram(program);
  for (const auto& [name, unit] : es.sampler_units) glUniform1i(glGetUniformLocation(program, name.c_str()), unit);
  const auto p = static_cast<GLuint>(previous);
  glUseProgram(p != 0 && glIsProgram(p) ? p : 0);
  for (const auto& [name, binding] : es.block_bindings) {
    const GLuint index = glGetUniformBlockIndex(program, name.c_str());
    if (index != GL_INVALID_INDEX) glUniformBlockBinding(program, index, static_cast<GLuint>(binding));
  }
  es30_name_uniforms(program, es.uniform_locations);
}

}  // namespace

Result<Program> build_program(const ProgramDesc& desc, const std::string& glsl_root) {
  assert(gl_loaded() && "build_program: no current GL context (create_context first)");
  assert(!desc.stages.empty() && "build_program: ProgramDesc::stages is empty");
  std::error_code ec;
  if (!fs::is_directory(glsl_root, ec)) {
    // The likely cause is an incomplete install or a binary copied out of it (install_layout.h).
    return make_error(glsl_root + ": no shader directory; pseudoshadow looks for share/pseudoshadow/glsl "
                      "beside or above its binary: install it with cmake --install (or the Debian package), "
                      "or set PSEUDOSHADOW_GLSL_DIR to a glsl/ directory");
  }
  std::vector<Shader> shaders;
  std::string names;
  EsBindings es;
  for (const std::string& stage : desc.stages) {
    const fs::path path = fs::path(stage).is_absolute() ? fs::path(stage) : fs::path(glsl_root) / stage;
    auto shader = compile_stage(path.string(), desc.defines, glsl_root, es);
    if (!shader) return shader.error();
    shaders.push_back(std::move(shader.value()));
    names += (names.empty() ? "" : " + ") + stage;
  }
  Program program(glCreateProgram());
  for (const Shader& s : shaders) glAttachShader(program.id(), s.id());
  glLinkProgram(program.id());
  for (const Shader& s : shaders) glDetachShader(program.id(), s.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    // Link logs carry no file:line (Mesa: "error: ..."), so name the stages.
    return make_error(names + ": link failed: " + error_first(program_log(program.id())));
  }
  if (dialect() == Dialect::kEs30) set_es_bindings(program.id(), es);
  return program;
}

std::string default_glsl_root() {
  if (const char* env = std::getenv("PSEUDOSHADOW_GLSL_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  // Found from this binary's own location, never from the tree it was built in
  // (core/install_layout.h): the build tree links build/share/pseudoshadow/glsl to glsl/.
  return (install::data_dir() / "glsl").string();
}

}  // namespace ps::gl
