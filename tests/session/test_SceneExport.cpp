// The draped scene out as files: the default dress's drape as GLB passes the Khronos glTF
// validator with no error and reads back through assimp node for node, in metres, y up,
// in the scene's colour; OBJ the same; the body comes with it when asked; a drape fed
// to a plain IndexedFaceSet counts as a garment; transforms and clockwise faces are
// honoured; bad paths are one line and leave nothing.

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/engines/SoEngineOutput.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "headless/InitHeadless.h"
#include "io/MeshImport.h"
#include "session/SceneExport.h"
#include "session/SceneSession.h"
#include "support/TempDir.h"

using namespace figment::session;

namespace {

constexpr const char* kDress = FIGMENT_SOURCE_DIR "/scenes/dress.iv";

class SceneExportTest : public ::testing::Test {
 protected:
  // The default dress, draped once for every test that exports it (an export changes
  // nothing in the scene); none when the default body is not installed.
  static void SetUpTestSuite() {
    figment::initHeadless();
    if (figment::findModelFile("human.zae").empty()) return;
    dress_ = new SceneSession;
    ASSERT_TRUE(dress_->load(kDress)) << dress_->loadError();
    dress_->drape();
    ASSERT_EQ(dress_->firstError(), "");
  }
  static void TearDownTestSuite() {
    delete dress_;
    dress_ = nullptr;
  }
  void SetUp() override { figment::initHeadless(); }
  std::string path(const std::string& name) const { return (dir_.path() / name).string(); }

  static SceneSession* dress_;
  figment::test::TempDir dir_;
};

SceneSession* SceneExportTest::dress_ = nullptr;

// The first diffuse colour of the Material beside the node named `name` (in its Separator).
SbColor materialBeside(SoNode* scene, const char* name) {
  SoSearchAction search;
  search.setName(name);
  search.apply(scene);
  EXPECT_NE(search.getPath(), nullptr) << name;
  if (!search.getPath()) return SbColor(-1, -1, -1);
  auto* group = static_cast<SoSeparator*>(search.getPath()->getNodeFromTail(1));
  for (int i = 0; i < group->getNumChildren(); ++i)
    if (group->getChild(i)->isOfType(SoMaterial::getClassTypeId()))
      return static_cast<SoMaterial*>(group->getChild(i))->diffuseColor[0];
  ADD_FAILURE() << "no Material beside " << name;
  return SbColor(-1, -1, -1);
}

// The draped nodes: the point field of the Coordinate3 a ClothEngine feeds.
const SoMFVec3f& drapedPoints(SoNode* scene) {
  static const SoMFVec3f none;
  SoSearchAction search;
  search.setType(SoCoordinate3::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.apply(scene);
  for (int i = 0; i < search.getPaths().getLength(); ++i) {
    auto* coordinates = static_cast<SoCoordinate3*>(search.getPaths()[i]->getTail());
    SoEngineOutput* output = nullptr;
    if (coordinates->point.getConnectedEngine(output)) return coordinates->point;
  }
  ADD_FAILURE() << "no Coordinate3 fed by an engine";
  return none;
}

// What the dress's export must hold whatever the format: one mesh, named for its layer,
// one vertex per cloth node at the engine's draped position (metres, y up, the scene's
// frame), the Material's colour.
void expectTheDrape(const aiScene* read, SceneSession& session) {
  ASSERT_NE(read, nullptr);
  ASSERT_EQ(read->mNumMeshes, 1u);
  const aiMesh* mesh = read->mMeshes[0];
  EXPECT_STREQ(mesh->mName.C_Str(), "Dress");
  const SoMFVec3f& drape = drapedPoints(session.scene());
  ASSERT_EQ(mesh->mNumVertices, static_cast<unsigned>(drape.getNum())) << "one vertex per cloth node";
  SbBox3f box;
  for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
    const SbVec3f v(mesh->mVertices[i].x, mesh->mVertices[i].y, mesh->mVertices[i].z);
    EXPECT_LT((v - drape[i]).length(), 1e-6f) << "node " << i;  // float; 9 digits in OBJ
    box.extendBy(v);
  }
  // The dress hangs from the shoulders (1.3-1.5 m on a 1.66 m body) to above the knees.
  EXPECT_GT(box.getMax()[1], 1.3f);
  EXPECT_LT(box.getMax()[1], 1.5f);
  EXPECT_GT(box.getMin()[1], 0.3f);
  EXPECT_LT(box.getMax()[0] - box.getMin()[0], 0.7f) << "metres: about a body's width";
  aiColor3D colour;
  ASSERT_EQ(read->mMaterials[mesh->mMaterialIndex]->Get(AI_MATKEY_COLOR_DIFFUSE, colour), AI_SUCCESS);
  const SbColor expected = materialBeside(session.scene(), "Dress");
  EXPECT_NEAR(colour.r, expected[0], 1e-6);
  EXPECT_NEAR(colour.g, expected[1], 1e-6);
  EXPECT_NEAR(colour.b, expected[2], 1e-6);
}

}  // namespace

