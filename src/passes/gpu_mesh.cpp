#include "passes/gpu_mesh.h"

#include <vector>

namespace ps {

namespace {

std::vector<float> interleave(const Mesh& mesh) {
  std::vector<float> interleaved;
  interleaved.reserve(mesh.positions.size() * 10);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i];
    const glm::vec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0.0f, 0.0f, 1.0f);
    // White (exactly 1.0) when the mesh has no colours: albedo * 1.0 leaves every image as it was.
    const glm::vec3 c = i < mesh.colors.size() ? mesh.colors[i] : glm::vec3(1.0f);
    const float w4 = i < mesh.w4.size() ? mesh.w4[i] : 0.0f;
    interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z, c.x, c.y, c.z, w4});
  }
  return interleaved;
}

}  // namespace

GpuMesh GpuMesh::upload(const Mesh& mesh, bool dynamic) {
  GpuMesh g;
  const std::vector<float> interleaved = interleave(mesh);
  g.vertices = gl::make_buffer(static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
                               interleaved.data(), dynamic ? GL_DYNAMIC_STORAGE_BIT : 0);
  g.indices = gl::make_buffer(static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                              mesh.indices.data(), 0);
  g.index_count = static_cast<GLsizei>(mesh.indices.size());
  g.vao = gl::make_vertex_array();
  const GLuint vao = g.vao.id();
  glVertexArrayVertexBuffer(vao, 0, g.vertices.id(), 0, 10 * sizeof(float));
  glVertexArrayElementBuffer(vao, g.indices.id());
  for (GLuint attr = 0; attr < 3; ++attr) {
    glEnableVertexArrayAttrib(vao, attr);
    glVertexArrayAttribFormat(vao, attr, 3, GL_FLOAT, GL_FALSE, attr * 3 * sizeof(float));
    glVertexArrayAttribBinding(vao, attr, 0);
  }
  glEnableVertexArrayAttrib(vao, 3);
  glVertexArrayAttribFormat(vao, 3, 1, GL_FLOAT, GL_FALSE, 9 * sizeof(float));
  glVertexArrayAttribBinding(vao, 3, 0);
  return g;
}

void GpuMesh::update(const Mesh& mesh) {
  const std::vector<float> interleaved = interleave(mesh);
  glNamedBufferSubData(vertices.id(), 0, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
                       interleaved.data());
}

void GpuMesh::draw() const {
  glBindVertexArray(vao.id());
  glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);
}

}  // namespace ps
