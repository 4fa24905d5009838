#include "MeshImport.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace figment {

namespace fs = std::filesystem;

namespace {
// Right-handed rotations that take the file's up axis onto +y.
Vec3 toYUp(const Vec3& p, UpAxis up) {
  switch (up) {
    case UpAxis::Y: return p;
    case UpAxis::Z: return {p.x(), p.z(), -p.y()};     // -90 degrees about x
    case UpAxis::X: return {-p.y(), p.x(), p.z()};     // +90 degrees about z
    case UpAxis::NegY: return {p.x(), -p.y(), -p.z()}; // 180 degrees about x
    case UpAxis::NegZ: return {p.x(), -p.z(), p.y()};  // +90 degrees about x
    case UpAxis::NegX: return {p.y(), -p.x(), p.z()};  // -90 degrees about z
  }
  return p;
}

bool excluded(const std::string& meshName, const std::vector<std::string>& exclude) {
  for (const std::string& pattern : exclude)
    if (!pattern.empty() && meshName.find(pattern) != std::string::npos) return true;
  return false;
}
}  // namespace

ImportedMesh importMesh(const std::string& path, const ImportOptions& options) {
  if (!fs::is_regular_file(path)) throw std::runtime_error(path + ": no such file");
  if (!(options.metresPerUnit > 0.0))
    throw std::runtime_error(path + ": metresPerUnit = " + std::to_string(options.metresPerUnit) + " must be > 0");
  Assimp::Importer importer;
  // Points and lines are of no use to cloth or bodies: drop them at import.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                                  aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  if (!scene || !scene->mRootNode) throw std::runtime_error(path + ": " + importer.GetErrorString());

  ImportedMesh result;
  TriangleMesh& mesh = result.mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    const std::string name = part->mName.C_Str();
    if (excluded(name, options.exclude)) continue;
    result.meshNames.push_back(name);
    const int offset = static_cast<int>(mesh.vertices.size());
    for (unsigned i = 0; i < part->mNumVertices; ++i) {
      const aiVector3D& v = part->mVertices[i];
      mesh.vertices.push_back(toYUp(options.metresPerUnit * Vec3(v.x, v.y, v.z), options.upAxis));
    }
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.triangles.push_back({offset + static_cast<int>(face.mIndices[0]), offset + static_cast<int>(face.mIndices[1]),
                                offset + static_cast<int>(face.mIndices[2])});
    }
  }
  if (mesh.triangles.empty()) throw std::runtime_error(path + ": no triangles (after exclusions)");
  if (options.mergeByPosition) mesh = figment::mergeByPosition(mesh, 1e-6);
  return result;
}

std::string findModelFile(const std::string& name, const std::string& sceneDir) {
  if (name.empty()) return {};
  const fs::path given(name);
  if (fs::is_regular_file(given)) return given.string();
  if (given.is_absolute()) return {};
  std::vector<fs::path> folders;
  if (const char* path = std::getenv("FIGMENT_MODEL_PATH")) {
    std::string list = path;
    size_t start = 0;
    while (start <= list.size()) {
      const size_t end = std::min(list.find(':', start), list.size());
      if (end > start) folders.emplace_back(list.substr(start, end - start));
      start = end + 1;
    }
  }
  if (!sceneDir.empty()) folders.emplace_back(sceneDir);
  const fs::path debian = "/usr/share/assimp/models";  // Debian's assimp-testmodels
  folders.push_back(debian);
  std::error_code error;
  if (fs::is_directory(debian, error)) {
    std::vector<fs::path> subfolders;
    for (const auto& entry : fs::directory_iterator(debian, error))
      if (entry.is_directory()) subfolders.push_back(entry.path());
    std::sort(subfolders.begin(), subfolders.end());  // a fixed order: the same file every run
    folders.insert(folders.end(), subfolders.begin(), subfolders.end());
  }
  for (const fs::path& folder : folders) {
    const fs::path candidate = folder / given;
    if (fs::is_regular_file(candidate, error)) return candidate.string();
  }
  return {};
}

}  // namespace figment
