// The importer brings files into the scene frame (metres, y up), leaves out excluded meshes
// and welds seams; findModelFile walks the model search path in its documented order.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "io/MeshImport.h"
#include "support/IoTestSupport.h"
#include "support/MeshChecks.h"

using namespace figment;
using figment::test::ScopedEnvironment;
using figment::test::TempDir;

namespace {

// A tetrahedron pointing along +z (tip at z = 2), counter-clockwise from outside, in OBJ.
const char* kTetrahedronZUp =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 2\n"
    "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";

// Two triangles in two groups and no materials: one material for both.
const char* kTwoGroups =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 0 0\nv 6 0 0\nv 5 1 0\n"
    "g first\nf 1 2 3\ng second\nf 4 5 6\n";

bool hasVertex(const TriangleMesh& mesh, const Vec3& p) {
  for (const Vec3& v : mesh.vertices)
    if ((v - p).norm() < 1e-9) return true;
  return false;
}

ImportOptions withUp(UpAxis up) {
  ImportOptions options;
  options.upAxis = up;
  return options;
}

class DefaultBody : public ::testing::Test {
 protected:
  void SetUp() override {
    path = test::defaultBodyPath();
    if (path.empty()) GTEST_SKIP() << "human.zae (assimp-testmodels) is not installed";
  }
  ImportedMesh importWithout(const std::string& excluded, bool merge = true) {
    ImportOptions options;
    options.exclude = {excluded};
    options.mergeByPosition = merge;
    return importMesh(path, options);
  }
  std::string path;
};

// importMesh refuses the file at `path` with exactly "<path>: <error>".
void expectRefused(const std::string& path, const std::string& error) {
  try {
    importMesh(path);
    ADD_FAILURE() << path << " was read";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), path + ": " + error);
  }
}

}  // namespace

// human.zae holds "human-baseMesh" and "human-highpolyeyesMesh"; "eyes" (part of the name)
// leaves the eyes out. Welded along its texture seams the body is one closed surface.
TEST_F(DefaultBody, WithoutEyesIsOneClosedSurface) {
  const ImportedMesh body = importWithout("eyes");
  EXPECT_EQ(body.meshNames, std::vector<std::string>{"human-baseMesh"});
  EXPECT_EQ(body.mesh.vertices.size(), 13380u);
  EXPECT_EQ(body.mesh.triangles.size(), 26756u);
  EXPECT_TRUE(checks::everyEdgeSharedByTwo(body.mesh));
  EXPECT_TRUE(checks::consistentlyOriented(body.mesh));
  EXPECT_EQ(checks::connectedComponents(body.mesh), 1);
}

// Wound outward: a positive enclosed volume, and a plausible one for a 1.66 m woman (0.055 m^3).
TEST_F(DefaultBody, WoundOutwardWithABodysVolume) {
  const double volume = checks::signedVolume(importWithout("eyes").mesh);
  EXPECT_GT(volume, 0.05);
  EXPECT_LT(volume, 0.08);
}

TEST_F(DefaultBody, StandsOnTheGround166Tall) {
  const Bounds bounds = boundsOf(importWithout("eyes").mesh.vertices);
  EXPECT_NEAR(bounds.min.y(), 0.0, 0.01);
  EXPECT_NEAR(bounds.size().y(), 1.66, 0.01);
  EXPECT_NEAR(bounds.min.x() + bounds.max.x(), 0.0, 1e-6);  // centred, symmetric
}

TEST_F(DefaultBody, ExactNameExcludesToo) {
  const ImportedMesh body = importWithout("human-highpolyeyesMesh");
  EXPECT_EQ(body.mesh.triangles.size(), 26756u);
  const ImportedMesh all = importMesh(path);
  EXPECT_EQ(all.meshNames, (std::vector<std::string>{"human-baseMesh", "human-highpolyeyesMesh"}));
  EXPECT_GT(all.mesh.triangles.size(), 26756u);
}

TEST_F(DefaultBody, UnweldedKeepsTheSeams) {
  const ImportedMesh body = importWithout("eyes", false);
  EXPECT_EQ(body.mesh.triangles.size(), 26756u);
  EXPECT_GT(body.mesh.vertices.size(), 13380u);
  EXPECT_FALSE(checks::everyEdgeSharedByTwo(body.mesh));
}

