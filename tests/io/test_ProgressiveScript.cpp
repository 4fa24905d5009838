// The reconstruction script: written and read back, it replays to the same garment; a
// script of another garment or a damaged one is one line naming the file (and line).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io/ProgressiveScript.h"
#include "sim/progressive/Decimation.h"
#include "support/TempDir.h"
#include "support/TestMeshes.h"

namespace test_ProgressiveScript {

using namespace figment;
using figment::test::TempDir;

namespace {
TriangleMesh sheet() {
  TriangleMesh s = meshes::grid(10, 8, 0.4, 0.3);
  for (Vec3& x : s.vertices) x.z() = float(0.3 * x.x() * x.x());  // as floats, as a scene holds them
  return s;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string errorOf(const std::string& path, const TriangleMesh& garment) {
  try {
    readProgressiveScript(path, garment);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}
}  // namespace

TEST(ProgressiveScript, ReadsBackEverySplitExactly) {
  TempDir dir;
  const TriangleMesh garment = sheet();
  const ProgressiveMesh written = decimate(garment, DecimationOptions{.targetFaces = 30});
  const std::string path = (dir.path() / "sheet.pm").string();
  writeProgressiveScript(written, path);
  const ProgressiveMesh read = readProgressiveScript(path, garment);
  ASSERT_EQ(read.levels(), written.levels());
  for (int k = 0; k < read.levels(); ++k) {
    const VertexSplit &a = read.splits[k], &b = written.splits[k];
    EXPECT_EQ(a.kept, b.kept);
    EXPECT_EQ(a.added, b.added);
    EXPECT_EQ(a.keptRest, b.keptRest);
    EXPECT_EQ(a.addedRest, b.addedRest);
    EXPECT_EQ(a.collapsedRest, b.collapsedRest);
    ASSERT_EQ(a.restored.size(), b.restored.size());
    for (size_t f = 0; f < a.restored.size(); ++f) {
      EXPECT_EQ(a.restored[f].face, b.restored[f].face);
      EXPECT_EQ(a.restored[f].corners, b.restored[f].corners);
    }
    EXPECT_EQ(a.repointed, b.repointed);
  }
  // Replayed, the read script gives back the garment.
  MeshLevel level(read);
  level.splitTo(read.levels());
  std::vector<int> fullIndex;
  const TriangleMesh back = level.restMesh(fullIndex);
  EXPECT_EQ(back.vertices, garment.vertices);
  EXPECT_EQ(back.triangles, garment.triangles);
}

TEST(ProgressiveScript, AnotherGarmentIsRefusedByItsHash) {
  TempDir dir;
  TriangleMesh garment = sheet();
  const std::string path = (dir.path() / "sheet.pm").string();
  writeProgressiveScript(decimate(garment, DecimationOptions{.targetFaces = 30}), path);
  garment.vertices[5].y() += 0.01f;  // the same counts, one vertex moved
  const std::string error = errorOf(path, garment);
  EXPECT_EQ(error.rfind(path + ":2: for another garment (hash ", 0), 0u) << error;
}

TEST(ProgressiveScript, ADamagedLineIsNamed) {
  TempDir dir;
  const TriangleMesh garment = sheet();
  const std::string good = (dir.path() / "sheet.pm").string();
  writeProgressiveScript(decimate(garment, DecimationOptions{.targetFaces = 30}), good);
  std::string text = readAll(good);
  const size_t fifth = text.find("\nsplit ", text.find("\nsplit ", text.find("\nsplit ") + 1) + 1);
  text[fifth + 7] = 'x';  // the third split's kept vertex is no number
  const std::string bad = dir.file("bad.pm", text);
  EXPECT_EQ(errorOf(bad, garment), bad + ":6: not a split");
  EXPECT_EQ(errorOf((dir.path() / "none.pm").string(), garment),
            (dir.path() / "none.pm").string() + ": cannot be read");
}

}  // namespace test_ProgressiveScript
