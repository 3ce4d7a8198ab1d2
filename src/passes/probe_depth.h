// Probe depth pass (thesis Table 4.2 step 2): orthographic projection of the probe onto a
// square window of the reference plane.
//   inputs : probe (sphere/capsule analytically, or a GpuMesh), reference frame, window
//   output : depth()  R32F size x size, the probe's lowest height h = dot(x, n) above each
//            texel centre, 1e30 where the probe does not cover the texel.
// Shaders: glsl/probe_depth_analytic.{vert,frag} (variant PS_PROBE_SPHERE for spheres),
// glsl/probe_depth_mesh.{vert,frag}.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "core/result.h"
#include "gl/objects.h"
#include "passes/gpu_mesh.h"
#include "passes/probe_input.h"
#include "reference/basis.h"
#include "reference/probe_geometry.h"

namespace ps {

// std140 mirror of glsl/lib/probe_depth_block.glsl.
struct ProbeDepthBlock {
  glm::mat4 model{1.0f};
  glm::vec4 ref_n, ref_t, ref_b;
  glm::vec4 window;        // centre u, v; half size; texels
  glm::vec4 cap_a;         // plane coords; w radius
  glm::vec4 cap_b;
  glm::vec4 height_range;  // mesh: lowest, highest height
};
static_assert(sizeof(ProbeDepthBlock) == 64 + 7 * 16, "ProbeDepthBlock must match std140 layout");

struct DepthWindow {
  glm::dvec2 center_uv{0.0};  // mm
  double half_size_mm = 1.0;
};

struct ProbeDepthPass {
  struct Params {
    int size = 256;  // texels per side (power of two)
  };
  struct Inputs {
    const PlaneFrame* frame = nullptr;
    DepthWindow window;
    ProbeInput probe;
    double height_lo = 0.0, height_hi = 1.0;  // mesh: plane-height range of the probe
  };

  Status init(const std::string& glsl_root, const Params& params);
  void run(const Inputs& in);
  const gl::Texture& depth() const { return depth_; }
  int size() const { return params_.size; }

 private:
  Params params_;
  gl::Program analytic_, sphere_, mesh_;  // sphere_: analytic, PS_PROBE_SPHERE=1
  gl::Texture depth_;
  gl::Renderbuffer depth_buffer_;
  gl::Framebuffer fbo_;
  gl::Buffer ubo_;
  gl::VertexArray empty_vao_;  // core profile draws need a bound VAO, even with no attributes
};

}  // namespace ps
