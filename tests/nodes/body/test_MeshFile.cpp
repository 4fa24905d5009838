// MeshFile: reads meshes through io/, resolves names next to the .iv file, reports load
// errors as read errors, draws through hidden nodes and offers its collision surface.

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPickedPoint.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "io/MeshImport.h"
#include "nodes/body/MeshFile.h"
#include "sim/collision/MeshCollider.h"
#include "sim/core/TriangleMesh.h"
#include "support/ActionChecks.h"
#include "support/MeshChecks.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

class MeshFileTest : public ::testing::Test {
 protected:
  void SetUp() override { initCoin(); }
  TempDir dir;

  // A scene file in `dir` holding one MeshFile with the given fields.
  std::string scene(const std::string& fields) {
    return dir.file("scene.iv", "#Inventor V2.1 ascii\nSeparator {\n DEF Mesh MeshFile { " + fields + " }\n}\n");
  }
};

bool humanAvailable() {
  return !figment::findModelFile("human.zae").empty();
}

}  // namespace

TEST_F(MeshFileTest, LoadsAFileNamedRelativeToItsSceneFile) {
  dir.file("cube.obj", cubeObj());
  const std::string path = scene("fileName \"cube.obj\"");
  // Read from elsewhere: only the scene file's folder can explain finding cube.obj.
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  SceneRoot root = readFile(path);
  std::filesystem::current_path(cwd);
  ASSERT_TRUE(root);
  auto* mesh = find<MeshFile>(root.get());
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(mesh->point.getNum(), 8);
  EXPECT_EQ(mesh->coordIndex.getNum(), 12 * 4);  // triangles, each ended by -1
  EXPECT_EQ(mesh->collisionSurface().vertices.size(), 8u);
  EXPECT_EQ(mesh->collisionSurface().triangles.size(), 12u);
}

TEST_F(MeshFileTest, AppliesMetresPerUnit) {
  dir.file("cube_cm.obj", cubeObj(100.0));
  SceneRoot root = readFile(scene("fileName \"cube_cm.obj\" metresPerUnit 0.01"));
  ASSERT_TRUE(root);
  auto* mesh = find<MeshFile>(root.get());
  SbBox3f box;
  for (int i = 0; i < mesh->point.getNum(); ++i) box.extendBy(mesh->point[i]);
  EXPECT_NEAR((box.getMax() - box.getMin()).length(), std::sqrt(3.0f), 1e-5f);
}

TEST_F(MeshFileTest, RotatesTheUpAxisOntoY) {
  // A 1 x 1 x 3 box standing along +z becomes 3 m tall along y.
  std::string tall = cubeObj();
  dir.file("tall.obj",
           "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 3\nv 1 0 3\nv 0 1 3\nv 1 1 3\n" + tall.substr(tall.find("f ")));
  SceneRoot root = readFile(scene("fileName \"tall.obj\" upAxis Z"));
  ASSERT_TRUE(root);
  auto* mesh = find<MeshFile>(root.get());
  SbBox3f box;
  for (int i = 0; i < mesh->point.getNum(); ++i) box.extendBy(mesh->point[i]);
  float dx, dy, dz;
  box.getSize(dx, dy, dz);
  EXPECT_NEAR(dy, 3.0f, 1e-5f);
  EXPECT_NEAR(dx, 1.0f, 1e-5f);
  EXPECT_NEAR(dz, 1.0f, 1e-5f);
}

TEST_F(MeshFileTest, MissingFileIsAReadErrorNamingSceneNodeFieldAndValue) {
  const std::string path = scene("fileName \"nothere.obj\"");
  CapturedErrors errors;
  SceneRoot root = readFile(path);
  EXPECT_FALSE(root);
  ASSERT_FALSE(errors.messages.empty());
  const std::string& message = errors.messages.front();
  EXPECT_NE(message.find("MeshFile 'Mesh'"), std::string::npos) << message;
  EXPECT_NE(message.find("fileName \"nothere.obj\""), std::string::npos) << message;
  EXPECT_NE(message.find("scene.iv"), std::string::npos) << message;
}

