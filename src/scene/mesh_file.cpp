// load_mesh_file: any format assimp reads (OBJ, PLY, STL, glTF, .blend, ...), all meshes merged.
#include <cmath>

#include <filesystem>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "scene/mesh.h"
#include "scene/mesh_procedural.h"

namespace ps {
namespace {

bool finite(const aiVector3D& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Appends one assimp mesh (triangles only; points and lines are skipped).
Status append_mesh(const std::string& path, const aiMesh& in, Mesh& out) {
  const auto base = static_cast<std::uint32_t>(out.positions.size());
  for (unsigned i = 0; i < in.mNumVertices; ++i) {
    const aiVector3D& p = in.mVertices[i];
    if (!finite(p)) {
      return make_error(path + ": cannot load mesh: vertex " + std::to_string(i) + " of mesh '" +
                        in.mName.C_Str() + "' is not finite (NaN or Inf)");
    }
    const aiVector3D n = in.mNormals && finite(in.mNormals[i]) ? in.mNormals[i]
                                                                : aiVector3D(0, 0, 1);
    out.positions.emplace_back(p.x, p.y, p.z);
    const glm::vec3 normal(n.x, n.y, n.z);
    const float length = glm::length(normal);
    out.normals.push_back(length > 0.0f ? normal / length : glm::vec3(0, 0, 1));
  }
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    const aiFace& face = in.mFaces[f];
    if (face.mNumIndices != 3) continue;
    for (unsigned k = 0; k < 3; ++k) out.indices.push_back(base + face.mIndices[k]);
  }
  if (out.indices.size() / 3 > kMaxMeshTriangles) {
    return make_error(path + ": cannot load mesh: more than " +
                      std::to_string(kMaxMeshTriangles) + " triangles (the limit)");
  }
  return ok_status();
}

}  // namespace

Result<Mesh> load_mesh_file(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (!ec && bytes > kMaxMeshFileBytes)
    return make_error(path + ": cannot load mesh: file is " + std::to_string(bytes) +
                      " bytes, more than the limit of " + std::to_string(kMaxMeshFileBytes));
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
    return make_error(path + ": cannot load mesh: " + importer.GetErrorString());
  }
  Mesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    if (Status s = append_mesh(path, *scene->mMeshes[m], mesh); !s) return s.error();
  }
  if (mesh.indices.empty()) {
    return make_error(path + ": cannot load mesh: the file contains no triangles");
  }
  mesh_detail::compute_bounds(mesh);
  return mesh;
}

}  // namespace ps