// The Khronos glTF validator (tools/gltf, pinned; scripts/setup.sh installs it) on the
// default dress's GLB: no error. Its figures are printed for the record.
TEST_F(SceneExportTest, TheDressAsGlbPassesTheKhronosValidator) {
  if (std::system("command -v node > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "node is not installed (scripts/setup.sh installs nodejs and the validator)";
  if (!dress_) GTEST_SKIP() << "assimp-testmodels' human.zae is not installed";
  SceneSession& session = *dress_;
  for (const bool body : {false, true}) {
    const std::string glb = path(body ? "dressed.glb" : "dress.glb");
    ASSERT_EQ(exportScene(session.scene(), {body}, glb), "");
    const std::string report = path("report.json");
    const std::string command = "node '" FIGMENT_SOURCE_DIR "/tools/gltf/validate.js' '" + glb + "' > '" + report +
                                "' 2> '" + path("validator-errors.txt") + "'";
    const int status = std::system(command.c_str());
    std::ifstream in(report);
    const nlohmann::json figures = nlohmann::json::parse(in, nullptr, false);
    ASSERT_FALSE(figures.is_discarded()) << "the validator gave no report (status " << status
                                         << "; run scripts/setup.sh to install it): see "
                                         << path("validator-errors.txt");
    std::cout << glb.substr(glb.rfind('/') + 1) << ": " << figures.dump() << "\n";
    EXPECT_EQ(figures.at("errors"), 0) << figures.dump();
    EXPECT_EQ(status, 0);
  }
}

TEST_F(SceneExportTest, TheDressAsGlbReadsBackNodeForNode) {
  if (!dress_) GTEST_SKIP() << "assimp-testmodels' human.zae is not installed";
  SceneSession& session = *dress_;
  const std::string glb = path("dress.glb");
  std::vector<std::string> written;
  ASSERT_EQ(exportScene(session.scene(), {}, glb, &written), "");
  EXPECT_EQ(written, std::vector<std::string>{glb});
  Assimp::Importer importer;
  const aiScene* read = importer.ReadFile(glb, 0);
  expectTheDrape(read, session);
  if (!read) return;
  int twoSided = 0;
  read->mMaterials[read->mMeshes[0]->mMaterialIndex]->Get(AI_MATKEY_TWOSIDED, twoSided);
  EXPECT_EQ(twoSided, 1) << "cloth is seen from both sides";
}

// OBJ lists a vertex per face corner: joined again, one per node.
TEST_F(SceneExportTest, TheDressAsObjReadsBackNodeForNode) {
  if (!dress_) GTEST_SKIP() << "assimp-testmodels' human.zae is not installed";
  SceneSession& session = *dress_;
  const std::string obj = path("dress.obj");
  std::vector<std::string> written;
  ASSERT_EQ(exportScene(session.scene(), {}, obj, &written), "");
  EXPECT_EQ(written, (std::vector<std::string>{obj, path("dress.mtl")}));
  Assimp::Importer importer;
  expectTheDrape(importer.ReadFile(obj, aiProcess_JoinIdenticalVertices), session);
}

// With the body: the dress first, then each skin part drawn, named for its DEF, in skin colour.
TEST_F(SceneExportTest, TheBodyComesWhenAskedAsGlbBytesInMemory) {
  if (!dress_) GTEST_SKIP() << "assimp-testmodels' human.zae is not installed";
  SceneSession& session = *dress_;
  std::string error = "unset";
  const std::vector<unsigned char> bytes = exportGlb(session.scene(), {true}, error);
  ASSERT_EQ(error, "");
  Assimp::Importer importer;
  const aiScene* read = importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, "glb");
  ASSERT_NE(read, nullptr);
  std::vector<std::string> names;
  SbBox3f body;
  for (unsigned m = 0; m < read->mNumMeshes; ++m) {
    names.push_back(read->mMeshes[m]->mName.C_Str());
    for (unsigned i = 0; m > 0 && i < read->mMeshes[m]->mNumVertices; ++i)
      body.extendBy(SbVec3f(read->mMeshes[m]->mVertices[i].x, read->mMeshes[m]->mVertices[i].y,
                            read->mMeshes[m]->mVertices[i].z));
  }
  EXPECT_EQ(names, (std::vector<std::string>{"Dress", "Torso", "LeftArm", "RightArm"}));
  // The default body stands on y = 0, about 1.66 m tall, in metres.
  EXPECT_NEAR(body.getMin()[1], 0.0f, 0.02f);
  EXPECT_GT(body.getMax()[1], 1.5f);
  EXPECT_LT(body.getMax()[1], 1.9f);
  aiColor3D skin;
  ASSERT_EQ(read->mMaterials[read->mMeshes[1]->mMaterialIndex]->Get(AI_MATKEY_COLOR_DIFFUSE, skin), AI_SUCCESS);
  EXPECT_NEAR(skin.r, materialBeside(session.scene(), "Torso")[0], 1e-6);
  EXPECT_EQ(exportGlb(session.scene(), {false}, error).size() < bytes.size(), true) << "the dress alone is smaller";
}

// A 1 m square drawn 100 units wide under a 0.01 scale: exported in the world frame. Its
// faces are clockwise from the front (ShapeHints), so the triangles are turned to face
// the front counter-clockwise, and the normals follow: towards -z. The unused fifth point
// is left out.
TEST_F(SceneExportTest, GarmentsAreInTheWorldFrameFacingTheirFront) {
  const std::string scene = dir_.file("square.iv",
                                      "#Inventor V2.1 ascii\nSeparator {\n"
                                      "  Transform { scaleFactor 0.01 0.01 0.01 }\n"
                                      "  ShapeHints { vertexOrdering CLOCKWISE shapeType SOLID }\n"
                                      "  Material { diffuseColor 0.2 0.4 0.6 transparency 0.25 }\n"
                                      "  Coordinate3 { point [ 0 0 0, 100 0 0, 100 100 0, 0 100 0, 7 7 7 ] }\n"
                                      "  DEF Square ClothingLayer { coordIndex [ 0 1 2 3 -1 ] }\n"
                                      "}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(scene)) << session.loadError();
  const std::vector<figment::ColouredMesh> meshes = sceneMeshes(session.scene(), {});
  ASSERT_EQ(meshes.size(), 1u);
  const figment::ColouredMesh& square = meshes[0];
  EXPECT_EQ(square.name, "Square");
  ASSERT_EQ(square.mesh.vertices.size(), 4u);
  EXPECT_LT((square.mesh.vertices[2] - figment::Vec3(1, 1, 0)).norm(), 1e-6);
  EXPECT_EQ(square.mesh.triangles.size(), 2u);
  for (const figment::Vec3& normal : square.normals) EXPECT_LT((normal - figment::Vec3(0, 0, -1)).norm(), 1e-6);
  EXPECT_FLOAT_EQ(square.colour[1], 0.4f);
  EXPECT_FLOAT_EQ(square.opacity, 0.75f);
  EXPECT_FALSE(square.twoSided) << "ShapeHints says SOLID";
}

// A layer drawn with a display mesh exports the simulation's faces: the drape itself, which
// another program can subdivide as it likes (ClothingLayer.displaySubdivision).
TEST_F(SceneExportTest, ALayersDisplayMeshIsNotExported) {
  const std::string scene = dir_.file("smooth.iv",
                                      "#Inventor V2.1 ascii\nSeparator {\n"
                                      "  Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0.2, 0 1 0 ] }\n"
                                      "  DEF Square ClothingLayer { coordIndex [ 0 1 2 3 -1 ] displaySubdivision 2 }\n"
                                      "}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(scene)) << session.loadError();
  const std::vector<figment::ColouredMesh> meshes = sceneMeshes(session.scene(), {});
  ASSERT_EQ(meshes.size(), 1u);
  EXPECT_EQ(meshes[0].mesh.vertices.size(), 4u);
  EXPECT_EQ(meshes[0].mesh.triangles.size(), 2u);
}

// A drape drawn by a plain IndexedFaceSet is a garment; an IndexedFaceSet of fixed points
// and a Cube are not, and come only with the body (the Cube's 6 faces: 24 corners, shared
// only where position and normal agree). The drape's edges drawn as lines are neither.
TEST_F(SceneExportTest, AnyFaceSetADrapeFeedsIsAGarmentTheRestComesWithTheBody) {
  const std::string scene =
      dir_.file("cloth.iv",
                "#Inventor V2.1 ascii\nSeparator {\n"
                "  Separator {\n"
                "    Coordinate3 { point = DEF Drape ClothEngine {\n"
                "      restPoints [ -0.5 1 -0.5, 0.5 1 -0.5, 0.5 1 0.5, -0.5 1 0.5 ]\n"
                "      coordIndex [ 0 3 2 1 -1 ]  maxTime 0.01 } . positions }\n"
                "    DEF Cloth IndexedFaceSet { coordIndex [ 0 3 2 1 -1 ] }\n"
                "    Separator { DrawStyle { style LINES }  DEF Edges IndexedFaceSet { coordIndex [ 0 3 2 1 -1 ] } }\n"
                "  }\n"
                "  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n"
                "  DEF Fixed IndexedFaceSet { coordIndex [ 0 1 2 -1 ] }\n"
                "  DEF Box Cube { }\n"
                "}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(scene)) << session.loadError();
  session.drape();
  ASSERT_EQ(session.firstError(), "");
  std::vector<figment::ColouredMesh> meshes = sceneMeshes(session.scene(), {});
  ASSERT_EQ(meshes.size(), 1u);
  EXPECT_EQ(meshes[0].name, "Cloth");
  EXPECT_EQ(meshes[0].mesh.vertices.size(), 4u);
  EXPECT_LT(meshes[0].mesh.vertices[0].y(), 1.0) << "the drape, not the rest shape";

  meshes = sceneMeshes(session.scene(), {true});
  ASSERT_EQ(meshes.size(), 3u);
  EXPECT_EQ(meshes[1].name, "Fixed");
  EXPECT_EQ(meshes[1].mesh.vertices.size(), 3u);
  EXPECT_EQ(meshes[2].name, "Box");
  EXPECT_EQ(meshes[2].mesh.triangles.size(), 12u);
  EXPECT_EQ(meshes[2].mesh.vertices.size(), 24u);
}

TEST_F(SceneExportTest, BadPathsAndEmptyScenesAreOneLineAndLeaveNothing) {
  const std::string scene = dir_.file("cube.iv", "#Inventor V2.1 ascii\nSeparator { Cube { } }\n");
  const std::string outputs = path("out");
  SceneSession session;
  ASSERT_TRUE(session.load(scene)) << session.loadError();
  EXPECT_EQ(exportScene(session.scene(), {}, outputs + "/a.glb"), "nothing to export: the scene draws no garment");
  EXPECT_EQ(exportScene(session.scene(), {true}, outputs + "/a.fbx"), "unknown extension (.glb, .gltf or .obj)");
  const std::string file = dir_.file("a-file", "x");
  const std::string error = exportScene(session.scene(), {true}, file + "/a.gltf");
  EXPECT_EQ(error.rfind("cannot make the folder " + file, 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(outputs));
  std::string glbError;
  EXPECT_TRUE(exportGlb(session.scene(), {}, glbError).empty());
  EXPECT_EQ(glbError, "nothing to export: the scene draws no garment");
}
