// GLSL 4.50 -> GLSL ES 3.00, line by line on preprocessed text (gl/shader_es.h).
#include "gl/shader_es.h"

#include <regex>
#include <sstream>

namespace ps::gl {
namespace {

// Where a line of preprocessed text came from: the #line directives preprocess_shader wrote
// say it (decode_source_line).
struct Origin {
  SourceLine at;
  void step(const std::string& text) {
    static const std::regex kLine(R"(^\s*#\s*line\s+(\d+)\s+(\d+)\s*$)");
    std::smatch m;
    if (std::regex_match(text, m, kLine)) {
      at = decode_source_line(std::stoull(m[2].str()), std::stoull(m[1].str()));
      --at.line;  // the next line is line n
    } else {
      ++at.line;
    }
  }
  std::string where(const std::vector<std::string>& files) const {
    return (at.file < files.size() ? files[at.file] : std::string("<shader>")) + ":" + std::to_string(at.line);
  }
};

std::string root_name(const ShaderSource& s) { return s.files.empty() ? std::string("<shader>") : s.files[0]; }

}  // namespace

Result<EsShader> to_glsl_es(const ShaderSource& desktop, Stage stage) {
  static const std::regex kVersion(R"(^\s*#\s*version\s+450(\s+core)?\s*$)");
  static const std::regex kSampler(R"(^(\s*)layout\s*\(\s*binding\s*=\s*(\d+)\s*\)\s*uniform\s+(\w+)\s+(\w+)\s*;(.*)$)");
  static const std::regex kBlock(R"(^(\s*)layout\s*\(\s*std140\s*,\s*binding\s*=\s*(\d+)\s*\)\s*uniform\s+(\w+)(.*)$)");
  static const std::regex kLooseUniform(R"(^(\s*)layout\s*\(\s*location\s*=\s*(\d+)\s*\)\s*uniform\s+(\w+)\s+(\w+)\s*;(.*)$)");
  static const std::regex kVarying(R"(^(\s*)layout\s*\(\s*location\s*=\s*\d+\s*\)\s*(in|out)\b(.*)$)");
  static const std::regex kBuffer(R"(^\s*layout\s*\([^)]*\)\s*(readonly\s+|writeonly\s+)*buffer\b.*$)");
  static const std::regex kPrecise(R"(\bprecise\s+)");
  EsShader es;
  es.files = desktop.files;
  if (stage == Stage::kCompute)
    return make_error(root_name(desktop) + ": a compute shader has no GLSL ES 3.00 form (WebGL2 has no compute; the reductions have a "
                      "fragment path, ReductionMethod::kFragment)");
  std::istringstream in(desktop.text);
  Origin origin;
  bool versioned = false;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!versioned) {
      if (!std::regex_match(line, kVersion))
        return make_error(root_name(desktop) + ": expected #version 450 first, found \"" + line + "\"");
      versioned = true;
      es.text += "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n";
      continue;
    }
    origin.step(line);
    if (std::regex_match(line, kBuffer))
      return make_error(origin.where(es.files) +
                        ": a storage buffer has no GLSL ES 3.00 form (WebGL2): pass the values as uniforms");
    if (std::regex_match(line, m, kSampler)) {
      es.sampler_units.emplace_back(m[4].str(), std::stoi(m[2].str()));
      line = m[1].str() + "uniform " + m[3].str() + " " + m[4].str() + ";" + m[5].str();
    } else if (std::regex_match(line, m, kBlock)) {
      es.block_bindings.emplace_back(m[3].str(), std::stoi(m[2].str()));
      line = m[1].str() + "layout(std140) uniform " + m[3].str() + m[4].str();
    } else if (std::regex_match(line, m, kLooseUniform)) {
      es.uniform_locations.emplace_back(m[4].str(), std::stoi(m[2].str()));
      line = m[1].str() + "uniform " + m[3].str() + " " + m[4].str() + ";" + m[5].str();
    } else if (std::regex_match(line, m, kVarying) &&
               ((stage == Stage::kFragment && m[2] == "in") || (stage == Stage::kVertex && m[2] == "out"))) {
      line = m[1].str() + m[2].str() + m[3].str();
    }
    line = std::regex_replace(line, kPrecise, "");
    es.text += line + "\n";
  }
  if (!versioned) return make_error(root_name(desktop) + ": empty shader");
  return es;
}

}  // namespace ps::gl
