// A triangle mesh on the GPU: interleaved position/normal (float), 32-bit indices.
// Attribute locations: 0 = position (mm), 1 = normal.
#pragma once

#include "gl/objects.h"
#include "scene/mesh.h"

namespace ps {

struct GpuMesh {
  gl::VertexArray vao;
  gl::Buffer vertices;
  gl::Buffer indices;
  GLsizei index_count = 0;

  // `dynamic`: the vertex buffer may be rewritten with update() (a deformable surface).
  static GpuMesh upload(const Mesh& mesh, bool dynamic = false);
  // New positions and normals for the same vertices (upload(mesh, true) only).
  void update(const Mesh& mesh);
  void draw() const;
};

}  // namespace ps
