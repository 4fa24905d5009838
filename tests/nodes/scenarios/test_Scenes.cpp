// Every scene under scenes/ reads (reading simulates nothing, so this is fast).

#include <gtest/gtest.h>

#include <filesystem>

#include "support/SceneTestSupport.h"

using namespace figment::test;

TEST(Scenes, EveryIvFileReads) {
  initCoin();
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(FIGMENT_SOURCE_DIR "/scenes")) {
    if (entry.path().extension() != ".iv") continue;
    ++count;
    CapturedErrors errors;
    SceneRoot root = readFile(entry.path().string());
    EXPECT_TRUE(root) << entry.path() << ":\n" << errors.all();
  }
  EXPECT_GE(count, 3) << "one example per node class at least";
}
