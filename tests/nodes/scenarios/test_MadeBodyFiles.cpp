// figment-body writes the made body as .obj, .glb and .iv (issue 30: `-o body.obj|.glb|.iv`),
// and each reads back whole: the OBJ and the glTF through assimp (io/MeshImport.h), the .iv
// through Coin, each with the body's vertices and triangles and its stature as the tool
// printed it. A name with another extension is refused in one line, with nothing written.
// Skipped when MakeHuman's data is absent (scripts/setup.sh fetches it).
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/MakeHumanFiles.h"
#include "io/MeshImport.h"
#include "support/ProgramRun.h"
#include "support/SceneTestSupport.h"

using namespace figment;
using figment::test::quote;

namespace {

const char* const kTypedSet = "--sex male --stature 1.77 --bust-girth 1.0 --waist-girth 0.88 --hip-girth 1.04";

struct MadeFile {
  test::ProgramResult run;
  double stature = 0;  // m, as printed
};

MadeFile makeBody(const test::TempDir& dir, const std::string& name) {
  MadeFile made;
  made.run = test::runProgram(FIGMENT_BINARY_DIR "/bin/figment-body",
                              std::string(kTypedSet) + " -o " + quote((dir.path() / name).string()), dir.path(),
                              dir.path() / "cache");
  const size_t at = made.run.out.find("\"stature\": ");
  if (at != std::string::npos) made.stature = std::strtod(made.run.out.c_str() + at + 11, nullptr);
  return made;
}

double heightOf(const std::vector<Vec3>& points) {
  const Bounds box = boundsOf(points);
  return box.max.y() - box.min.y();
}

}  // namespace

TEST(MadeBodyFiles, ObjGlbAndIvReadBackWithTheSameBody) {
  if (findMakeHumanData().empty()) GTEST_SKIP() << "MakeHuman's data not found (scripts/setup.sh fetches it)";
  const test::TempDir dir;
  const MadeFile obj = makeBody(dir, "body.obj"), glb = makeBody(dir, "body.glb"), iv = makeBody(dir, "body.iv");
  for (const MadeFile* made : {&obj, &glb, &iv}) ASSERT_EQ(made->run.status, 0) << made->run.err;
  EXPECT_NEAR(obj.stature, 1.77, 0.005);  // the typed stature, met within 5 mm

  // The OBJ as every tool reads a body; the glTF through the same importer.
  ImportOptions asWritten;
  asWritten.mergeByPosition = false;
  const TriangleMesh fromObj = importMesh((dir.path() / "body.obj").string(), asWritten).mesh;
  const TriangleMesh fromGlb = importMesh((dir.path() / "body.glb").string(), asWritten).mesh;
  ASSERT_GT(fromObj.triangles.size(), 20000u);  // the skin: 26,756 triangles
  EXPECT_EQ(fromGlb.vertices.size(), fromObj.vertices.size());
  EXPECT_EQ(fromGlb.triangles.size(), fromObj.triangles.size());
  // Feet on the floor: the stature is the height of the vertices (9 digits: 1e-6 m).
  EXPECT_NEAR(heightOf(fromObj.vertices), obj.stature, 1e-5);
  EXPECT_NEAR(heightOf(fromGlb.vertices), obj.stature, 1e-5);  // glTF's floats: 1e-7 relative

  // The .iv through Coin: one Coordinate3 and one IndexedFaceSet of triangles.
  test::initCoin();
  const test::SceneRoot root = test::readFile((dir.path() / "body.iv").string());
  ASSERT_NE(root, nullptr);
  const auto* coordinates = test::find<SoCoordinate3>(root.get());
  const auto* faces = test::find<SoIndexedFaceSet>(root.get());
  ASSERT_NE(coordinates, nullptr);
  ASSERT_NE(faces, nullptr);
  std::vector<Vec3> points;
  for (int i = 0; i < coordinates->point.getNum(); ++i)
    points.emplace_back(coordinates->point[i][0], coordinates->point[i][1], coordinates->point[i][2]);
  EXPECT_EQ(points.size(), fromObj.vertices.size());
  EXPECT_EQ(faces->coordIndex.getNum(), 4 * static_cast<int>(fromObj.triangles.size()));  // a, b, c, -1
  EXPECT_NEAR(heightOf(points), obj.stature, 1e-5);                                       // Coin's floats
}

TEST(MadeBodyFiles, AnotherExtensionIsRefusedInOneLine) {
  if (findMakeHumanData().empty()) GTEST_SKIP() << "MakeHuman's data not found (scripts/setup.sh fetches it)";
  const test::TempDir dir;
  const MadeFile stl = makeBody(dir, "body.stl");
  EXPECT_EQ(stl.run.status, 1);
  EXPECT_NE(stl.run.err.find("body.stl: only .obj, .glb, .gltf and .iv are written"), std::string::npos) << stl.run.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "body.stl"));
}
