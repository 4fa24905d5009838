// The drape cache's record of a drape: every field of its report comes back as written
// (each set to a value of its own, so a field read into another's place shows), and its
// positions and sections as the engine draws them; a record of another version, one cut
// short and one with bytes after its end are refused, naming why; a bool byte other than 0
// or 1, a method's enumeration past its values, a position that is not finite or a
// section past the positions is damage.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "io/DrapeRecord.h"

using figment::DrapeReport;
using figment::GarmentDrape;
using figment::readDrapeRecord;
using figment::writeDrapeRecord;

namespace {

DrapeReport everyFieldSet() {
  DrapeReport s;
  s.method = {figment::Integrator::SymplecticEuler, figment::ContactModel::Penalty, 0.02,
              figment::AccelerationLimiter::Tanh, 30.0};
  s.method.maxTimeStep = 0.75;
  s.strainLimit = 0.1;
  s.maxTime = 5.0;
  s.picked = "implicit:0.05, volumes, progressive 0:3000 \xc2\xb5";
  s.pickedDeviation = 0.7;
  s.pickedBody = "triangles";
  s.passedOver = "capsules: no capsule volumes";
  s.body = {"mannequin", {{"capsule_volumes", 3}, {"radial_volumes", 11}}};
  s.triangles = 1442;
  s.run.iterations = 53;
  s.run.simulatedTime = 2.65;
  s.run.wallSeconds = 0.375;
  s.run.atRest = true;
  s.run.clampedSectionShare = 0.125;
  s.run.limitedNodeShare = 0.0625;
  s.run.implicitCosts = {5000000000L, -7, 9, 1.5e-300, 3.25, 0.75, 6000000000L, 2};  // two past 32 bits
  s.run.maxSpeed = 0.31;
  s.run.maxStretch = 2.02;
  s.run.clampedSectionShareAtEnd = 0.25;
  s.run.limitedNodeShareAtEnd = 0.035;
  s.level = 11;
  s.levels = 3000;
  s.sections = 2884;
  s.settling = {1.875, 1e-4, 2e-3};
  s.startedOverLayers = 313;
  s.warm = true;
  s.fromCache = true;
  s.wallSeconds = std::nextafter(16.9, 17.0);
  s.garmentWarning = "12 nodes start inside the body";
  s.verdict = "not at rest";
  return s;
}

void expectSame(const DrapeReport& a, const DrapeReport& b) {
  EXPECT_EQ(a.method, b.method);
  EXPECT_EQ(a.strainLimit, b.strainLimit);
  EXPECT_EQ(a.maxTime, b.maxTime);
  EXPECT_EQ(a.picked, b.picked);
  EXPECT_EQ(a.pickedDeviation, b.pickedDeviation);
  EXPECT_EQ(a.pickedBody, b.pickedBody);
  EXPECT_EQ(a.passedOver, b.passedOver);
  EXPECT_EQ(a.body.kind, b.body.kind);
  EXPECT_EQ(a.body.counts, b.body.counts);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.startedOverLayers, b.startedOverLayers);
  EXPECT_EQ(a.run.iterations, b.run.iterations);
  EXPECT_EQ(a.run.simulatedTime, b.run.simulatedTime);
  EXPECT_EQ(a.run.wallSeconds, b.run.wallSeconds);
  EXPECT_EQ(a.run.atRest, b.run.atRest);
  EXPECT_EQ(a.run.clampedSectionShare, b.run.clampedSectionShare);
  EXPECT_EQ(a.run.limitedNodeShare, b.run.limitedNodeShare);
  const figment::ImplicitStepCosts &c = a.run.implicitCosts, &d = b.run.implicitCosts;
  EXPECT_EQ(c.steps, d.steps);
  EXPECT_EQ(c.solverIterations, d.solverIterations);
  EXPECT_EQ(c.unconvergedSolves, d.unconvergedSolves);
  EXPECT_EQ(c.assemblySeconds, d.assemblySeconds);
  EXPECT_EQ(c.solveSeconds, d.solveSeconds);
  EXPECT_EQ(c.contactSeconds, d.contactSeconds);
  EXPECT_EQ(c.halvedSteps, d.halvedSteps);
  EXPECT_EQ(c.failedSteps, d.failedSteps);
  EXPECT_EQ(a.run.maxSpeed, b.run.maxSpeed);
  EXPECT_EQ(a.run.maxStretch, b.run.maxStretch);
  EXPECT_EQ(a.run.clampedSectionShareAtEnd, b.run.clampedSectionShareAtEnd);
  EXPECT_EQ(a.run.limitedNodeShareAtEnd, b.run.limitedNodeShareAtEnd);
  EXPECT_EQ(a.level, b.level);
  EXPECT_EQ(a.levels, b.levels);
  EXPECT_EQ(a.sections, b.sections);
  EXPECT_EQ(a.settling.arrival, b.settling.arrival);
  EXPECT_EQ(a.settling.meanMove, b.settling.meanMove);
  EXPECT_EQ(a.settling.maxMove, b.settling.maxMove);
  EXPECT_EQ(a.warm, b.warm);
  EXPECT_EQ(a.fromCache, b.fromCache);
  EXPECT_EQ(a.wallSeconds, b.wallSeconds);
  EXPECT_EQ(a.garmentWarning, b.garmentWarning);
  EXPECT_EQ(a.verdict, b.verdict);
}

