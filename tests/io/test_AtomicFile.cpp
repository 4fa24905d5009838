// Output files that exist only when complete, in folders made as needed.
#include "io/AtomicFile.h"
#include "support/TempDir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

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

}  // namespace
