// Coloured meshes out through assimp's Exporter (https://assimp-docs.readthedocs.io,
// "Export"): "glb2" and "gltf2" (glTF 2.0: a material's AI_MATKEY_BASE_COLOR becomes its
// pbrMetallicRoughness.baseColorFactor, AI_MATKEY_TWOSIDED its doubleSided) and "obj"
// (AI_MATKEY_COLOR_DIFFUSE becomes the .mtl's Kd).

#include "io/MeshSetExport.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Exporter.hpp>
#include <cctype>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "io/AtomicFile.h"

namespace figment {

namespace {

aiVector3D toAi(const Vec3& v) {
  return aiVector3D(static_cast<ai_real>(v.x()), static_cast<ai_real>(v.y()), static_cast<ai_real>(v.z()));
}

// Unit length in single precision too: the glTF validator holds normals to it.
aiVector3D unitNormal(const Vec3& n) {
  aiVector3D normal = toAi(n);
  const ai_real length = normal.Length();
  return length > 0 ? normal / length : aiVector3D(0, 1, 0);
}

aiMesh* meshOf(const ColouredMesh& part, unsigned materialIndex) {
  auto* mesh = new aiMesh();
  mesh->mName = part.name;
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mMaterialIndex = materialIndex;
  mesh->mNumVertices = static_cast<unsigned>(part.mesh.vertices.size());
  mesh->mVertices = new aiVector3D[mesh->mNumVertices];
  mesh->mNormals = new aiVector3D[mesh->mNumVertices];
  for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
    mesh->mVertices[i] = toAi(part.mesh.vertices[i]);
    mesh->mNormals[i] = unitNormal(part.normals[i]);
  }
  mesh->mNumFaces = static_cast<unsigned>(part.mesh.triangles.size());
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    aiFace& face = mesh->mFaces[f];
    face.mNumIndices = 3;
    face.mIndices = new unsigned[3];
    for (int k = 0; k < 3; ++k) face.mIndices[k] = static_cast<unsigned>(part.mesh.triangles[f][k]);
  }
  return mesh;
}

// A matte cloth or skin: the colour, no metal (glTF's default metallicFactor is 1).
aiMaterial* materialOf(const ColouredMesh& part) {
  auto* material = new aiMaterial();
  const aiString name(part.name);
  material->AddProperty(&name, AI_MATKEY_NAME);
  const aiColor4D colour(part.colour[0], part.colour[1], part.colour[2], part.opacity);
  material->AddProperty(&colour, 1, AI_MATKEY_BASE_COLOR);
  const aiColor3D diffuse(part.colour[0], part.colour[1], part.colour[2]);
  material->AddProperty(&diffuse, 1, AI_MATKEY_COLOR_DIFFUSE);
  const float opacity = part.opacity;
  material->AddProperty(&opacity, 1, AI_MATKEY_OPACITY);
  const float metallic = 0.0f;
  const float roughness = 1.0f;
  material->AddProperty(&metallic, 1, AI_MATKEY_METALLIC_FACTOR);
  material->AddProperty(&roughness, 1, AI_MATKEY_ROUGHNESS_FACTOR);
  const int twoSided = part.twoSided ? 1 : 0;
  material->AddProperty(&twoSided, 1, AI_MATKEY_TWOSIDED);
  return material;
}

// The aiScene destructor frees what it points to, so everything is allocated with new:
// a root node with one child node per mesh, each mesh with its own material.
std::unique_ptr<aiScene> sceneOf(const std::vector<ColouredMesh>& meshes) {
  auto scene = std::make_unique<aiScene>();
  const auto count = static_cast<unsigned>(meshes.size());
  scene->mRootNode = new aiNode("figment");
  scene->mRootNode->mNumChildren = count;
  scene->mRootNode->mChildren = new aiNode*[count];
  scene->mNumMeshes = count;
  scene->mMeshes = new aiMesh*[count];
  scene->mNumMaterials = count;
  scene->mMaterials = new aiMaterial*[count];
  for (unsigned i = 0; i < count; ++i) {
    scene->mMeshes[i] = meshOf(meshes[i], i);
    scene->mMaterials[i] = materialOf(meshes[i]);
    auto* node = new aiNode(meshes[i].name);
    node->mParent = scene->mRootNode;
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{i};
    scene->mRootNode->mChildren[i] = node;
  }
  return scene;
}

// "" when every mesh can be written, else what is wrong with the first that cannot.
std::string checkMeshes(const std::vector<ColouredMesh>& meshes) {
  if (meshes.empty()) return "nothing to write (no meshes)";
  for (const ColouredMesh& part : meshes) {
    const int count = static_cast<int>(part.mesh.vertices.size());
    if (part.mesh.triangles.empty()) return "mesh '" + part.name + "' has no triangles";
    if (part.normals.size() != part.mesh.vertices.size())
      return "mesh '" + part.name + "' has " + std::to_string(part.normals.size()) + " normals for " +
             std::to_string(count) + " vertices";
    for (const Triangle& t : part.mesh.triangles)
      for (const int index : t)
        if (index < 0 || index >= count)
          return "mesh '" + part.name + "': triangle index " + std::to_string(index) + " out of range (" +
                 std::to_string(count) + " vertices)";
  }
  return "";
}

// Each format once: the extension that asks for it and assimp's exporter that writes it.
struct FormatEntry {
  MeshSetFormat format;
  const char* extension;
  const char* exporterId;
};
constexpr FormatEntry kFormats[] = {
    {MeshSetFormat::Glb, ".glb", "glb2"}, {MeshSetFormat::Gltf, ".gltf", "gltf2"}, {MeshSetFormat::Obj, ".obj", "obj"}};

const char* exporterId(MeshSetFormat format) {
  for (const FormatEntry& entry : kFormats)
    if (entry.format == format) return entry.exporterId;
  return "";
}

}  // namespace

std::optional<MeshSetFormat> meshSetFormatOf(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const FormatEntry& entry : kFormats)
    if (extension == entry.extension) return entry.format;
  return std::nullopt;
}

void exportMeshSet(const std::vector<ColouredMesh>& meshes, const std::string& path,
                   std::vector<std::string>* written) {
  const std::optional<MeshSetFormat> format = meshSetFormatOf(path);
  if (!format) throw std::runtime_error(path + ": unknown extension (.glb, .gltf or .obj)");
  std::string error = checkMeshes(meshes);
  if (!error.empty()) throw std::runtime_error(path + ": " + error);
  const std::unique_ptr<aiScene> scene = sceneOf(meshes);
  error = writeFilesAtomically(
      path,
      [&scene, &format](const std::string& temporary) -> std::string {
        Assimp::Exporter exporter;
        if (exporter.Export(scene.get(), exporterId(*format), temporary) != AI_SUCCESS)
          return exporter.GetErrorString();
        return "";
      },
      written);
  if (!error.empty()) throw std::runtime_error(path + ": " + error);
}

std::vector<unsigned char> glbOfMeshSet(const std::vector<ColouredMesh>& meshes) {
  const std::string error = checkMeshes(meshes);
  if (!error.empty()) throw std::runtime_error(error);
  const std::unique_ptr<aiScene> scene = sceneOf(meshes);
  Assimp::Exporter exporter;
  const aiExportDataBlob* blob = exporter.ExportToBlob(scene.get(), exporterId(MeshSetFormat::Glb));
  if (!blob) throw std::runtime_error(std::string("GLB export failed: ") + exporter.GetErrorString());
  const auto* bytes = static_cast<const unsigned char*>(blob->data);
  return std::vector<unsigned char>(bytes, bytes + blob->size);
}

}  // namespace figment
