// Mesh files into the scene frame through assimp (https://assimp-docs.readthedocs.io,
// "Post processing" and "Importer properties"). Order of work:
//   1. assimp: Triangulate, JoinIdenticalVertices, PreTransformVertices (node transforms
//      applied, hierarchy kept), SortByPType (points and lines removed), ValidateDataStructure.
//      Format-level conversions the importer itself makes (Collada's <unit> and <up_axis>)
//      happen here, before ours.
//   2. per mesh reached from the node tree: skip it when `exclude` matches its name, keep its
//      triangles, scale by metresPerUnit, rotate the given up axis onto +y.
//   3. optionally weld vertices split along texture seams (mergeByPosition).
//
// Why PreTransformVertices keeps the hierarchy: without AI_CONFIG_PP_PTV_KEEP_HIERARCHY it
// joins every mesh that shares a material into one, named after one of them, so `exclude`
// would drop or keep the wrong geometry (two OBJ groups without materials become one mesh).
// With it the meshes stay apart, in world space, each with its own name.

#include "MeshImport.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "io/AssimpHazards.h"

namespace figment {

namespace fs = std::filesystem;

namespace {

// An entry of `exclude` matches a mesh whose name contains it: the exact name
// ("human-highpolyeyesMesh" in human.zae) or any part of it ("eyes").
bool excluded(const std::string& meshName, const std::vector<std::string>& exclude) {
  return std::any_of(exclude.begin(), exclude.end(), [&](const std::string& pattern) {
    return !pattern.empty() && meshName.find(pattern) != std::string::npos;
  });
}

// Mesh indices in node-tree order, each once: with the hierarchy kept, a mesh that no
// node references was never transformed and is not part of the scene.
void collectMeshes(const aiNode* node, std::vector<unsigned>& order, std::vector<bool>& seen) {
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    const unsigned index = node->mMeshes[i];
    if (index < seen.size() && !seen[index]) {
      seen[index] = true;
      order.push_back(index);
    }
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) collectMeshes(node->mChildren[c], order, seen);
}

void appendTriangles(const aiMesh& part, const ImportOptions& options, TriangleMesh& mesh) {
  const int offset = static_cast<int>(mesh.vertices.size());
  for (unsigned i = 0; i < part.mNumVertices; ++i) {
    const aiVector3D& v = part.mVertices[i];
    mesh.vertices.push_back(toYUp(options.metresPerUnit * Vec3(v.x, v.y, v.z), options.upAxis));
  }
  for (unsigned f = 0; f < part.mNumFaces; ++f) {
    const aiFace& face = part.mFaces[f];
    if (face.mNumIndices != 3) continue;
    mesh.triangles.push_back({offset + static_cast<int>(face.mIndices[0]), offset + static_cast<int>(face.mIndices[1]),
                              offset + static_cast<int>(face.mIndices[2])});
  }
}

std::vector<fs::path> searchFolders(const std::string& sceneDir) {
  std::vector<fs::path> folders = modelPathFolders();
  if (!sceneDir.empty()) folders.emplace_back(sceneDir);
  const fs::path debian = "/usr/share/assimp/models";  // Debian's assimp-testmodels
  folders.push_back(debian);
  std::error_code error;
  if (fs::is_directory(debian, error)) {
    std::vector<fs::path> subfolders;
    for (const auto& entry : fs::directory_iterator(debian, error))
      if (entry.is_directory(error)) subfolders.push_back(entry.path());
    std::sort(subfolders.begin(), subfolders.end());  // a fixed order: the same file every run
    folders.insert(folders.end(), subfolders.begin(), subfolders.end());
  }
  return folders;
}

}  // namespace

ImportedMesh importMesh(const std::string& path, const ImportOptions& options) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) throw std::runtime_error(path + ": no such file");
  if (!(options.metresPerUnit > 0.0))
    throw std::runtime_error(path + ": metresPerUnit = " + std::to_string(options.metresPerUnit) + " must be > 0");
  if (const std::string hazard = assimpHazard(path); !hazard.empty()) throw std::runtime_error(path + ": " + hazard);

  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  importer.SetPropertyBool(AI_CONFIG_PP_PTV_KEEP_HIERARCHY, true);
  // Read, then post-process: in between, what assimp's readers get wrong is put right
  // (io/AssimpHazards.h), before a post-processing step aborts on it.
  const aiScene* scene = importer.ReadFile(path, 0);
  if (scene) correctPrimitiveTypes(*const_cast<aiScene*>(scene));
  if (scene)
    scene = importer.ApplyPostProcessing(aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                                         aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                                         aiProcess_SortByPType);
  if (!scene || !scene->mRootNode) throw std::runtime_error(path + ": " + importer.GetErrorString());

  std::vector<unsigned> order;
  std::vector<bool> seen(scene->mNumMeshes, false);
  collectMeshes(scene->mRootNode, order, seen);

  ImportedMesh result;
  for (const unsigned index : order) {
    const aiMesh& part = *scene->mMeshes[index];
    const std::string name = part.mName.C_Str();
    if (excluded(name, options.exclude)) continue;
    // A mesh placed by several nodes comes once per placement, under one name.
    if (std::find(result.meshNames.begin(), result.meshNames.end(), name) == result.meshNames.end())
      result.meshNames.push_back(name);
    appendTriangles(part, options, result.mesh);
  }
  if (result.mesh.triangles.empty()) throw std::runtime_error(path + ": no triangles (after exclusions)");
  if (options.mergeByPosition) result.mesh = figment::mergeByPosition(result.mesh);
  return result;
}

std::string findModelFile(const std::string& name, const std::string& sceneDir) {
  if (name.empty()) return {};
  const fs::path given(name);
  std::error_code error;
  if (fs::is_regular_file(given, error)) return given.string();
  if (given.is_absolute()) return {};
  for (const fs::path& folder : searchFolders(sceneDir)) {
    const fs::path candidate = folder / given;
    if (fs::is_regular_file(candidate, error)) return candidate.string();
  }
  return {};
}

std::vector<fs::path> modelPathFolders() {
  std::vector<fs::path> folders;
  if (const char* list = std::getenv("FIGMENT_MODEL_PATH")) {
    const std::string text = list;
    size_t start = 0;
    while (start <= text.size()) {
      const size_t end = std::min(text.find(':', start), text.size());
      if (end > start) folders.emplace_back(text.substr(start, end - start));
      start = end + 1;
    }
  }
  return folders;
}

}  // namespace figment
