// The GLSL ES 3.00 text of every shader that has one (gl/shader_es.h), compiled and linked by
// the driver itself in an OpenGL ES 3.0 context (Mesa's, on EGL's surfaceless platform): a
// second judge beside glslang's build-time check (ps_glsl_check_es), with the ES front end a
// browser's WebGL2 implementation reaches through ANGLE or the driver. Each recorded sampler
// unit and block binding is then set through the API, as a WebGL2 host does, without a GL error.
// The renderer's own GL 4.5 code (direct state access) does not run here; only the shaders.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl/shader.h"
#include "gl/shader_es.h"

namespace {

using ps::gl::Defines;

// The few ES 3.0 entry points the test needs, from the ES context (eglGetProcAddress).
struct EsApi {
  PFNGLCREATESHADERPROC create_shader;
  PFNGLSHADERSOURCEPROC shader_source;
  PFNGLCOMPILESHADERPROC compile_shader;
  PFNGLGETSHADERIVPROC get_shader_iv;
  PFNGLGETSHADERINFOLOGPROC shader_log;
  PFNGLCREATEPROGRAMPROC create_program;
  PFNGLATTACHSHADERPROC attach;
  PFNGLLINKPROGRAMPROC link;
  PFNGLGETPROGRAMIVPROC get_program_iv;
  PFNGLGETPROGRAMINFOLOGPROC program_log;
  PFNGLUSEPROGRAMPROC use;
  PFNGLGETUNIFORMLOCATIONPROC uniform_location;
  PFNGLUNIFORM1IPROC uniform1i;
  PFNGLGETUNIFORMBLOCKINDEXPROC block_index;
  PFNGLUNIFORMBLOCKBINDINGPROC block_binding;
  PFNGLGETERRORPROC get_error;
  PFNGLGETSTRINGPROC get_string;
  PFNGLDELETESHADERPROC delete_shader;
  PFNGLDELETEPROGRAMPROC delete_program;
};

template <typename F>
void load(F& f, const char* name) {
  f = reinterpret_cast<F>(eglGetProcAddress(name));
}

class EsContext {
 public:
  EsContext() {
    auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) return;
    display_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) return;
    if (!eglBindAPI(EGL_OPENGL_ES_API)) return;
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (context_ == EGL_NO_CONTEXT || !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) return;
    load(gl.create_shader, "glCreateShader");
    load(gl.shader_source, "glShaderSource");
    load(gl.compile_shader, "glCompileShader");
    load(gl.get_shader_iv, "glGetShaderiv");
    load(gl.shader_log, "glGetShaderInfoLog");
    load(gl.create_program, "glCreateProgram");
    load(gl.attach, "glAttachShader");
    load(gl.link, "glLinkProgram");
    load(gl.get_program_iv, "glGetProgramiv");
    load(gl.program_log, "glGetProgramInfoLog");
    load(gl.use, "glUseProgram");
    load(gl.uniform_location, "glGetUniformLocation");
    load(gl.uniform1i, "glUniform1i");
    load(gl.block_index, "glGetUniformBlockIndex");
    load(gl.block_binding, "glUniformBlockBinding");
    load(gl.get_error, "glGetError");
    load(gl.get_string, "glGetString");
    load(gl.delete_shader, "glDeleteShader");
    load(gl.delete_program, "glDeleteProgram");
    ok_ = gl.create_shader && gl.get_string && gl.block_binding;
  }
  ~EsContext() {
    if (display_ == EGL_NO_DISPLAY) return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
    eglReleaseThread();
  }
  bool ok() const { return ok_; }
  EsApi gl{};

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  bool ok_ = false;
};

// Compiles one stage's ES text; returns 0 and sets `log` (mapped to file:line) on failure.
GLuint compile(const EsApi& gl, GLenum type, const ps::gl::EsShader& es, std::string& log) {
  const GLuint s = gl.create_shader(type);
  const char* text = es.text.c_str();
  gl.shader_source(s, 1, &text, nullptr);
  gl.compile_shader(s);
  GLint ok = 0, len = 0;
  gl.get_shader_iv(s, GL_COMPILE_STATUS, &ok);
  gl.get_shader_iv(s, GL_INFO_LOG_LENGTH, &len);
  std::string raw(static_cast<size_t>(std::max(len, 1)), '\0');
  gl.shader_log(s, static_cast<GLsizei>(raw.size()), nullptr, raw.data());
  log = ps::gl::map_shader_log(raw.c_str(), es.files);
  if (ok) return s;
  gl.delete_shader(s);
  return 0;
}

struct Pair {
  std::string vert, frag;
  Defines defines;
};

