// MakeHuman's morph targets read on first use and kept: a target found under targets/ is
// read once, a missing one is null (and asked again, still null), an unreadable one names
// its file.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/TargetLibrary.h"
#include "support/GzipFile.h"
#include "support/TempDir.h"

using namespace figment;

namespace {

TEST(TargetLibrary, ReadsATargetOnceAndKeepsIt) {
  const test::TempDir dir;
  dir.file("targets/torso/placeholder", "");  // the folder
  test::writeGzip((dir.path() / "targets/torso/bust.target.gz").string(), "3 0.1 0.2 0.3\n7 -0.5 0 0.25\n");
  TargetLibrary library(dir.path().string());
  const MorphTarget* bust = library.find("torso/bust");
  ASSERT_NE(bust, nullptr);
  EXPECT_EQ(bust->vertices, (std::vector<int>{3, 7}));
  ASSERT_EQ(bust->offsets.size(), 2u);
  EXPECT_TRUE(bust->offsets[1].isApprox(Vec3(-0.5, 0, 0.25), 1e-6));
  std::filesystem::remove(dir.path() / "targets/torso/bust.target.gz");
  EXPECT_EQ(library.find("torso/bust"), bust);  // kept: not read again
  EXPECT_EQ(library.lookup()("torso/bust"), bust);
}

TEST(TargetLibrary, AMissingTargetIsNullAndABadOneNamesItsFile) {
  const test::TempDir dir;
  dir.file("targets/placeholder", "");
  test::writeGzip((dir.path() / "targets/bad.target.gz").string(), "1 0.1 oops\n");
  TargetLibrary library(dir.path().string());
  EXPECT_EQ(library.find("nothere"), nullptr);
  EXPECT_EQ(library.find("nothere"), nullptr);
  try {
    library.find("bad");
    FAIL() << "a bad target was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.target.gz"), std::string::npos) << e.what();
  }
}

}  // namespace