TEST_F(DefaultBody, MetresPerUnitScales) {
  ImportOptions options;
  options.exclude = {"eyes"};
  const Bounds metres = boundsOf(importMesh(path, options).mesh.vertices);
  options.metresPerUnit = 0.01;
  const Bounds scaled = boundsOf(importMesh(path, options).mesh.vertices);
  EXPECT_TRUE(scaled.min.isApprox(0.01 * metres.min, 1e-6));
  EXPECT_TRUE(scaled.max.isApprox(0.01 * metres.max, 1e-6));
}

// Z up, as documented: (x, y, z) -> (x, z, -y).
TEST(MeshImport, ZUpTurnsAsDocumented) {
  const TempDir dir;
  const ImportedMesh imported = importMesh(dir.file("tetra.obj", kTetrahedronZUp), withUp(UpAxis::Z));
  ASSERT_EQ(imported.mesh.vertices.size(), 4u);
  EXPECT_TRUE(hasVertex(imported.mesh, Vec3(1, 0, 0)));
  EXPECT_TRUE(hasVertex(imported.mesh, Vec3(0, 0, -1)));
  EXPECT_TRUE(hasVertex(imported.mesh, Vec3(0, 2, 0)));
}

// Every up axis turns onto +y by a proper rotation: the tip goes up, lengths and the winding
// (a positive volume) survive.
class UpAxes : public ::testing::TestWithParam<UpAxis> {};

TEST_P(UpAxes, TurnOntoYByARotation) {
  const TempDir dir;
  // The tetrahedron's tip along the file's up axis: swap coordinates by a rotation that takes z
  // there (a cyclic permutation keeps the handedness; a sign flip is paired with another).
  const UpAxis up = GetParam();
  auto fileFrame = [up](const Vec3& zUp) -> Vec3 {
    switch (up) {
      case UpAxis::X:
        return {zUp.z(), zUp.x(), zUp.y()};
      case UpAxis::Y:
        return {zUp.y(), zUp.z(), zUp.x()};
      case UpAxis::Z:
        return zUp;
      case UpAxis::NegX:
        return {-zUp.z(), -zUp.x(), zUp.y()};
      case UpAxis::NegY:
        return {zUp.y(), -zUp.z(), -zUp.x()};
      case UpAxis::NegZ:
        return {zUp.x(), -zUp.y(), -zUp.z()};
    }
    return zUp;
  };
  const Vec3 corners[4] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 2)};
  std::string obj;
  for (const Vec3& c : corners) {
    const Vec3 p = fileFrame(c);
    obj += "v " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
  }
  obj += "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
  const ImportedMesh imported = importMesh(dir.file("tetra.obj", obj), withUp(up));
  ASSERT_EQ(imported.mesh.vertices.size(), 4u);
  EXPECT_TRUE(hasVertex(imported.mesh, Vec3(0, 2, 0)));  // the tip, up
  EXPECT_TRUE(hasVertex(imported.mesh, Vec3(0, 0, 0)));
  EXPECT_NEAR(checks::signedVolume(imported.mesh), 2.0 / 6.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(MeshImport, UpAxes,
                         ::testing::Values(UpAxis::X, UpAxis::Y, UpAxis::Z, UpAxis::NegX, UpAxis::NegY, UpAxis::NegZ));

// assimp joins meshes that share a material when it pre-transforms vertices; the importer
// keeps them apart, so excluding one leaves the other.
TEST(MeshImport, ExcludesOneOfTwoMeshesSharingAMaterial) {
  const TempDir dir;
  const std::string path = dir.file("two.obj", kTwoGroups);
  ImportOptions options;
  options.exclude = {"second"};
  const ImportedMesh first = importMesh(path, options);
  EXPECT_EQ(first.meshNames, std::vector<std::string>{"first"});
  ASSERT_EQ(first.mesh.triangles.size(), 1u);
  EXPECT_LT(boundsOf(first.mesh.vertices).max.x(), 2.0);
  EXPECT_EQ(importMesh(path).mesh.triangles.size(), 2u);
}

TEST(MeshImport, MissingFileNamesThePath) {
  const std::string path = "/nonexistent/figment/body.obj";
  try {
    importMesh(path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()).rfind(path + ": ", 0), 0u) << error.what();
  }
}

