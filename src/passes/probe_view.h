// Probe view pass: draws the probe itself - the displayed proxy, after this frame's
// displacement - into the surface pass's colour target, depth-tested against the surfaces.
// Off by default (the pseudo-shadow is the display); `render --show-probe`, `run`'s P key.
//   inputs : probe (sphere/capsule tessellated here, or the probe's GpuMesh), camera, light,
//            the surface pass's colour target and depth buffer
//   output : the surface pass's color(), probe pixels only. Runs after the reductions, so the
//            normal/AOV targets, the reference plane and the displacement are unchanged.
// Shaders: glsl/probe_view.{vert,frag}; uniform contract glsl/lib/probe_view_block.glsl.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "core/result.h"
#include "gl/objects.h"
#include "passes/gpu_mesh.h"
#include "passes/probe_input.h"
#include "passes/surface.h"
#include "reference/probe_geometry.h"
#include "scene/mesh.h"
#include "scene/scene.h"

namespace ps {

// Capsule from a to b of radius r in world space (a == b: a sphere): two hemispheres of
// `segments` around the axis and segments/4 (>= 2) rings each, joined by a cylinder; the normals
// are the exact surface normals. Every vertex lies on the capsule surface (tested).
Mesh make_capsule_mesh(const CapsuleShape& capsule, int segments);

// std140 mirror of glsl/lib/probe_view_block.glsl.
struct ProbeViewBlock {
  glm::mat4 view_proj{1.0f};
  glm::mat4 model{1.0f};
  glm::vec4 light_dir;    // direction the light travels; w ambient
  glm::vec4 light_color;  // rgb; a output gamma
  glm::vec4 probe_color;  // rgb linear; a opacity
};
static_assert(sizeof(ProbeViewBlock) == 2 * 64 + 3 * 16, "ProbeViewBlock must match std140 layout");

struct ProbeViewPass {
  // Tessellation of sphere/capsule probes: 64 segments keep the silhouette within
  // r (1 - cos(pi / 64)) = 0.12 % of r of the true outline.
  static constexpr int kSegments = 64;
  static constexpr glm::dvec3 kColor{0.78, 0.80, 0.84};  // light neutral grey, linear

  Status init(const std::string& glsl_root, const SurfacePass& surface);
  struct Inputs {
    glm::dmat4 view_proj{1.0};
    const Light* light = nullptr;
    double gamma = 1.0 / 2.2;
    ProbeInput probe;  // after this frame's displacement
    glm::dvec3 color = kColor;  // linear rgb
    double alpha = 1.0;         // < 1: blended over the image (the faint device ghost)
  };
  void run(const Inputs& in);

 private:
  const SurfacePass* surface_ = nullptr;
  gl::Program program_;
  gl::Framebuffer fbo_;
  gl::Buffer ubo_;
  GpuMesh capsule_mesh_;
  CapsuleShape cached_{};  // capsule_mesh_ is rebuilt only when the shape changes
  bool have_capsule_ = false;
};

}  // namespace ps
