// Output files that exist only when complete, in folders made as needed.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/AtomicFile.h"
#include "support/TempDir.h"

namespace test_AtomicFile {

namespace {

using figment::writeAtomically;

std::string writeText(const std::string& path, const std::string& text) {
  return writeAtomically(path, [&text](const std::string& temporary) -> std::string {
    std::ofstream(temporary) << text;
    return "";
  });
}

TEST(AtomicFile, MakesTheFoldersThePathNames) {
  const figment::test::TempDir dir;
  const std::string path = (dir.path() / "one" / "two" / "out.txt").string();
  ASSERT_EQ(writeText(path, "hello"), "");
  std::string read;
  std::ifstream(path) >> read;
  EXPECT_EQ(read, "hello");
}

TEST(AtomicFile, AFolderThatCannotBeMadeIsAnErrorNamingItAndWhy) {
  const figment::test::TempDir dir;
  const std::string file = dir.file("a-file", "x");
  const std::string error = writeText(file + "/inside/out.txt", "hello");
  EXPECT_NE(error.find("cannot make the folder " + file + "/inside"), std::string::npos) << error;
  EXPECT_NE(error.find("Not a directory"), std::string::npos) << error;
}

TEST(AtomicFile, AFailedWriteLeavesThePathAsItWasAndNoTemporaryFile) {
  const figment::test::TempDir dir;
  const std::string path = (dir.path() / "out.txt").string();
  ASSERT_EQ(writeText(path, "before"), "");
  const std::string error = writeAtomically(path, [](const std::string& temporary) -> std::string {
    std::ofstream(temporary) << "half";
    return "the writer failed";
  });
  EXPECT_EQ(error, "the writer failed");
  std::string read;
  std::ifstream(path) >> read;
  EXPECT_EQ(read, "before");
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) files += entry.is_regular_file();
  EXPECT_EQ(files, 1);
}

// A writer that puts a companion beside its file, naming it after the file (as assimp's
// OBJ and glTF writers do).
std::string writeWithCompanion(const std::string& path, std::vector<std::string>* written,
                               const std::string& failure = "") {
  return figment::writeFilesAtomically(
      path,
      [&failure](const std::string& temporary) -> std::string {
        std::filesystem::path companion(temporary);
        companion.replace_extension(".mtl");
        std::ofstream(temporary) << "mtllib " << companion.filename().string();
        std::ofstream(companion) << "newmtl";
        return failure;
      },
      written);
}

std::vector<std::string> namesIn(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(AtomicFile, CompanionFilesArriveWithTheFileUnderTheirFinalNames) {
  const figment::test::TempDir dir;
  const std::string path = (dir.path() / "sub" / "out.obj").string();
  std::vector<std::string> written;
  ASSERT_EQ(writeWithCompanion(path, &written), "");
  EXPECT_EQ(namesIn(dir.path() / "sub"), (std::vector<std::string>{"out.mtl", "out.obj"}));
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[0], path);  // the file first
  EXPECT_EQ(written[1], (dir.path() / "sub" / "out.mtl").string());
  std::string line;
  std::getline(std::ifstream(path), line);
  EXPECT_EQ(line, "mtllib out.mtl");  // written under the final name, not a temporary one
}

TEST(AtomicFile, AFailedWriteWithCompanionsLeavesNothing) {
  const figment::test::TempDir dir;
  const std::string path = (dir.path() / "out.obj").string();
  std::vector<std::string> written{"stale"};
  EXPECT_EQ(writeWithCompanion(path, &written, "the writer failed"), "the writer failed");
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));  // no file, no companion, no temporary folder
  EXPECT_EQ(written, std::vector<std::string>{"stale"});
}

TEST(AtomicFile, CompanionsUnderAFileThatIsNoFolderAreAnErrorNamingIt) {
  const figment::test::TempDir dir;
  const std::string file = dir.file("a-file", "x");
  const std::string error = writeWithCompanion(file + "/out.obj", nullptr);
  EXPECT_NE(error.find("cannot make the folder " + file), std::string::npos) << error;
  EXPECT_EQ(namesIn(dir.path()), std::vector<std::string>{"a-file"});
}

}  // namespace

}  // namespace test_AtomicFile
