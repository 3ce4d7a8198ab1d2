// A triangle mesh on the GPU: interleaved position/normal/colour (float), 32-bit indices.
// Attribute locations: 0 = position (mm), 1 = normal, 2 = colour (Mesh::colors, white if none),
// 3 = 4D depth w (Mesh::w4, 0 if none).
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