TEST_F(MeshFileTest, UnknownCollisionExcludeIsAReadError) {
  dir.file("cube.obj", cubeObj());
  CapturedErrors errors;
  SceneRoot root = readFile(scene("fileName \"cube.obj\" collisionExclude \"eyes\""));
  EXPECT_FALSE(root);
  EXPECT_NE(errors.all().find("collisionExclude \"eyes\""), std::string::npos) << errors.all();
}

TEST_F(MeshFileTest, NonPositiveMetresPerUnitIsAReadError) {
  dir.file("cube.obj", cubeObj());
  CapturedErrors errors;
  SceneRoot root = readFile(scene("fileName \"cube.obj\" metresPerUnit 0"));
  EXPECT_FALSE(root);
  EXPECT_NE(errors.all().find("metresPerUnit = 0 must be > 0"), std::string::npos) << errors.all();
}

TEST_F(MeshFileTest, ReloadsWhenFileNameChangesAndPostsErrorsOutsideReading) {
  dir.file("cube.obj", cubeObj());
  SceneRoot root = readFile(scene("fileName \"cube.obj\""));
  ASSERT_TRUE(root);
  auto* mesh = find<MeshFile>(root.get());
  const auto before = mesh->collider();
  ASSERT_TRUE(before);
  EXPECT_EQ(mesh->collider(), before) << "the collider is built once and kept";

  dir.file("tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  mesh->fileName = "tetra.obj";  // resolved in the scene's folder, as when read
  EXPECT_EQ(mesh->point.getNum(), 4);
  EXPECT_NE(mesh->collider(), before) << "a new mesh gets a new collider";

  CapturedErrors errors;
  mesh->fileName = "gone.obj";
  EXPECT_EQ(mesh->point.getNum(), 0);
  EXPECT_EQ(mesh->collider(), nullptr);
  EXPECT_NE(errors.all().find("fileName \"gone.obj\""), std::string::npos) << errors.all();
}

TEST_F(MeshFileTest, OutputFieldsAreNotWritten) {
  dir.file("cube.obj", cubeObj());
  SceneRoot root = readFile(scene("fileName \"cube.obj\""));
  ASSERT_TRUE(root);
  const std::string text = writeString(root.get());
  EXPECT_EQ(text.find("point ["), std::string::npos) << text;
  EXPECT_EQ(text.find("coordIndex ["), std::string::npos) << text;
  EXPECT_NE(text.find("fileName \"cube.obj\""), std::string::npos) << text;
}

TEST_F(MeshFileTest, DrawsThroughHiddenNodes) {
  dir.file("cube.obj", cubeObj());
  SceneRoot root = readFile(scene("fileName \"cube.obj\""));
  ASSERT_TRUE(root);
  const SbBox3f box = boundingBoxOf(root.get());
  EXPECT_NEAR((box.getMin() - SbVec3f(0, 0, 0)).length(), 0.0f, 1e-6f);
  EXPECT_NEAR((box.getMax() - SbVec3f(1, 1, 1)).length(), 0.0f, 1e-6f);
  EXPECT_EQ(triangleCountOf(root.get()), 12);

  SoRayPickAction pick(kActionViewport);
  const SoPickedPoint* picked = pickAlongMinusZ(pick, root.get(), SbVec3f(0.5f, 0.5f, 5.0f));
  ASSERT_NE(picked, nullptr);
  EXPECT_NEAR(picked->getPoint()[2], 1.0f, 1e-5f);

  // Searches find the MeshFile, never the face set inside it.
  EXPECT_NE(find<MeshFile>(root.get()), nullptr);
  EXPECT_EQ(find<SoIndexedFaceSet>(root.get()), nullptr);
}

TEST_F(MeshFileTest, CopiesKeepTheMeshWithoutReadingAgain) {
  dir.file("cube.obj", cubeObj());
  SceneRoot root = readFile(scene("fileName \"cube.obj\""));
  ASSERT_TRUE(root);
  std::filesystem::remove(dir.path() / "cube.obj");  // a copy that read the file would fail
  SceneRoot copy(static_cast<SoSeparator*>(root->copy()));
  copy->ref();
  auto* mesh = find<MeshFile>(copy.get());
  EXPECT_EQ(mesh->point.getNum(), 8);
  EXPECT_EQ(mesh->collisionSurface().triangles.size(), 12u);
  EXPECT_TRUE(mesh->point.isDefault()) << "outputs stay out of written files";
}

TEST_F(MeshFileTest, HumanWithoutEyesIsOneClosedSurface) {
  if (!humanAvailable()) GTEST_SKIP() << "assimp-testmodels' human.zae is not installed";
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\n"
      "MeshFile { fileName \"human.zae\" collisionExclude \"human-highpolyeyesMesh\" }\n");
  ASSERT_TRUE(root);
  auto* body = find<MeshFile>(root.get());
  // design.md: merged by position the body is 13,380 vertices and 26,756 triangles.
  EXPECT_EQ(body->collisionSurface().vertices.size(), 13380u);
  EXPECT_EQ(body->collisionSurface().triangles.size(), 26756u);
  EXPECT_GT(body->point.getNum(), 13380) << "the eyes are still drawn";
  // Closed: every edge between two triangles, walked oppositely by them, one piece; and
  // wound outward (its signed volume is positive, about a body's 0.06 m^3).
  const figment::TriangleMesh& surface = body->collisionSurface();
  EXPECT_TRUE(figment::checks::everyEdgeSharedByTwo(surface));
  EXPECT_TRUE(figment::checks::consistentlyOriented(surface));
  EXPECT_EQ(figment::checks::connectedComponents(surface), 1);
  EXPECT_GT(figment::checks::signedVolume(surface), 0.03);
  EXPECT_LT(figment::checks::signedVolume(surface), 0.12);
}

