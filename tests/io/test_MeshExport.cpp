// OBJ output: what is written reads back the same, and a failed write leaves nothing behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "io/MeshExport.h"
#include "io/MeshImport.h"
#include "support/IoTestSupport.h"

using namespace figment;
using figment::test::TempDir;

namespace {

// A 3 x 2 quad strip, its vertices numbered in the order its triangles first use them.
TriangleMesh strip() {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0),   Vec3(0.1, 0, 0),   Vec3(0, 0.1, 0), Vec3(0.1, 0.1, 0.01234567),
                   Vec3(0.2, 0, 0), Vec3(0.2, 0.1, 0), Vec3(0.3, 0, 0), Vec3(0.3, 0.1, -1e-3)};
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}, {1, 4, 3}, {4, 5, 3}, {4, 6, 5}, {6, 7, 5}};
  return mesh;
}

}  // namespace

TEST(MeshExport, ReadsBackIndexForIndex) {
  const TempDir dir;
  const std::string path = (dir.path() / "strip.obj").string();
  const TriangleMesh written = strip();
  exportObj(written, path);
  const TriangleMesh read = importMesh(path).mesh;
  ASSERT_EQ(read.vertices.size(), written.vertices.size());
  for (size_t i = 0; i < read.vertices.size(); ++i)
    EXPECT_LT((read.vertices[i] - written.vertices[i]).norm(), 1e-7) << i;  // float, 9 digits
  EXPECT_EQ(read.triangles, written.triangles);
}

// "objnomtl": no material file; the temporary file is renamed away.
TEST(MeshExport, WritesOneFileAndNothingElse) {
  const TempDir dir;
  exportObj(strip(), (dir.path() / "strip.obj").string());
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    names.push_back(entry.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"strip.obj"});
}

TEST(MeshExport, ReplacesAnOlderFile) {
  const TempDir dir;
  const std::string path = dir.file("strip.obj", "old contents");
  exportObj(strip(), path);
  EXPECT_EQ(importMesh(path).mesh.triangles.size(), 6u);
}

TEST(MeshExport, UnwritablePathNamesItAndLeavesNothing) {
  // A missing folder is made (writeAtomically); one under a file cannot be.
  const TempDir dir;
  const std::string file = dir.file("a-file", "x");
  const std::string path = file + "/strip.obj";
  try {
    exportObj(strip(), path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()).rfind(path + ": ", 0), 0u) << error.what();
  }
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1) << "only the file that stands in the way";
}

TEST(MeshExport, RejectsEmptyAndBrokenMeshes) {
  const TempDir dir;
  const std::string path = (dir.path() / "bad.obj").string();
  EXPECT_THROW(exportObj(TriangleMesh{}, path), std::runtime_error);
  TriangleMesh broken = strip();
  broken.triangles.push_back({0, 1, 99});
  EXPECT_THROW(exportObj(broken, path), std::runtime_error);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}