// A drape of three points and one section, with every field of its report set.
GarmentDrape everyPartSet() {
  GarmentDrape drape;
  drape.report = everyFieldSet();
  drape.positions = {{0.25, 1.0, -0.5}, {std::nextafter(1.0f, 2.0f), 0.0, 3e-7}, {-1.0, 2.0, 0.125}};
  drape.sections = {{0, 2, 1}};
  return drape;
}

// `report` through a record (of a drape with no points) and back.
std::optional<DrapeReport> roundTrip(const DrapeReport& report, std::string& problem) {
  GarmentDrape drape;
  drape.report = report;
  std::optional<GarmentDrape> read = readDrapeRecord(writeDrapeRecord(drape), problem);
  if (!read) return std::nullopt;
  return read->report;
}

std::string problemOf(const std::vector<unsigned char>& record) {
  std::string problem;
  EXPECT_FALSE(readDrapeRecord(record, problem));
  return problem;
}

}  // namespace

TEST(DrapeRecord, EveryFieldComesBackAsWritten) {
  const DrapeReport written = everyFieldSet();
  std::string problem = "not cleared";
  const std::optional<DrapeReport> read = roundTrip(written, problem);
  ASSERT_TRUE(read) << problem;
  EXPECT_EQ(problem, "");
  expectSame(*read, written);
  const std::optional<DrapeReport> empty = roundTrip({}, problem);
  ASSERT_TRUE(empty) << problem;
  expectSame(*empty, DrapeReport{});
  DrapeReport noLimit = written;
  noLimit.method.limit.reset();
  EXPECT_EQ(roundTrip(noLimit, problem)->method, noLimit.method);
}

// Positions as the engine draws them: floats, so a float's bits come back whole.
TEST(DrapeRecord, PositionsAndSectionsComeBackAsFloatsAndTriples) {
  const GarmentDrape written = everyPartSet();
  std::string problem;
  const std::optional<GarmentDrape> read = readDrapeRecord(writeDrapeRecord(written), problem);
  ASSERT_TRUE(read) << problem;
  ASSERT_EQ(read->positions.size(), 3u);
  for (size_t i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(read->positions[i][k], double(float(written.positions[i][k])));
  EXPECT_EQ(read->positions[1].x(), double(std::nextafter(1.0f, 2.0f)));
  EXPECT_EQ(read->sections, written.sections);
  EXPECT_FALSE(read->sewing);
}

TEST(DrapeRecord, APositionNotFiniteOrASectionPastThePositionsIsDamage) {
  GarmentDrape nan = everyPartSet(), past = everyPartSet(), negative = everyPartSet();
  nan.positions[1].y() = std::nan("");
  past.sections = {{0, 1, 3}};
  negative.sections = {{0, -1, 2}};
  for (const GarmentDrape* drape : {&nan, &past, &negative})
    EXPECT_EQ(problemOf(writeDrapeRecord(*drape)), "a damaged record");
}

TEST(DrapeRecord, StartsWithItsVersion) {
  const std::vector<unsigned char> record = writeDrapeRecord(everyPartSet());
  std::uint32_t version = 0;
  ASSERT_GE(record.size(), sizeof version);
  std::memcpy(&version, record.data(), sizeof version);
  EXPECT_EQ(version, figment::kDrapeRecordVersion);
}

TEST(DrapeRecord, ARecordOfAnotherVersionIsRefusedNamingIt) {
  std::vector<unsigned char> record = writeDrapeRecord(everyPartSet());
  const std::uint32_t earlier = figment::kDrapeRecordVersion - 1;
  std::memcpy(record.data(), &earlier, sizeof earlier);
  EXPECT_EQ(problemOf(record),
            "a record of version " + std::to_string(earlier) + ", not " + std::to_string(figment::kDrapeRecordVersion));
}

TEST(DrapeRecord, ARecordCutShortOrRunningOnIsDamaged) {
  const std::vector<unsigned char> record = writeDrapeRecord(everyPartSet());
  for (size_t size : {size_t(0), size_t(2), size_t(4), size_t(20), record.size() - 1}) {
    const std::vector<unsigned char> cut(record.begin(), record.begin() + size);
    EXPECT_EQ(problemOf(cut), "a damaged record") << size << " bytes";
  }
  std::vector<unsigned char> longer = record;
  longer.push_back(0);
  EXPECT_EQ(problemOf(longer), "a damaged record");
}

TEST(DrapeRecord, ABoolOtherThanZeroOrOneOrAnEnumerationPastItsValuesIsDamage) {
  const std::vector<unsigned char> record = writeDrapeRecord(everyPartSet());
  // After the version (4 bytes): the integrator, the contact model (a byte each), the
  // time step and the largest step (float64 each), the limiter (a byte), whether a limit is
  // given (a bool).
  ASSERT_EQ(record.at(4), static_cast<unsigned char>(figment::Integrator::SymplecticEuler));
  ASSERT_EQ(record.at(23), 1);
  std::vector<unsigned char> integrator = record, flag = record;
  integrator[4] = static_cast<unsigned char>(figment::Integrator::Implicit) + 1;
  EXPECT_EQ(problemOf(integrator), "a damaged record");
  flag[23] = 2;
  EXPECT_EQ(problemOf(flag), "a damaged record");
}