TEST(MeshImport, FileWithoutTrianglesNamesThePath) {
  const TempDir dir;
  const std::string path = dir.file("empty.obj", "# nothing\nv 0 0 0\n");
  try {
    importMesh(path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()).rfind(path + ": ", 0), 0u) << error.what();
  }
}

TEST(MeshImport, AllExcludedIsAnError) {
  const TempDir dir;
  ImportOptions options;
  options.exclude = {"first", "second"};
  EXPECT_THROW(importMesh(dir.file("two.obj", kTwoGroups), options), std::runtime_error);
}

// Order: as given, then $FIGMENT_MODEL_PATH (each folder in turn), then the scene's folder,
// then Debian's assimp-testmodels.
TEST(FindModelFile, SearchesInOrder) {
  const TempDir dir;
  const std::string inFirst = dir.file("first/shared.obj", "");
  const std::string inSecond = dir.file("second/only-second.obj", "");
  const std::string inSecondToo = dir.file("second/shared.obj", "");
  const std::string inScene = dir.file("scene/only-scene.obj", "");
  const std::string sceneCopy = dir.file("scene/shared.obj", "");
  const ScopedEnvironment path("FIGMENT_MODEL_PATH",
                               (dir.path() / "first").string() + "::" + (dir.path() / "second").string());
  const std::string scene = (dir.path() / "scene").string();
  EXPECT_EQ(findModelFile("shared.obj", scene), inFirst);
  EXPECT_EQ(findModelFile("only-second.obj", scene), inSecond);
  EXPECT_EQ(findModelFile("only-scene.obj", scene), inScene);
  EXPECT_EQ(findModelFile("only-scene.obj"), "");
  EXPECT_EQ(findModelFile("missing.obj", scene), "");
  EXPECT_EQ(findModelFile(inSecondToo, scene), inSecondToo);                          // absolute and there
  EXPECT_EQ(findModelFile((dir.path() / "nowhere/shared.obj").string(), scene), "");  // absolute, missing
  EXPECT_EQ(findModelFile("", scene), "");
}

TEST(FindModelFile, RelativeToTheWorkingDirectoryFirst) {
  const TempDir dir;
  const std::string local = dir.file("here/body.obj", "");
  const std::string elsewhere = dir.file("path/here/body.obj", "");
  const ScopedEnvironment path("FIGMENT_MODEL_PATH", (dir.path() / "path").string());
  const std::filesystem::path previous = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  const std::string found = findModelFile("here/body.obj");
  std::filesystem::current_path(previous);
  EXPECT_EQ(found, "here/body.obj");
}

TEST(FindModelFile, FallsBackToAssimpTestModels) {
  const ScopedEnvironment noPath("FIGMENT_MODEL_PATH", std::nullopt);
  if (!std::filesystem::exists("/usr/share/assimp/models/Collada/human.zae"))
    GTEST_SKIP() << "assimp-testmodels is not installed";
  EXPECT_EQ(findModelFile("human.zae"), "/usr/share/assimp/models/Collada/human.zae");
  EXPECT_EQ(findModelFile("Collada/human.zae"), "/usr/share/assimp/models/Collada/human.zae");
}

// assimp 5.2's PLY reader loops forever on a header without end_header, or with a control
// byte in a line (found by tests/fuzz/fuzz_mesh; figment-view hung on a MeshFile naming such a
// file). importMesh refuses them first (io/AssimpHazards.h), by name or by the file's first word.
TEST(MeshImport, AMalformedPlyHeaderIsAnErrorNotAHang) {
  TempDir dir;
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n";
  const std::string rest =
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::string tail = " (assimp 5.2 may never finish reading it)";
  const struct {
    const char* name;
    std::string text, error;
  } cases[] = {
      {"open.ply", header, "PLY header without end_header in its first 64 KiB"},
      {"open.obj", header, "PLY header without end_header in its first 64 KiB"},
      {"control.ply", "ply\nformat ascii 1.0\nelement vertex 3\x06" + std::string("property float x\n") + rest,
       "PLY header line 3 holds a control or non-ASCII byte"},
      {"word.ply", "ply\nformat ascii 1.0\nelemen1 vertex 3\n" + rest,
       "PLY header line 3 does not begin with a PLY keyword"},
  };
  for (const auto& c : cases) expectRefused(dir.file(c.name, c.text), c.error + tail);
  const ImportedMesh good = importMesh(dir.file("good.ply", header + rest));
  EXPECT_EQ(good.mesh.triangles.size(), 1u);
}

