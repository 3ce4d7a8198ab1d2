// load_mesh_file: any format assimp reads (OBJ, PLY, STL, glTF, .blend, ...), all meshes merged.
#include <cctype>
#include <cmath>

#include <filesystem>
#include <algorithm>
#include <vector>
#include <sstream>
#include <fstream>
#include <set>

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

bool is_count(const std::string& word) {
  return !word.empty() && word.find_first_not_of("0123456789") == std::string::npos;
}

// PLY headers are checked line by line against the format's grammar before assimp sees them:
// assimp 5.2's PLY reader loops forever on several malformed headers (fuzz_mesh found one
// without end_header and one with end_header at the end of a property line), so only headers
// it reads correctly get through. `head` is the file's first 4 KiB. Kept whole (over 40 lines):
// one chain of cases, one per kind of header line, that reads like the format's grammar.
Status check_ply_header(const std::string& path, const std::string& head) {
  static const std::set<std::string> kTypes = {
      "char",  "uchar",  "short",  "ushort", "int",    "uint",    "float",   "double",
      "int8",  "uint8",  "int16",  "uint16", "int32",  "uint32",  "float32", "float64"};
  const auto fail = [&](size_t line, const std::string& what) {
    return make_error(path + ":" + std::to_string(line) + ": cannot load mesh: PLY header " +
                      what);
  };
  std::istringstream lines(head);
  std::string line;
  bool in_element = false;
  for (size_t n = 1; std::getline(lines, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find('\0') != std::string::npos) return fail(n, "line contains a NUL byte");
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    const std::string key = w.empty() ? "" : w[0];
    if (n == 1) {
      if (w.size() != 1 || key != "ply") return fail(n, "must start with a line 'ply'");
    } else if (n == 2) {
      if (w.size() != 3 || key != "format" ||
          (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian") ||
          w[2] != "1.0")
        return fail(n, "second line must be 'format ascii|binary_little_endian|binary_big_endian 1.0'");
    } else if (key == "comment" || key == "obj_info") {
      continue;
    } else if (key == "element") {
      if (w.size() != 3 || !is_count(w[2])) return fail(n, "'element NAME COUNT' expected");
      if (w[2].size() > 10 || std::stoull(w[2]) > 3 * kMaxMeshTriangles)
        return make_error(path + ": cannot load mesh: its header declares more than " +
                          std::to_string(3 * kMaxMeshTriangles) + " elements (limit: " +
                          std::to_string(kMaxMeshTriangles) + " triangles)");
      in_element = true;
    } else if (key == "property") {
      const bool scalar = w.size() == 3 && kTypes.count(w[1]);
      const bool list = w.size() == 5 && w[1] == "list" && kTypes.count(w[2]) && kTypes.count(w[3]);
      if (!scalar && !list)
        return fail(n, "'property TYPE NAME' or 'property list TYPE TYPE NAME' expected");
      if (!in_element) return fail(n, "property before any element");
    } else if (key == "end_header" && w.size() == 1) {
      return ok_status();
    } else {
      return fail(n, "line not understood (expected element, property, comment or end_header)");
    }
  }
  return make_error(path + ": cannot load mesh: PLY header has no end_header in its first 4 KiB");
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
  const auto too_many = [&](const std::string& word) {
    // assimp reads a count as the digits at the start of a word (strtoul10) and ignores what
    // follows, so "19999999999\xbc..." is a count of 2e10 (fuzz_mesh found that one too). A
    // negative count would wrap to a huge unsigned one. A word not starting with digits is left
    // to assimp; one with > 10 digits is surely too many.
    const bool negative = !word.empty() && word[0] == '-';
    const size_t start = (!word.empty() && (word[0] == '+' || negative)) ? 1 : 0;
    size_t end = start;
    while (end < word.size() && word[end] >= '0' && word[end] <= '9') ++end;
    if (end == start) return false;
    const std::string digits = word.substr(start, end - start);
    if (negative) return digits.find_first_not_of('0') != std::string::npos;
    return digits.size() > 10 || std::stoull(digits) > 3 * kMaxMeshTriangles;
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
  if (ply) return check_ply_header(path, head);
  if (bad)
    return make_error(path + ": cannot load mesh: its header declares more than " +
                      std::to_string(3 * kMaxMeshTriangles) + " elements (limit: " +
                      std::to_string(kMaxMeshTriangles) + " triangles)");
  return ok_status();
}

// Every face has 1..kMaxFaceIndices indices, all in range, and each mesh's mPrimitiveTypes says
// what its faces are (the post-processing steps trust both). Recomputing the flags is safe: the
// scene belongs to the importer until it is destroyed, and we are its only user.
Status check_imported_faces(const std::string& path, const aiScene& scene) {
  constexpr unsigned kMaxFaceIndices = 1u << 16;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    aiMesh& mesh = *scene.mMeshes[m];
    unsigned types = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices == 0 || face.mNumIndices > kMaxFaceIndices || !face.mIndices)
        return make_error(path + ": cannot load mesh: face " + std::to_string(f) + " of mesh '" +
                          mesh.mName.C_Str() + "' has " + std::to_string(face.mNumIndices) +
                          " vertex indices (1 to " + std::to_string(kMaxFaceIndices) + " allowed)");
      for (unsigned k = 0; k < face.mNumIndices; ++k)
        if (face.mIndices[k] >= mesh.mNumVertices)
          return make_error(path + ": cannot load mesh: face " + std::to_string(f) + " of mesh '" +
                            mesh.mName.C_Str() + "' uses vertex " + std::to_string(face.mIndices[k]) +
                            " of " + std::to_string(mesh.mNumVertices));
      types |= face.mNumIndices == 1   ? aiPrimitiveType_POINT
               : face.mNumIndices == 2 ? aiPrimitiveType_LINE
               : face.mNumIndices == 3 ? aiPrimitiveType_TRIANGLE
                                       : aiPrimitiveType_POLYGON;
    }
    mesh.mPrimitiveTypes = types;
  }
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
  // Two steps: read and validate, check what the importer produced, then post-process. Debian's
  // assimp keeps its ai_assert()s, which abort the process when an importer hands the
  // post-processing steps a mesh that contradicts itself (fuzz_mesh: a PLY face list cut short
  // left a mesh flagged as polygons with none, and Triangulate aborted).
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
    return make_error(path + ": cannot load mesh: " + importer.GetErrorString());
  }
  if (Status s = check_imported_faces(path, *scene); !s) return s.error();
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                       aiProcess_JoinIdenticalVertices |
                                       aiProcess_PreTransformVertices);
  if (!scene) return make_error(path + ": cannot load mesh: " + importer.GetErrorString());
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
