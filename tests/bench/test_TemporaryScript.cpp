// A progressive mesh made on the fly: its file reads back as the garment's script with the
// levels it reports, coarsened to about the share asked, and goes with the object.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bench/TemporaryScript.h"
#include "io/ProgressiveScript.h"
#include "sim/progressive/ProgressiveMesh.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

TEST(TemporaryScript, WritesAScriptThatReadsBackAndGoesWithTheObject) {
  const TriangleMesh garment = bench::asSceneHoldsIt(meshes::grid(8, 8, 0.4, 0.4));
  std::string path;
  {
    const bench::TemporaryScript script(garment, 0.25);
    path = script.path();
    ASSERT_TRUE(std::filesystem::exists(path));
    const ProgressiveMesh read = readProgressiveScript(path, garment);
    EXPECT_EQ(read.levels(), script.levels());
    EXPECT_GT(script.levels(), 0);
    // About a quarter of the 128 sections; decimation stops at the first level at or below it.
    EXPECT_LE(script.coarseSections(), 32);
    EXPECT_EQ(MeshLevel(read).activeFaces(), script.coarseSections());
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(TemporaryScript, AsSceneHoldsItRoundsToFloats) {
  TriangleMesh mesh;
  mesh.vertices = {{0.1, 1.0 / 3.0, 2.0}};
  const TriangleMesh held = bench::asSceneHoldsIt(mesh);
  EXPECT_EQ(held.vertices[0].y(), double(float(1.0 / 3.0)));
  EXPECT_NE(held.vertices[0].y(), 1.0 / 3.0);
  EXPECT_EQ(held.vertices[0].z(), 2.0);
}

}  // namespace