// assimp 5.2's PLY reader reads every element its header counts, seeking past the end of the
// file once for each it lacks: "element face 6666...60" (48 digits) in a 332-byte file ran for
// hours, a million faces took 4 s (found by tests/fuzz/fuzz_mesh). A count must be a whole
// number, and all of them together no more than the file's bytes (an element takes at least one).
TEST(MeshImport, APlyCountingMoreElementsThanItsBytesHoldIsAnErrorNotAHang) {
  TempDir dir;
  const auto ply = [](const std::string& faces) {
    return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "element face " +
           faces +
           "\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  };
  const std::string digits48 = std::string(47, '6') + "0";
  const std::string tail = " (assimp 5.2 may never finish reading it)";
  const struct {
    const char* name;
    std::string faces, error;
  } cases[] = {
      {"digits.ply", digits48,
       "PLY header line 7: element face count \"66666666666666666666...\" is not a whole number"},
      {"billions.ply", "4000000000",
       "PLY header line 7: element face count \"4000000000\" makes more elements than the file's 189 bytes hold"},
      {"million.ply", "1000000",
       "PLY header line 7: element face count \"1000000\" makes more elements than the file's 186 bytes hold"},
      {"letters.ply", "1at", "PLY header line 7: element face count \"1at\" is not a whole number"},
      {"none.ply", "", "PLY header line 7: element face count \"\" is not a whole number"},
  };
  for (const auto& c : cases) expectRefused(dir.file(c.name, ply(c.faces)), c.error + tail);
  EXPECT_EQ(importMesh(dir.file("one.ply", ply("1"))).mesh.triangles.size(), 1u);
}

// assimp 5.2's PLY reader flagged a mesh as holding polygons when its face list held none of
// more than three corners, and its Triangulate step then aborted the program (ai_assert
// "numOut != pMesh->mNumFaces"; found by tests/fuzz/fuzz_mesh). importMesh sets the flags from
// the faces before post-processing (correctPrimitiveTypes): the file now reads or is refused.
TEST(MeshImport, APlyWhoseFacesDisagreeWithItsHeaderDoesNotAbort) {
  TempDir dir;
  const std::string path = dir.file("short.ply",
                                    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                                    "property float y1property float z\nelement face 3\n"
                                    "property list uchar int vertex_indices\nend_header\n"
                                    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1er\n0 0 0\n1 3\n");
  try {
    const ImportedMesh imported = importMesh(path);
    for (const auto& t : imported.mesh.triangles)
      for (const int v : t) EXPECT_LT(v, static_cast<int>(imported.mesh.vertices.size()));
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
  }
}

// assimp 5.2's OFF reader trusts the file's counts and indices and wrote out of bounds on a
// face naming more corners than its line holds (SEGV; found by tests/fuzz/fuzz_mesh).
// importMesh checks OFF text first (io/AssimpHazards.h); a sound one still reads.
TEST(MeshImport, AnOffFileThatDisagreesWithItsCountsIsAnErrorNotACrash) {
  TempDir dir;
  const std::string vertices = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const ImportedMesh tetrahedron = importMesh(dir.file("good.off", vertices + "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"));
  EXPECT_EQ(tetrahedron.mesh.triangles.size(), 4u);
  const struct {
    const char* name;
    std::string text, error;
  } cases[] = {
      {"corners.off", vertices + "6 0 2 3\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
       "OFF file line 7: not a face of 1 to 9 corners and their indices"},
      {"index.off", vertices + "3 0 2 4\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
       "OFF file line 7: a face index that is not a vertex"},
      {"short.off", vertices + "3 0 2 1\n", "OFF file line 7: fewer faces than the 4 counted"},
  };
  for (const auto& c : cases) expectRefused(dir.file(c.name, c.text), c.error + " (assimp 5.2 may crash on it)");
}
