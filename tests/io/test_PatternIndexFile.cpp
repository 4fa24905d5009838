// The pattern index (scenes/patterns/index.json): the shipped one names a file that exists
// for every entry, each cut for its size's stature and girths; a bad entry is refused
// naming the file, the entry and the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/PatternIndexFile.h"
#include "support/TempDir.h"

namespace test_PatternIndexFile {

using namespace figment;
using figment::test::TempDir;

namespace {

const std::string kShipped = std::string(FIGMENT_SOURCE_DIR) + "/scenes/patterns/index.json";

std::string errorOf(const std::string& path) {
  try {
    readPatternIndex(path);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(PatternIndexFile, TheShippedIndexNamesFilesThatExist) {
  const std::vector<PatternIndexEntry> entries = readPatternIndex(kShipped);
  ASSERT_FALSE(entries.empty());
  int tshirts = 0;
  for (const PatternIndexEntry& entry : entries) {
    EXPECT_TRUE(std::filesystem::is_regular_file(entry.file)) << entry.file;
    tshirts += entry.style == "tshirt";
  }
  EXPECT_EQ(tshirts, 22);  // women's 32-54 and men's 44-62: 12 + 10
  const PatternIndexEntry& first = entries.front();
  EXPECT_EQ(first.style, "tshirt");
  EXPECT_EQ(first.sex, Sex::Female);
  EXPECT_EQ(first.size, "XXS");
  EXPECT_EQ(first.number, "32");
  EXPECT_DOUBLE_EQ(first.body.stature, 1.68);
  EXPECT_DOUBLE_EQ(first.body.bust, 0.76);
  EXPECT_DOUBLE_EQ(first.body.waist, 0.60);
  EXPECT_DOUBLE_EQ(first.body.hip, 0.84);
  EXPECT_EQ(std::filesystem::path(first.file).filename(), "tshirt-f-32_specification.json");
}

TEST(PatternIndexFile, BadEntriesAreNamed) {
  const TempDir dir;
  const std::string entry = R"("style": "tee", "sex": "female", "size": "M", "number": 38, "file": "a.json")";
  const auto index = [&](const std::string& text) { return dir.file("index.json", text); };
  EXPECT_EQ(errorOf(index("{\"patterns\": [{" + entry + R"(, "stature": 1.68, "bust": 0.88, "waist": 0.72}]})")),
            dir.path().string() + "/index.json: patterns[0]: hips is not a positive number (m)");
  EXPECT_EQ(errorOf(index(R"({"patterns": [{"style": "tee", "sex": "woman"}]})")),
            dir.path().string() + "/index.json: patterns[0]: sex woman is not female or male");
  EXPECT_EQ(errorOf(index(R"({"patterns": [{"sex": "female"}]})")),
            dir.path().string() + "/index.json: patterns[0]: no \"style\"");
  EXPECT_EQ(errorOf(index("{\"patterns\": [")), dir.path().string() + "/index.json: not JSON (byte 15)");
  EXPECT_EQ(errorOf(index("{}")), dir.path().string() + "/index.json: no \"patterns\" list");
  EXPECT_EQ(errorOf(index("{\"patterns\": [{" + entry +
                          R"(, "stature": 1.68, "bust": 0.88, "waist": 0.72, "hips": 0.96}]})")),
            "");
}

}  // namespace test_PatternIndexFile
