// load_mesh_file: any format assimp reads (OBJ, PLY, STL, glTF, .blend, ...), all meshes merged.
#include <cctype>
#include <cmath>

#include <filesystem>
#include <algorithm>
#include <vector>
#include <sstream>
#include <fstream>

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

// Headers of text OFF and PLY files, checked before assimp reads them. Element counts: assimp allocates arrays of
// the declared size before reading a single element, so a header claiming 10^19 faces made it
// ask for 8 GiB (found by fuzz_mesh); refuse such files before assimp sees them.
Status check_declared_counts(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  std::istringstream words(head);
  std::vector<std::string> w;
  for (std::string word; words >> word;) w.push_back(word);
  const auto too_many = [&](const std::string& count) {
    // A count that does not parse is left to assimp; one with > 10 digits is surely too many.
    if (count.empty() || count.find_first_not_of("0123456789") != std::string::npos) return false;
    return count.size() > 10 || std::stoull(count) > 3 * kMaxMeshTriangles;
  };
  bool bad = false;
  // OFF, COFF, NOFF...: "nv nf ne". assimp also reads .off files whose keyword is missing, so
  // check the first numbers of any .off file too (fuzz_mesh found an 8 GiB-per-count one).
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (!w.empty() && (ext == ".off" || w[0].find("OFF") != std::string::npos))
    for (size_t i = 0; i < std::min<size_t>(w.size(), 4); ++i) bad = bad || too_many(w[i]);
  // assimp takes any file whose first word starts with "ply", or named .ply, as PLY.
  const bool ply = !w.empty() && (ext == ".ply" || w[0].rfind("ply", 0) == 0);
  if (ply)
    for (size_t i = 0; i + 2 < w.size(); ++i)
      if (w[i] == "element") bad = bad || too_many(w[i + 2]);
  // assimp 5.2's PLY reader loops forever on a header without end_header (found by fuzz_mesh).
  if (ply && std::find(w.begin(), w.end(), "end_header") == w.end())
    return make_error(path + ": cannot load mesh: PLY header has no end_header in its first 4 KiB");
  if (bad)
    return make_error(path + ": cannot load mesh: its header declares more than " +
                      std::to_string(3 * kMaxMeshTriangles) + " elements (limit: " +
                      std::to_string(kMaxMeshTriangles) + " triangles)");
  return ok_status();
}

}  // namespace

// Formats we ship, test and fuzz. assimp reads many more, but fuzzing found a heap overflow in
// its glTF importer (docs/hardening.md): formats outside this list are refused rather than
// handed to importers nobody here has hardened.
constexpr const char* kMeshFormats[] = {".obj", ".ply", ".stl", ".off", ".blend"};

Status check_format(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  std::string list;
  for (const char* f : kMeshFormats) {
    if (ext == f) return ok_status();
    list += (list.empty() ? "" : ", ") + std::string(f);
  }
  return make_error(path + ": cannot load mesh: format '" + ext + "' is not supported (supported: " + list + ")");
}

Result<Mesh> load_mesh_file(const std::string& path) {
  if (Status s = check_format(path); !s) return s.error();
  if (Status s = check_declared_counts(path); !s) return s.error();
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
