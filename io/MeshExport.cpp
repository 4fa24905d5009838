// OBJ output through assimp's Exporter (https://assimp-docs.readthedocs.io, "Export"):
// one aiScene with a root node, one mesh and the one default material the OBJ exporter
// needs to name (no .mtl file is written for "objnomtl").

#include "io/MeshExport.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <assimp/Exporter.hpp>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "io/AtomicFile.h"

namespace figment {

namespace {

// The aiScene destructor frees what it points to, so everything is allocated with new.
std::unique_ptr<aiScene> sceneOf(const TriangleMesh& mesh) {
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode("garment");
  scene->mRootNode->mNumMeshes = 1;
  scene->mRootNode->mMeshes = new unsigned[1]{0};

  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial* [1] { new aiMaterial() };

  auto* part = new aiMesh();
  part->mName = "garment";
  part->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  part->mMaterialIndex = 0;
  part->mNumVertices = static_cast<unsigned>(mesh.vertices.size());
  part->mVertices = new aiVector3D[part->mNumVertices];
  for (unsigned i = 0; i < part->mNumVertices; ++i) {
    const Vec3& v = mesh.vertices[i];
    part->mVertices[i] =
        aiVector3D(static_cast<ai_real>(v.x()), static_cast<ai_real>(v.y()), static_cast<ai_real>(v.z()));
  }
  part->mNumFaces = static_cast<unsigned>(mesh.triangles.size());
  part->mFaces = new aiFace[part->mNumFaces];
  for (unsigned f = 0; f < part->mNumFaces; ++f) {
    aiFace& face = part->mFaces[f];
    face.mNumIndices = 3;
    face.mIndices = new unsigned[3];
    for (int k = 0; k < 3; ++k) face.mIndices[k] = static_cast<unsigned>(mesh.triangles[f][k]);
  }
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh* [1] { part };
  return scene;
}

void checkIndices(const TriangleMesh& mesh, const std::string& path) {
  const int count = static_cast<int>(mesh.vertices.size());
  for (const Triangle& t : mesh.triangles)
    for (const int index : t)
      if (index < 0 || index >= count)
        throw std::runtime_error(path + ": triangle index " + std::to_string(index) + " out of range (" +
                                 std::to_string(count) + " vertices)");
}

}  // namespace

void exportObj(const TriangleMesh& mesh, const std::string& path) {
  if (mesh.triangles.empty()) throw std::runtime_error(path + ": nothing to write (no triangles)");
  checkIndices(mesh, path);

  const std::unique_ptr<aiScene> scene = sceneOf(mesh);
  const std::string error = writeAtomically(path, [&scene](const std::string& temporary) -> std::string {
    Assimp::Exporter exporter;
    if (exporter.Export(scene.get(), "objnomtl", temporary) != AI_SUCCESS) return exporter.GetErrorString();
    return "";
  });
  if (!error.empty()) throw std::runtime_error(path + ": " + error);
}

void exportIv(const TriangleMesh& mesh, const std::string& path) {
  if (mesh.triangles.empty()) throw std::runtime_error(path + ": nothing to write (no triangles)");
  checkIndices(mesh, path);
  const std::string error = writeAtomically(path, [&mesh](const std::string& temporary) -> std::string {
    std::ofstream out(temporary);
    out.precision(9);
    out << "#Inventor V2.1 ascii\n\nSeparator {\n"
           "  ShapeHints { vertexOrdering COUNTERCLOCKWISE  shapeType SOLID  creaseAngle 1.0 }\n"
           "  Coordinate3 { point [\n";
    for (const Vec3& p : mesh.vertices) out << "    " << p.x() << ' ' << p.y() << ' ' << p.z() << ",\n";
    out << "  ] }\n  IndexedFaceSet { coordIndex [\n";
    for (const Triangle& t : mesh.triangles) out << "    " << t[0] << ", " << t[1] << ", " << t[2] << ", -1,\n";
    out << "  ] }\n}\n";
    out.close();
    return out ? "" : "cannot be written";
  });
  if (!error.empty()) throw std::runtime_error(path + ": " + error);
}

}  // namespace figment
