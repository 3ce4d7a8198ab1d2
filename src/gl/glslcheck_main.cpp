// ps_glslcheck: build-time GLSL validation with glslang, through the same preprocess_shader the
// renderer uses at run time, so a shader that passes here compiles the same text on Mesa.
//   ps_glslcheck --root DIR [--es] [--define NAME=VALUE]... [--variant "A=1 B=0"]... FILE...
// --es: each file rewritten to GLSL ES 3.00 (gl/shader_es.h, the browser build's text) and
// checked under ES 3.00's rules instead.
// Every file is checked once per variant (--define applies to all); the stages of one variant
// that share a path stem (surface.vert + surface.frag) are linked together. Errors print as
// "file:line: error: ..." and the exit status is 1 (2 for bad usage).
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "gl/shader.h"
#include "gl/shader_es.h"

namespace {

namespace fs = std::filesystem;
using ps::gl::Defines;

struct Args {
  std::string root;
  Defines defines;
  std::vector<Defines> variants;
  std::vector<std::string> files;
  bool es = false;
};

bool parse_define(const std::string& text, Defines& out) {
  const size_t eq = text.find('=');
  if (eq == 0 || text.empty()) return false;
  if (eq == std::string::npos) out.emplace_back(text, "1");
  else out.emplace_back(text.substr(0, eq), text.substr(eq + 1));
  return true;
}

bool parse_variant(const std::string& text, Defines& out) {
  std::istringstream in(text);
  for (std::string word; in >> word;) {
    if (!parse_define(word, out)) return false;
  }
  return true;
}

// Returns false (after printing why) on bad usage.
bool parse_args(int argc, char** argv, Args& args) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if ((arg == "--root" || arg == "--define" || arg == "--variant") && !has_value) {
      std::cerr << "ps_glslcheck: " << arg << " needs a value\n";
      return false;
    }
    if (arg == "--root") {
      args.root = argv[++i];
    } else if (arg == "--define") {
      if (!parse_define(argv[++i], args.defines)) {
        std::cerr << "ps_glslcheck: bad --define \"" << argv[i] << "\" (want NAME=VALUE)\n";
        return false;
      }
    } else if (arg == "--variant") {
      args.variants.emplace_back();
      if (!parse_variant(argv[++i], args.variants.back())) {
        std::cerr << "ps_glslcheck: bad --variant \"" << argv[i] << "\" (want \"A=1 B=0\")\n";
        return false;
      }
    } else if (arg == "--es") {
      args.es = true;
    } else if (arg.rfind("--", 0) == 0) {
      std::cerr << "ps_glslcheck: unknown option " << arg << "\n";
      return false;
    } else {
      args.files.push_back(arg);
    }
  }
  if (args.files.empty()) {
    std::cerr << "usage: ps_glslcheck --root DIR [--es] [--define N=V]... [--variant \"A=1 B=0\"]... FILE...\n";
    return false;
  }
  if (args.variants.empty()) args.variants.emplace_back();
  return true;
}

std::optional<EShLanguage> glslang_stage(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".vert") return EShLangVertex;
  if (ext == ".frag") return EShLangFragment;
  if (ext == ".comp") return EShLangCompute;
  return std::nullopt;
}

std::string variant_label(const Defines& defines) {
  std::string label;
  for (const auto& [name, value] : defines) label += (label.empty() ? "" : " ") + name + "=" + value;
  return label.empty() ? std::string() : " [" + label + "]";
}

// Parses one stage; prints the mapped log. glslang keeps its own copy of the text.
bool parse_stage(glslang::TShader& shader, const std::string& path, const Args& args,
                 const Defines& variant) {
  Defines defines = args.defines;
  defines.insert(defines.end(), variant.begin(), variant.end());
  auto source = ps::gl::preprocess_shader(path, defines, args.root);
  if (!source) {
    std::cout << source.error().message << variant_label(variant) << "\n";
    return false;
  }
  const EShLanguage stage = *glslang_stage(path);
  std::string es_text;
  if (args.es) {
    auto es = ps::gl::to_glsl_es(source.value(), ps::gl::stage_from_path(path));
    if (!es) {
      std::cout << es.error().message << variant_label(variant) << "\n";
      return false;
    }
    es_text = std::move(es->text);
  }
  const char* text = args.es ? es_text.c_str() : source->text.c_str();
  shader.setStrings(&text, 1);
  if (args.es) {
    // GLSL ES 3.00 as WebGL2 takes it: the #version 300 es line decides the rules.
    const bool ok = shader.parse(GetDefaultResources(), 300, EEsProfile, false, false, EShMsgDefault);
    const std::string log = ps::gl::map_shader_log(shader.getInfoLog(), source->files);
    if (!log.empty() && log != "\n") std::cout << log;
    if (!ok) std::cout << path << ": glslang rejected this shader as GLSL ES 3.00" << variant_label(variant) << "\n";
    return ok;
  }
  // OpenGL GLSL 450. The OpenGL client applies ARB_gl_spirv rules, under which loose uniforms
  // ("non-opaque uniform variables need a layout(location=L)") and unbound samplers are errors;
  // Mesa compiles this text as plain GLSL where they are legal, so let glslang assign them.
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientOpenGL, 450);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setAutoMapLocations(true);
  shader.setAutoMapBindings(true);
  const bool ok = shader.parse(GetDefaultResources(), 450, false, EShMsgDefault);
  const std::string log = ps::gl::map_shader_log(shader.getInfoLog(), source->files);
  if (!log.empty() && log != "\n") std::cout << log;
  if (!ok) std::cout << path << ": glslang rejected this shader" << variant_label(variant) << "\n";
  return ok;
}

// Checks one group of stages (same stem) for one variant: parse each, then link them.
bool check_group(const std::vector<std::string>& paths, const Args& args, const Defines& variant) {
  std::vector<std::unique_ptr<glslang::TShader>> shaders;  // must outlive the program
  bool ok = true;
  for (const std::string& path : paths) {
    shaders.push_back(std::make_unique<glslang::TShader>(*glslang_stage(path)));
    ok = parse_stage(*shaders.back(), path, args, variant) && ok;
  }
  if (!ok) return false;
  glslang::TProgram program;
  for (auto& shader : shaders) program.addShader(shader.get());
  if (!program.link(EShMsgDefault)) {
    std::cout << paths.front() << ": link failed" << variant_label(variant) << ":\n"
              << program.getInfoLog();
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  if (!parse_args(argc, argv, args)) return 2;
  std::map<std::string, std::vector<std::string>> groups;  // path stem -> stages
  for (const std::string& file : args.files) {
    if (!glslang_stage(file)) {
      std::cerr << "ps_glslcheck: " << file << ": unknown stage (want .vert, .frag or .comp)\n";
      return 2;
    }
    groups[fs::path(file).replace_extension().string()].push_back(file);
  }
  glslang::InitializeProcess();
  bool ok = true;
  for (const Defines& variant : args.variants) {
    for (const auto& [stem, paths] : groups) ok = check_group(paths, args, variant) && ok;
  }
  glslang::FinalizeProcess();
  return ok ? 0 : 1;
}
