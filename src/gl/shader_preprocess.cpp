// GLSL preprocessing on the host (no GL needed): #include resolution with #line mapping,
// #pragma once, variant #defines after #version; plus mapping of compiler logs back to files.
// Shared by the run-time program builder and the build-time validator (ps_glslcheck).
#include <algorithm>
#include <charconv>
#include <cassert>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <system_error>

#include "core/file_io.h"
#include "gl/shader.h"

namespace ps::gl {
namespace {

namespace fs = std::filesystem;

struct Preprocessor {
  std::string glsl_root;
  ShaderSource out;
  std::set<fs::path> once;  // canonical paths of files that said #pragma once and were included
};

Result<std::string> read_file(const fs::path& path) {
  std::optional<std::string> text = read_whole_file(path.string());
  if (!text) {
    std::error_code ec(errno, std::generic_category());
    return make_error(path.string() + ": cannot open shader: " + ec.message());
  }
  if (text->size() > kMaxShaderFileBytes)
    return make_error(path.string() + ": shader file larger than the limit of " +
                      std::to_string(kMaxShaderFileBytes) + " bytes");
  return std::move(*text);
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // CRLF files
    lines.push_back(std::move(line));
  }
  return lines;
}

bool is_directive(const std::string& line, const char* name) {
  static const std::regex kDirective(R"(^\s*#\s*(\w+)\b.*)");
  std::smatch m;
  return std::regex_match(line, m, kDirective) && m[1] == name;
}

bool is_pragma_once(const std::string& line) {
  static const std::regex kOnce(R"(^\s*#\s*pragma\s+once\s*(//.*)?$)");
  return std::regex_match(line, kOnce);
}

// Included name if `line` is `#include "name"`, else empty.
std::string include_name(const std::string& line) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*"([^"]+)\"\s*(//.*)?$)");
  std::smatch m;
  return std::regex_match(line, m, kInclude) ? m[1].str() : std::string();
}

fs::path canonical_or_self(const fs::path& path) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(path, ec);
  return ec ? path.lexically_normal() : c;
}

// Index of `path` in out.files, adding it on first sight.
int file_index(ShaderSource& out, const std::string& path) {
  for (size_t i = 0; i < out.files.size(); ++i) {
    if (out.files[i] == path) return static_cast<int>(i);
  }
  out.files.push_back(path);
  return static_cast<int>(out.files.size()) - 1;
}

// First of <including dir>/name, <glsl_root>/name that exists; empty if none.
fs::path resolve_include(const fs::path& including, const std::string& name,
                         const std::string& glsl_root) {
  for (const fs::path& base : {including.parent_path(), fs::path(glsl_root)}) {
    fs::path candidate = (base / name).lexically_normal();
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  return {};
}

// GLSL >= 3.30: the line after `#line n s` is line n of source string s. Mesa 22.3 loses s
// for most errors (its YYLLOC_DEFAULT resets the location's source to 0, so an error inside an
// expression in an include reads "0:5(10)"), so the file index is also carried in the line
// number: line = index * kIncludeLineStride + n. map_shader_log decodes both.
std::string line_directive(int line, int index) {
  return "#line " + std::to_string(index * kIncludeLineStride + line) + " " +
         std::to_string(index) + "\n";
}

Status append_file(Preprocessor& pp, const fs::path& path, int depth);

Status append_include(Preprocessor& pp, const fs::path& parent, int parent_index, int line_no,
                      const std::string& name, int depth) {
  const std::string where = parent.string() + ":" + std::to_string(line_no) + ": ";
  if (depth + 1 > kMaxIncludeDepth) {
    return make_error(where + "include depth > " + std::to_string(kMaxIncludeDepth) +
                      " (cycle?) including \"" + name + "\"");
  }
  fs::path path = resolve_include(parent, name, pp.glsl_root);
  if (path.empty()) return make_error(where + "cannot open include \"" + name + "\"");
  if (pp.once.count(canonical_or_self(path)) != 0) {  // #pragma once: already in
    pp.out.text += "\n";  // stands for the #include line
    return ok_status();
  }
  if (Status s = append_file(pp, path, depth + 1); !s) return s;
  pp.out.text += line_directive(line_no + 1, parent_index);
  return ok_status();
}

// Appends `lines` of file `index`, expanding includes; line numbers are kept by emitting one
// output line per input line (directives we consume become empty lines).
Status append_lines(Preprocessor& pp, const fs::path& path, int index,
                    const std::vector<std::string>& lines, int depth) {
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (is_pragma_once(line)) {
      pp.once.insert(canonical_or_self(path));
      pp.out.text += "\n";  // consumed here; drivers would warn on an unknown pragma
    } else if (std::string name = include_name(line); !name.empty()) {
      const int line_no = static_cast<int>(i) + 1;
      if (Status s = append_include(pp, path, index, line_no, name, depth); !s) return s;
    } else {
      pp.out.text += line + "\n";
    }
  }
  return ok_status();
}

