// figment-view --export as a user meets it: the drape alone (no -o needed) or with
// images; a bad extension, a path that cannot be written or a failure after the export
// is one line naming the option and value, a non-zero exit, and no file left behind.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/ProgramRun.h"
#include "support/TempDir.h"

namespace fs = std::filesystem;

namespace {

using figment::test::quote;
using ProcessResult = figment::test::ProgramResult;

// A square of cloth, weightless and so at rest once its rest window has passed (a clean
// drape: an error's line is the only one), drawn by a ClothingLayer.
constexpr const char* kCloth =
    "#Inventor V2.1 ascii\nSeparator {\n"
    "  Material { diffuseColor 0.1 0.3 0.8 }\n"
    "  Coordinate3 { point = DEF Drape ClothEngine {\n"
    "    restPoints [ -0.5 1 -0.5, 0.5 1 -0.5, 0.5 1 0.5, -0.5 1 0.5 ]\n"
    "    coordIndex [ 0 3 2 1 -1 ]  integrator HEUN  maxTime 0.01  gravity 0 0 0  restWindow 0.005 } . positions }\n"
    "  DEF Layer ClothingLayer { coordIndex [ 0 3 2 1 -1 ] }\n"
    "}\n";

class FigmentViewExport : public ::testing::Test {
 protected:
  void SetUp() override { scene_ = dir_.file("cloth.iv", kCloth); }
  std::string path(const std::string& name) const { return (dir_.path() / name).string(); }
  ProcessResult run(const std::string& arguments) const {
    return figment::test::runProgram(FIGMENT_VIEW_EXECUTABLE, quote(scene_) + " " + arguments, dir_.path(),
                                     path("cache"));
  }
  // The files the run left in `folder` (the test's own folder: besides the scene, the
  // cache, stdout.txt and stderr.txt).
  std::vector<std::string> outputs(const std::string& folder = "") const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder.empty() ? dir_.path() : fs::path(folder))) {
      const std::string name = entry.path().filename().string();
      if (name != "cloth.iv" && name != "cache" && name != "stdout.txt" && name != "stderr.txt") names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
  }
  std::string scene_;
  figment::test::TempDir dir_;
};

// One line, ending in a newline, beginning as given.
void expectOneLine(const std::string& err, const std::string& start) {
  EXPECT_EQ(err.rfind(start, 0), 0u) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

}  // namespace

TEST_F(FigmentViewExport, WritesTheDrapeAloneOrBesideTheImages) {
  ProcessResult result = run("--export " + quote(path("out/cloth.obj")));
  EXPECT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(outputs(path("out")), (std::vector<std::string>{"cloth.mtl", "cloth.obj"}));
  result = run("-o " + quote(path("cloth.png")) + " --export " + quote(path("cloth.glb")) + " --export-body");
  EXPECT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(outputs(), (std::vector<std::string>{"cloth.glb", "cloth.png", "out"}));
}

TEST_F(FigmentViewExport, AnUnknownExtensionIsRefusedBeforeAnyDrape) {
  const ProcessResult result = run("-o " + quote(path("cloth.png")) + " --export " + quote(path("cloth.fbx")));
  EXPECT_EQ(result.status, 2);
  expectOneLine(result.err,
                "figment-view: --export " + path("cloth.fbx") + ": unknown extension (.glb, .gltf or .obj)");
  EXPECT_TRUE(outputs().empty());
}

TEST_F(FigmentViewExport, AnUnwritablePathIsOneLineAndNoImage) {
  const std::string file = dir_.file("a-file", "x");
  const ProcessResult result = run("-o " + quote(path("cloth.png")) + " --export " + quote(file + "/cloth.gltf"));
  EXPECT_EQ(result.status, 1);
  expectOneLine(result.err, "figment-view: --export " + file + "/cloth.gltf: cannot make the folder " + file);
  EXPECT_EQ(outputs(), std::vector<std::string>{"a-file"});
}

// The export comes first; an image that then cannot be written takes it away again.
TEST_F(FigmentViewExport, AFailureAfterTheExportLeavesNoExport) {
  const std::string file = dir_.file("a-file", "x");
  const ProcessResult result = run("-o " + quote(file + "/cloth.png") + " --export " + quote(path("cloth.gltf")));
  EXPECT_EQ(result.status, 1);
  expectOneLine(result.err, "figment-view: " + file + "/cloth.png: ");
  EXPECT_EQ(outputs(), std::vector<std::string>{"a-file"}) << "neither cloth.gltf nor cloth.bin";
}

TEST_F(FigmentViewExport, ExportBodyNeedsExportAndOneOutputIsNeeded) {
  ProcessResult result = run("-o " + quote(path("cloth.png")) + " --export-body");
  EXPECT_EQ(result.status, 2);
  expectOneLine(result.err, "figment-view: usage: --export-body needs --export");
  result = run("");
  EXPECT_EQ(result.status, 2);
  expectOneLine(result.err, "figment-view: usage: --output or --export is required");
  EXPECT_TRUE(outputs().empty());
}
