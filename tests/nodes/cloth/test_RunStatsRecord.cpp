// The drape cache's record of a run's statistics: every field comes back as written
// (each set to a value of its own, so a field read into another's place shows); a record
// of another version, one cut short and one with bytes after its end are refused, naming
// why; a bool byte other than 0 or 1 is damage too.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "nodes/cloth/RunStatsRecord.h"

using figment::readRunStats;
using figment::writeRunStats;

namespace {

ClothEngine::RunStats everyFieldSet() {
  ClothEngine::RunStats s;
  s.triangles = 1442;
  s.iterations = 53;
  s.simulatedSeconds = 2.65;
  s.wallSeconds = std::nextafter(16.9, 17.0);
  s.atRest = true;
  s.clampedSectionShare = 0.125;
  s.limitedNodeShare = 0.0625;
  s.implicitSteps = 5000000000L;  // past 32 bits
  s.solverIterations = -7;
  s.assemblySeconds = 1.5e-300;
  s.solveSeconds = 3.25;
  s.contactSeconds = 0.75;
  s.level = 11;
  s.levels = 3000;
  s.sections = 2884;
  s.endLevelSeconds = 1.875;
  s.meanMoveAfterEndLevel = 1e-4;
  s.maxMoveAfterEndLevel = 2e-3;
  s.fromCache = false;
  s.picked = "implicit:0.05, volumes, progressive 0:3000 \xc2\xb5";
  s.pickedDeviation = 0.7;
  s.pickedBody = "triangles";
  s.passedOver = "capsules: no capsule volumes";
  s.integrator = "IMPLICIT";
  s.contactModel = "PENALTY";
  s.accelerationLimiter = "TANH";
  s.timeStep = 0.02;
  s.strainLimit = 0.1;
  s.accelerationLimit = 30.0;
  s.maxTime = 5.0;
  s.maxSpeed = 0.31;
  s.maxStretch = 2.02;
  s.clampedSectionShareAtEnd = 0.25;
  s.limitedNodeShareAtEnd = 0.035;
  s.halvedSteps = 6000000000L;  // past 32 bits
  s.failedSteps = 2;
  return s;
}

void expectSame(const ClothEngine::RunStats& a, const ClothEngine::RunStats& b) {
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.simulatedSeconds, b.simulatedSeconds);
  EXPECT_EQ(a.wallSeconds, b.wallSeconds);
  EXPECT_EQ(a.atRest, b.atRest);
  EXPECT_EQ(a.clampedSectionShare, b.clampedSectionShare);
  EXPECT_EQ(a.limitedNodeShare, b.limitedNodeShare);
  EXPECT_EQ(a.implicitSteps, b.implicitSteps);
  EXPECT_EQ(a.solverIterations, b.solverIterations);
  EXPECT_EQ(a.assemblySeconds, b.assemblySeconds);
  EXPECT_EQ(a.solveSeconds, b.solveSeconds);
  EXPECT_EQ(a.contactSeconds, b.contactSeconds);
  EXPECT_EQ(a.level, b.level);
  EXPECT_EQ(a.levels, b.levels);
  EXPECT_EQ(a.sections, b.sections);
  EXPECT_EQ(a.endLevelSeconds, b.endLevelSeconds);
  EXPECT_EQ(a.meanMoveAfterEndLevel, b.meanMoveAfterEndLevel);
  EXPECT_EQ(a.maxMoveAfterEndLevel, b.maxMoveAfterEndLevel);
  EXPECT_EQ(a.fromCache, b.fromCache);
  EXPECT_EQ(a.picked, b.picked);
  EXPECT_EQ(a.pickedDeviation, b.pickedDeviation);
  EXPECT_EQ(a.pickedBody, b.pickedBody);
  EXPECT_EQ(a.passedOver, b.passedOver);
  EXPECT_EQ(a.integrator, b.integrator);
  EXPECT_EQ(a.contactModel, b.contactModel);
  EXPECT_EQ(a.accelerationLimiter, b.accelerationLimiter);
  EXPECT_EQ(a.timeStep, b.timeStep);
  EXPECT_EQ(a.strainLimit, b.strainLimit);
  EXPECT_EQ(a.accelerationLimit, b.accelerationLimit);
  EXPECT_EQ(a.maxTime, b.maxTime);
  EXPECT_EQ(a.maxSpeed, b.maxSpeed);
  EXPECT_EQ(a.maxStretch, b.maxStretch);
  EXPECT_EQ(a.clampedSectionShareAtEnd, b.clampedSectionShareAtEnd);
  EXPECT_EQ(a.limitedNodeShareAtEnd, b.limitedNodeShareAtEnd);
  EXPECT_EQ(a.halvedSteps, b.halvedSteps);
  EXPECT_EQ(a.failedSteps, b.failedSteps);
}

}  // namespace

TEST(RunStatsRecord, EveryFieldComesBackAsWritten) {
  const ClothEngine::RunStats written = everyFieldSet();
  std::string problem = "not cleared";
  const std::optional<ClothEngine::RunStats> read = readRunStats(writeRunStats(written), problem);
  ASSERT_TRUE(read) << problem;
  EXPECT_EQ(problem, "");
  expectSame(*read, written);
  const std::optional<ClothEngine::RunStats> empty = readRunStats(writeRunStats({}), problem);
  ASSERT_TRUE(empty) << problem;
  expectSame(*empty, ClothEngine::RunStats{});
}

TEST(RunStatsRecord, StartsWithItsVersion) {
  const std::vector<unsigned char> record = writeRunStats(everyFieldSet());
  std::uint32_t version = 0;
  ASSERT_GE(record.size(), sizeof version);
  std::memcpy(&version, record.data(), sizeof version);
  EXPECT_EQ(version, figment::kRunStatsRecordVersion);
}

TEST(RunStatsRecord, ARecordOfAnotherVersionIsRefusedNamingIt) {
  std::vector<unsigned char> record = writeRunStats(everyFieldSet());
  const std::uint32_t earlier = figment::kRunStatsRecordVersion - 1;
  std::memcpy(record.data(), &earlier, sizeof earlier);
  std::string problem;
  EXPECT_FALSE(readRunStats(record, problem));
  EXPECT_EQ(problem, "a record of version " + std::to_string(earlier) + ", not " +
                         std::to_string(figment::kRunStatsRecordVersion));
}

TEST(RunStatsRecord, ARecordCutShortOrRunningOnIsDamaged) {
  const std::vector<unsigned char> record = writeRunStats(everyFieldSet());
  std::string problem;
  for (size_t size : {size_t(0), size_t(2), size_t(4), size_t(20), record.size() - 1}) {
    const std::vector<unsigned char> cut(record.begin(), record.begin() + size);
    EXPECT_FALSE(readRunStats(cut, problem)) << size << " bytes";
    EXPECT_EQ(problem, "a damaged record") << size << " bytes";
  }
  std::vector<unsigned char> longer = record;
  longer.push_back(0);
  EXPECT_FALSE(readRunStats(longer, problem));
  EXPECT_EQ(problem, "a damaged record");
}

TEST(RunStatsRecord, ABoolOtherThanZeroOrOneIsDamage) {
  ClothEngine::RunStats stats;
  stats.atRest = true;
  std::vector<unsigned char> record = writeRunStats(stats);
  // atRest follows the version (4 bytes), two int32 and two float64: byte 28.
  ASSERT_EQ(record.at(28), 1);
  record[28] = 2;
  std::string problem;
  EXPECT_FALSE(readRunStats(record, problem));
  EXPECT_EQ(problem, "a damaged record");
}