// Appends an included file (depth >= 1): "#line 1 <index>", then its lines.
Status append_file(Preprocessor& pp, const fs::path& path, int depth) {
  auto text = read_file(path);
  if (!text) return text.error();
  const int index = file_index(pp.out, path.string());
  pp.out.text += line_directive(1, index);
  return append_lines(pp, path, index, split_lines(text.value()), depth);
}

}  // namespace

Result<ShaderSource> preprocess_shader(const std::string& path, const Defines& defines,
                                       const std::string& glsl_root) {
  auto text = read_file(path);
  if (!text) return text.error();
  std::vector<std::string> lines = split_lines(text.value());
  auto version = std::find_if(lines.begin(), lines.end(),
                              [](const std::string& l) { return is_directive(l, "version"); });
  if (version == lines.end()) return make_error(path + ": missing #version");

  Preprocessor pp;
  pp.glsl_root = glsl_root;
  file_index(pp.out, path);  // the root is source string 0
  // #version must come first; the variant's #defines follow it, then #line restores the
  // root's own numbering. Lines before #version can only be comments or blank.
  pp.out.text = *version + "\n";
  for (const auto& [name, value] : defines) {
    assert(!name.empty() && "preprocess_shader: empty define name");
    pp.out.text += "#define " + name + " " + value + "\n";
  }
  pp.out.text += line_directive(1, 0);
  version->clear();
  if (Status s = append_lines(pp, fs::path(path), 0, lines, 0); !s) return s.error();
  return std::move(pp.out);
}

SourceLine decode_source_line(unsigned long long source, unsigned long long line) {
  const auto stride = static_cast<unsigned long long>(kIncludeLineStride);
  return line >= stride ? SourceLine{line / stride, line % stride} : SourceLine{source, line};
}

std::string map_shader_log(const std::string& log, const std::vector<std::string>& files) {
  // Mesa: "0:12(3): error: x"; glslang: "ERROR: 0:12: x"; NVIDIA style: "0(12) : error x".
  static const std::regex kMesa(R"(^(\d+):(\d+)\(\d+\): (.*)$)");
  static const std::regex kGlslang(R"(^(ERROR|WARNING): (\d+):(\d+): (.*)$)");
  static const std::regex kNvidia(R"(^(\d+)\((\d+)\) : (.*)$)");
  // "<file>:<line>" from a source-string number and a (possibly strided) line number.
  // Numbers are parsed with from_chars: a log line with an absurd number (fuzzing found one
  // that made std::stoul throw out_of_range) is left as it is instead of aborting.
  auto where = [&](const std::string& source, const std::string& line_text) -> std::string {
    unsigned long long index = 0, line = 0;
    const auto src_end = source.data() + source.size(), line_end = line_text.data() + line_text.size();
    const auto a = std::from_chars(source.data(), src_end, index);
    const auto b = std::from_chars(line_text.data(), line_end, line);
    if (a.ec != std::errc() || a.ptr != src_end || b.ec != std::errc() || b.ptr != line_end)
      return source + ":" + line_text;
    const SourceLine at = decode_source_line(index, line);
    if (at.file >= files.size()) return source + ":" + line_text;  // not ours: leave it
    return files[at.file] + ":" + std::to_string(at.line);
  };
  std::string out;
  for (const std::string& line : split_lines(log)) {
    std::smatch m;
    if (std::regex_match(line, m, kMesa) || std::regex_match(line, m, kNvidia)) {
      out += where(m[1], m[2]) + ": " + m[3].str();
    } else if (std::regex_match(line, m, kGlslang)) {
      const std::string kind = m[1] == "ERROR" ? "error" : "warning";
      out += where(m[2], m[3]) + ": " + kind + ": " + m[4].str();
    } else {
      out += line;
    }
    out += "\n";
  }
  return out;
}

Stage stage_from_path(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".vert") return Stage::kVertex;
  if (ext == ".frag") return Stage::kFragment;
  assert(ext == ".comp" && "stage_from_path: shader file must end in .vert, .frag or .comp");
  return Stage::kCompute;
}

}  // namespace ps::gl