TEST_F(MeshFileTest, CropKeepsTheTrianglesCentredInTheBox) {
  // The unit cube from 0 to 1: each face is two triangles whose centroids lie a third
  // of the way in. A box over x > 0.5 keeps the +x face (centroids at x = 1) and the
  // halves of the four side faces whose centroids have x = 2/3.
  dir.file("cube.obj", cubeObj());
  SceneRoot root = readFile(scene("fileName \"cube.obj\" cropMin 0.5 -1 -1 cropMax 2 2 2"));
  ASSERT_TRUE(root);
  auto* mesh = find<MeshFile>(root.get(), "Mesh");
  EXPECT_EQ(mesh->coordIndex.getNum() / 4, 2 + 4);
  for (int i = 0; i < mesh->point.getNum(); ++i) EXPECT_GE(mesh->point[i][0], 0.0f);
  EXPECT_EQ(mesh->collisionSurface().triangles.size(), 6u) << "the collision surface is cropped alike";
}

TEST_F(MeshFileTest, BadCropBoxesAreReadErrors) {
  dir.file("cube.obj", cubeObj());
  {
    CapturedErrors errors;
    EXPECT_FALSE(readFile(scene("fileName \"cube.obj\" cropMin 0 0 0 cropMax 1 0 1")));
    EXPECT_NE(errors.all().find("cropMin = 0 0 0 must be below cropMax = 1 0 1"), std::string::npos) << errors.all();
  }
  {
    CapturedErrors errors;
    EXPECT_FALSE(readFile(scene("fileName \"cube.obj\" cropMin 5 5 5 cropMax 6 6 6")));
    EXPECT_NE(errors.all().find("no triangle"), std::string::npos) << errors.all();
  }
}