std::vector<Pair> programs() {
  std::vector<Pair> p;
  for (const char* v : {"PS_SHADOW=1 PS_TEXTURED=1", "PS_SHADOW=1 PS_TEXTURED=0", "PS_SHADOW=0 PS_TEXTURED=0",
                        "PS_SHADOW=1 PS_TEXTURED=1 PS_GABOR_STRATIFIED=1", "PS_SHADOW=1 PS_TEXTURED=1 PS_GABOR_BAKED=1",
                        "PS_SHADOW=1 PS_TEXTURED=1 PS_GABOR_BAKED=2", "PS_SHADOW=1 PS_TEXTURED=1 PS_GABOR_FILTER=1",
                        "PS_SHADOW=1 PS_TEXTURED=1 PS_GABOR_FILTER=2", "PS_SHADOW=1 PS_TEXTURED=1 PS_INTENSITY_LUT=1"}) {
    Defines d;
    std::string s = v;
    for (size_t at = 0; at < s.size();) {
      const size_t end = std::min(s.find(' ', at), s.size()), eq = s.find('=', at);
      d.emplace_back(s.substr(at, eq - at), s.substr(eq + 1, end - eq - 1));
      at = end + 1;
    }
    p.push_back({"surface.vert", "surface.frag", d});
  }
  p.push_back({"probe_depth_analytic.vert", "probe_depth_analytic.frag", {}});
  p.push_back({"probe_depth_analytic.vert", "probe_depth_analytic.frag", {{"PS_PROBE_SPHERE", "1"}}});
  p.push_back({"probe_depth_mesh.vert", "probe_depth_mesh.frag", {}});
  p.push_back({"probe_view.vert", "probe_view.frag", {}});
  p.push_back({"gabor_bake.vert", "gabor_bake.frag", {}});
  for (const char* f : {"max_penetration_rows.frag", "displacement_rows.frag", "normal_rows.frag",
                        "displacement_weights.frag"})
    p.push_back({"displacement_weights.vert", f, {}});
  return p;
}

TEST(ShaderEsGLTest, EveryEsProgramCompilesAndLinksInAnEs30Context) {
  EsContext ctx;
  if (!ctx.ok()) GTEST_SKIP() << "no OpenGL ES 3.0 context on EGL's surfaceless platform here";
  const EsApi& gl = ctx.gl;
  const std::string version = reinterpret_cast<const char*>(gl.get_string(GL_VERSION));
  ASSERT_NE(version.find("OpenGL ES 3"), std::string::npos) << version;
  const std::string root = ps::gl::default_glsl_root();
  int linked = 0;
  for (const Pair& p : programs()) {
    const std::string what = p.vert + " + " + p.frag + (p.defines.empty() ? "" : " [" + p.defines[0].first + "...]");
    GLuint shaders[2] = {0, 0};
    std::vector<ps::gl::EsShader> es;
    for (const std::string& stage : {p.vert, p.frag}) {
      auto src = ps::gl::preprocess_shader(root + "/" + stage, p.defines, root);
      ASSERT_TRUE(src.ok()) << what << ": " << src.error().message;
      auto conv = ps::gl::to_glsl_es(src.value(), ps::gl::stage_from_path(stage));
      ASSERT_TRUE(conv.ok()) << what << ": " << conv.error().message;
      es.push_back(std::move(conv.value()));
    }
    std::string log;
    shaders[0] = compile(gl, GL_VERTEX_SHADER, es[0], log);
    ASSERT_NE(shaders[0], 0u) << what << " (vertex):\n" << log;
    shaders[1] = compile(gl, GL_FRAGMENT_SHADER, es[1], log);
    ASSERT_NE(shaders[1], 0u) << what << " (fragment):\n" << log;
    const GLuint prog = gl.create_program();
    gl.attach(prog, shaders[0]);
    gl.attach(prog, shaders[1]);
    gl.link(prog);
    GLint ok = 0;
    gl.get_program_iv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
      char buf[4096] = {};
      gl.program_log(prog, sizeof buf, nullptr, buf);
      ADD_FAILURE() << what << ": link failed:\n" << buf;
    } else {
      ++linked;
      // What the desktop source said with layout(binding), set the WebGL2 way.
      gl.use(prog);
      for (const ps::gl::EsShader& s : es) {
        for (const auto& [name, unit] : s.sampler_units)
          if (const GLint at = gl.uniform_location(prog, name.c_str()); at >= 0) gl.uniform1i(at, unit);
        for (const auto& [name, binding] : s.block_bindings) {
          const GLuint index = gl.block_index(prog, name.c_str());
          if (index != GL_INVALID_INDEX) gl.block_binding(prog, index, static_cast<GLuint>(binding));
        }
      }
      EXPECT_EQ(gl.get_error(), static_cast<GLenum>(GL_NO_ERROR)) << what;
    }
    gl.delete_program(prog);
    gl.delete_shader(shaders[0]);
    gl.delete_shader(shaders[1]);
  }
  EXPECT_EQ(linked, static_cast<int>(programs().size()));
}

}  // namespace
