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

  static GpuMesh upload(const Mesh& mesh);
  void draw() const;
};

}  // namespace ps
