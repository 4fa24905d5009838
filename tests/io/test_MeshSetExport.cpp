// Coloured mesh sets out through assimp: each format reads back mesh for mesh, with its
// name, vertices and colour; the files appear whole with their companions, or not at all.
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/MeshSetExport.h"
#include "support/TempDir.h"

using namespace figment;
using figment::test::TempDir;

namespace {

// A unit square in the z = 0 plane (facing +z) and a triangle above it, each its own colour.
std::vector<ColouredMesh> twoMeshes() {
  ColouredMesh square;
  square.name = "Square";
  square.mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  square.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  square.normals.assign(4, Vec3(0, 0, 1));
  square.colour = {0.12f, 0.25f, 0.70f};
  square.twoSided = true;
  ColouredMesh triangle;
  triangle.name = "Triangle";
  triangle.mesh.vertices = {Vec3(0, 2, 0), Vec3(0.5, 2, 0.5), Vec3(0, 2.5, 0)};
  triangle.mesh.triangles = {{0, 1, 2}};
  triangle.normals.assign(3, Vec3(2, 0, 0));  // not unit: the export makes it so
  triangle.colour = {0.8f, 0.58f, 0.45f};
  return {square, triangle};
}

std::vector<std::string> namesIn(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

// What must read back from any format: per mesh its vertices (joined again where the
// format unrolls them per corner), normals of unit length and its diffuse colour.
void expectReadsBack(const aiScene* scene, const std::vector<ColouredMesh>& written) {
  ASSERT_NE(scene, nullptr);
  ASSERT_EQ(scene->mNumMeshes, written.size());
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const ColouredMesh& part = written[m];
    ASSERT_EQ(mesh->mNumVertices, part.mesh.vertices.size()) << part.name;
    EXPECT_EQ(mesh->mNumFaces, part.mesh.triangles.size()) << part.name;
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
      const aiVector3D& v = mesh->mVertices[i];
      const bool listed = std::any_of(part.mesh.vertices.begin(), part.mesh.vertices.end(), [&v](const Vec3& w) {
        return (Vec3(v.x, v.y, v.z) - w).norm() < 1e-6;  // float, 9 digits in OBJ
      });
      EXPECT_TRUE(listed) << part.name << " vertex " << i;
      ASSERT_TRUE(mesh->HasNormals());
      EXPECT_NEAR(mesh->mNormals[i].Length(), 1.0, 1e-6);
    }
    aiColor3D colour;
    ASSERT_EQ(scene->mMaterials[mesh->mMaterialIndex]->Get(AI_MATKEY_COLOR_DIFFUSE, colour), AI_SUCCESS);
    EXPECT_NEAR(colour.r, part.colour[0], 1e-6);
    EXPECT_NEAR(colour.g, part.colour[1], 1e-6);
    EXPECT_NEAR(colour.b, part.colour[2], 1e-6);
  }
}

class MeshSetFormats : public ::testing::TestWithParam<const char*> {};

}  // namespace

TEST_P(MeshSetFormats, ReadsBackMeshForMeshWithColours) {
  const TempDir dir;
  const std::string path = (dir.path() / (std::string("set.") + GetParam())).string();
  std::vector<std::string> written;
  exportMeshSet(twoMeshes(), path, &written);
  ASSERT_FALSE(written.empty());
  EXPECT_EQ(written.front(), path);
  EXPECT_EQ(written.size(), namesIn(dir.path()).size()) << "every file it made is listed";
  Assimp::Importer importer;
  expectReadsBack(importer.ReadFile(path, aiProcess_JoinIdenticalVertices), twoMeshes());
}

INSTANTIATE_TEST_SUITE_P(MeshSetExport, MeshSetFormats, ::testing::Values("glb", "gltf", "obj"));

TEST(MeshSetExport, EachFormatWritesItsFileAndItsCompanionsOnly) {
  const TempDir dir;
  exportMeshSet(twoMeshes(), (dir.path() / "a.glb").string());
  exportMeshSet(twoMeshes(), (dir.path() / "b.gltf").string());
  exportMeshSet(twoMeshes(), (dir.path() / "c.OBJ").string());
  EXPECT_EQ(namesIn(dir.path()), (std::vector<std::string>{"a.glb", "b.bin", "b.gltf", "c.OBJ", "c.mtl"}));
}

TEST(MeshSetExport, GlbInMemoryReadsBackAsTheFileDoes) {
  const std::vector<unsigned char> bytes = glbOfMeshSet(twoMeshes());
  ASSERT_GT(bytes.size(), 12u);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "glTF");  // the GLB header's magic
  Assimp::Importer importer;
  expectReadsBack(importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, "glb"), twoMeshes());
}

TEST(MeshSetExport, KnowsItsFormatsByExtension) {
  EXPECT_EQ(meshSetFormatOf("a/b.glb"), MeshSetFormat::Glb);
  EXPECT_EQ(meshSetFormatOf("b.GLTF"), MeshSetFormat::Gltf);
  EXPECT_EQ(meshSetFormatOf("b.obj"), MeshSetFormat::Obj);
  EXPECT_EQ(meshSetFormatOf("b.fbx"), std::nullopt);
  EXPECT_EQ(meshSetFormatOf("glb"), std::nullopt);
  EXPECT_EQ(meshSetFormatOf("b.glb/"), std::nullopt);
}

TEST(MeshSetExport, RefusesWhatItCannotWriteAndLeavesNothing) {
  const TempDir dir;
  const auto refused = [](const std::vector<ColouredMesh>& meshes, const std::string& path) {
    try {
      exportMeshSet(meshes, path);
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("no exception");
  };
  const std::string glb = (dir.path() / "out.glb").string();
  EXPECT_EQ(refused(twoMeshes(), (dir.path() / "out.fbx").string()),
            (dir.path() / "out.fbx").string() + ": unknown extension (.glb, .gltf or .obj)");
  EXPECT_EQ(refused({}, glb), glb + ": nothing to write (no meshes)");
  std::vector<ColouredMesh> broken = twoMeshes();
  broken[1].mesh.triangles.push_back({0, 1, 7});
  EXPECT_EQ(refused(broken, glb), glb + ": mesh 'Triangle': triangle index 7 out of range (3 vertices)");
  broken = twoMeshes();
  broken[0].normals.pop_back();
  EXPECT_EQ(refused(broken, glb), glb + ": mesh 'Square' has 3 normals for 4 vertices");
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));

  const std::string file = dir.file("a-file", "x");  // a folder cannot be made under a file
  const std::string under = file + "/out.gltf";
  EXPECT_EQ(refused(twoMeshes(), under).rfind(under + ": cannot make the folder", 0), 0u);
  EXPECT_EQ(namesIn(dir.path()), std::vector<std::string>{"a-file"});
  EXPECT_THROW(glbOfMeshSet({}), std::runtime_error);
}
