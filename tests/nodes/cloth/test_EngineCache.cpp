// A ClothEngine's output from a drape (floats, sections as coordIndex) and its side of the
// drape cache: kept and read back with its report marked as from the cache, none without a
// cache or for another count of rest points, and a record this build cannot read removed
// and said.
#include <gtest/gtest.h>

#include <cstring>

#include "io/DrapeCache.h"
#include "io/DrapeRecord.h"
#include "nodes/cloth/EngineCache.h"
#include "support/TempDir.h"

using figment::EngineCache;
using figment::EngineOutput;
using figment::test::TempDir;

namespace {

figment::GarmentDrape twoTriangles() {
  figment::GarmentDrape drape;
  drape.positions = {{0.0, 1.0, 0.0}, {0.5, 1.0, 0.0}, {0.5, 1.5, 0.0}, {0.1, 1.5, 1.0 / 3.0}};
  drape.sections = {{0, 1, 2}, {0, 2, 3}};
  drape.report.run.iterations = 40;
  drape.report.run.atRest = true;
  drape.report.triangles = 2;
  return drape;
}

EngineOutput restOutput(int n) {
  return EngineOutput{std::vector<SbVec3f>(static_cast<size_t>(n), SbVec3f(9, 9, 9)), {}};
}

}  // namespace

TEST(EngineCache, AnOutputTakesTheDrapesPositionsAsFloatsAndItsSectionsAsCoordIndex) {
  EngineOutput out = restOutput(4);
  out.take(twoTriangles());
  EXPECT_EQ(out.positions[1], SbVec3f(0.5f, 1.0f, 0.0f));
  EXPECT_EQ(out.positions[3], SbVec3f(0.1f, 1.5f, float(1.0 / 3.0)));
  EXPECT_EQ(out.indices, (std::vector<std::int32_t>{0, 1, 2, -1, 0, 2, 3, -1}));
}

TEST(EngineCache, WithoutACacheNothingIsReadOrKept) {
  const EngineCache none(nullptr);
  EXPECT_FALSE(none);
  EngineOutput out = restOutput(4);
  std::string message;
  none.keep("key", twoTriangles(), message);
  EXPECT_FALSE(none.read("key", 4, out, message));
  EXPECT_EQ(message, "");
}

TEST(EngineCache, AKeptDrapeReadsBackWithItsReportFromTheCache) {
  const TempDir dir;
  const figment::DrapeCache drapes(dir.path(), 1 << 20);
  const EngineCache cache(&drapes);
  EngineOutput made = restOutput(4);
  const figment::GarmentDrape drape = twoTriangles();
  made.take(drape);
  std::string message;
  cache.keep("dress", drape, message);
  EXPECT_EQ(message, "");
  EngineOutput back = restOutput(4);
  const std::optional<figment::DrapeReport> report = cache.read("dress", 4, back, message);
  ASSERT_TRUE(report) << message;
  EXPECT_EQ(back.positions, made.positions);
  EXPECT_EQ(back.indices, made.indices);
  EXPECT_TRUE(report->fromCache);
  EXPECT_EQ(report->run.iterations, 40);
  EXPECT_TRUE(report->run.atRest);
  EngineOutput other = restOutput(5);
  EXPECT_FALSE(cache.read("dress", 5, other, message));  // another garment's count of points
  EXPECT_FALSE(cache.read("", 4, other, message));       // no key: nothing to look for
}

TEST(EngineCache, ARecordOfAnotherVersionIsRemovedAndSaid) {
  const TempDir dir;
  const figment::DrapeCache drapes(dir.path(), 1 << 20);
  const EngineCache cache(&drapes);
  std::string message;
  cache.keep("dress", twoTriangles(), message);
  std::optional<std::vector<unsigned char>> entry = drapes.find("dress", message);
  ASSERT_TRUE(entry) << message;
  const std::uint32_t later = figment::kDrapeRecordVersion + 1;
  std::memcpy(entry->data(), &later, sizeof later);  // a record starts with its version
  ASSERT_EQ(drapes.store("dress", *entry), "");
  EngineOutput back = restOutput(4);
  EXPECT_FALSE(cache.read("dress", 4, back, message));
  EXPECT_NE(message.find("version " + std::to_string(later)), std::string::npos) << message;
  EXPECT_NE(message.find("removed; draped again"), std::string::npos) << message;
  EXPECT_FALSE(drapes.find("dress", message));
}
