// Mesh files that hang or crash assimp 5.2 are refused with one line saying why; clean ones,
// and files of other formats, pass to assimp.
#include <gtest/gtest.h>

#include <string>

#include "io/AssimpHazards.h"
#include "support/TempDir.h"

using namespace figment;

namespace {

const char kPly[] =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

TEST(AssimpHazards, ACleanPlyAndOtherFormatsPass) {
  const test::TempDir dir;
  EXPECT_EQ(assimpHazard(dir.file("ok.ply", kPly)), "");
  EXPECT_EQ(assimpHazard(dir.file("ok.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")), "");
  EXPECT_EQ(assimpHazard(dir.file("ok.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")), "");
}

TEST(AssimpHazards, APlyHeaderWithoutItsEndIsRefused) {
  const test::TempDir dir;
  const std::string problem = assimpHazard(dir.file("cut.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"));
  EXPECT_EQ(problem, "PLY header without end_header in its first 64 KiB (assimp 5.2 may never finish reading it)");
}

TEST(AssimpHazards, APlyCountTheFileCannotHoldIsRefused) {
  const test::TempDir dir;
  std::string text = kPly;
  text.replace(text.find("element face 1"), 14, "element face 6666666666");
  const std::string problem = assimpHazard(dir.file("huge.ply", text));
  EXPECT_EQ(
      problem.rfind("PLY header line 7: element face count \"6666666666\" makes more elements than the file's ", 0), 0u)
      << problem;
  // Found by its first word too, whatever its name.
  EXPECT_NE(assimpHazard(dir.file("huge.mesh", text)), "");
}

TEST(AssimpHazards, AnOffFileShortOfItsCountsIsRefused) {
  const test::TempDir dir;
  const std::string problem = assimpHazard(dir.file("short.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n"));
  EXPECT_EQ(problem.rfind("OFF file line ", 0), 0u) << problem;
  EXPECT_NE(problem.find("fewer vertices than the 4 counted"), std::string::npos) << problem;
  EXPECT_NE(problem.find("(assimp 5.2 may crash on it)"), std::string::npos) << problem;
}

}  // namespace
