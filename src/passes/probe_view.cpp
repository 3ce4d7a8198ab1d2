#include "passes/probe_view.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/shader.h"

namespace ps {

// Whole (43 lines): the ring loop and the index loop share the ring layout (columns, ring_count)
// they are written against; apart, each would restate it.
Mesh make_capsule_mesh(const CapsuleShape& c, int segments) {
  segments = std::max(segments, 8);
  const int rings = std::max(segments / 4, 2);  // per hemisphere, pole to equator
  glm::dvec3 axis = c.b - c.a;
  const double length = glm::length(axis);
  axis = length > 0.0 ? axis / length : glm::dvec3(0.0, 0.0, 1.0);
  // Any unit vector orthogonal to the axis, and the third one.
  const glm::dvec3 helper = std::abs(axis.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(helper, axis));
  const glm::dvec3 e2 = glm::cross(axis, e1);
  Mesh m;
  // Latitude rings from the pole beyond b (polar angle 0) to the pole beyond a (pi); the equator
  // appears twice, once around b and once around a, so the cylinder between has radial normals.
  const int columns = segments + 1;  // seam duplicated: simple indexing
  int ring_count = 0;
  for (int hemi = 0; hemi < 2; ++hemi) {
    for (int k = 0; k <= rings; ++k) {
      const double polar = std::numbers::pi * 0.5 * (hemi + static_cast<double>(k) / rings);
      const glm::dvec3 centre = hemi == 0 ? c.b : c.a;
      for (int s = 0; s < columns; ++s) {
        const double az = 2.0 * std::numbers::pi * (s % segments) / segments;
        const glm::dvec3 n = std::cos(polar) * axis +
                             std::sin(polar) * (std::cos(az) * e1 + std::sin(az) * e2);
        m.positions.emplace_back(centre + c.radius * n);
        m.normals.emplace_back(n);
      }
      ++ring_count;
    }
  }
  for (int r = 0; r + 1 < ring_count; ++r)
    for (int s = 0; s < segments; ++s) {
      const auto i0 = static_cast<std::uint32_t>(r * columns + s), i1 = i0 + 1;
      const auto j0 = static_cast<std::uint32_t>((r + 1) * columns + s), j1 = j0 + 1;
      m.indices.insert(m.indices.end(), {i0, j0, i1, i1, j0, j1});
    }
  m.bounds_min = c.a;
  m.bounds_max = c.a;
  for (const glm::vec3& p : m.positions) {
    m.bounds_min = glm::min(m.bounds_min, glm::dvec3(p));
    m.bounds_max = glm::max(m.bounds_max, glm::dvec3(p));
  }
  return m;
}

Status ProbeViewPass::init(const std::string& glsl_root, const SurfacePass& surface) {
  surface_ = &surface;
  auto built = gl::build_program({{"probe_view.vert", "probe_view.frag"}, {}}, glsl_root);
  if (!built) return built.error();
  program_ = std::move(built.value());
  fbo_ = gl::make_framebuffer();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, surface.color().id(), 0);
  glNamedFramebufferRenderbuffer(fbo_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                 surface.depth_buffer().id());
  glNamedFramebufferDrawBuffer(fbo_.id(), GL_COLOR_ATTACHMENT0);
  if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return make_error("probe view pass: framebuffer incomplete (surface colour + depth)");
  ubo_ = gl::make_buffer(sizeof(ProbeViewBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  return ok_status();
}

// Whole (48 lines): the block, then every GL state the pass depends on, set at entry in the order
// the draw uses it (house rule 2); split, the state would be set in two places.
void ProbeViewPass::run(const Inputs& in) {
  assert(in.light && "ProbeViewPass::run: a light is required");
  glm::dmat4 model = in.probe.model;
  const GpuMesh* mesh = in.probe.mesh;
  if (!mesh) {
    // Tessellate in the capsule's own frame (tip cap at the origin) so moving the probe only
    // changes the model matrix.
    const CapsuleShape& c = in.probe.capsule;
    const CapsuleShape local{glm::dvec3(0.0), c.b - c.a, c.radius};
    if (!have_capsule_ || local.b != cached_.b || local.radius != cached_.radius) {
      capsule_mesh_ = GpuMesh::upload(make_capsule_mesh(local, kSegments));
      cached_ = local;
      have_capsule_ = true;
    }
    mesh = &capsule_mesh_;
    model = glm::translate(glm::dmat4(1.0), c.a);
  }
  ProbeViewBlock block;
  block.view_proj = glm::mat4(in.view_proj);
  block.model = glm::mat4(model);
  block.light_dir = glm::vec4(glm::dvec4(in.light->direction, in.light->ambient));
  block.light_color = glm::vec4(glm::dvec4(in.light->color, in.gamma));
  block.probe_color = glm::vec4(glm::dvec4(in.color, in.alpha));
  glNamedBufferSubData(ubo_.id(), 0, sizeof(block), &block);

  // All state this pass depends on is set here.
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, surface_->width(), surface_->height());
  glDisable(GL_SCISSOR_TEST);
  const bool translucent = in.alpha < 1.0;
  if (translucent) {  // a ghost: blended, and it leaves the depth buffer to what is solid
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  } else {
    glDisable(GL_BLEND);
  }
  glDisable(GL_CULL_FACE);  // mesh probes may be open
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(translucent ? GL_FALSE : GL_TRUE);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, ubo_.id());
  glUseProgram(program_.id());
  mesh->draw();
  if (translucent) {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
}

}  // namespace ps
