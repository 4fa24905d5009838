// Every shopper's body (issues 30 and 43): the 78 measurement sets (sim/garment/SizeGrading.h's
// bodyCheckSets over the shipped chart: its women's DOB 32 to 54 and men's HAKA 44 to 62, two
// graded below each sex's smallest, each at its stature and 8 cm shorter and taller) each make a body that, written and
// read back as figment-measure reads it, measures within 5 mm of every typed value, and whose
// skin has no two parts crossing that do not in the base mesh. Skipped when MakeHuman's data
// is absent (scripts/setup.sh fetches it).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "io/MakeHumanFiles.h"
#include "io/MakeHumanLibrary.h"
#include "io/MakeHumanRig.h"
#include "io/MeshExport.h"
#include "io/MeshImport.h"
#include "io/SizeChartFile.h"
#include "sim/body/MeasuredBody.h"
#include "sim/body/SkinParts.h"
#include "sim/collision/SelfIntersections.h"
#include "sim/garment/SizeGrading.h"
#include "support/IoTestSupport.h"

using namespace figment;
using figment::test::TempDir;

namespace {

class MeasuredBodies : public ::testing::Test {
 protected:
  void SetUp() override {
    if (human.dir().empty()) GTEST_SKIP() << "MakeHuman's data not found (scripts/setup.sh fetches it)";
    model = &human.model();
    parts = skinTriangleParts(readHumanRig(human.dir(), model->base().fileVertexCount), model->base());
    baseCrossing = crossingLabels(selfIntersections(model->base().skin), parts);
  }
  // The part pairs that cross on `body` and not in the base mesh, named: "left thigh x right thigh".
  std::vector<std::string> newPartCrossings(const TriangleMesh& body) const {
    std::vector<std::string> out;
    for (const auto& [a, b] : crossingLabels(selfIntersections(body), parts))
      if (std::find(baseCrossing.begin(), baseCrossing.end(), std::pair(a, b)) == baseCrossing.end())
        out.push_back(skinPartNames()[size_t(a)] + " x " + skinPartNames()[size_t(b)]);
    return out;
  }
  static HumanParameters startFor(Sex sex) {
    HumanParameters p;
    p.macro.gender = sex == Sex::Male ? 1.0 : 0.0;
    return p;
  }
  MakeHumanLibrary human;
  const HumanModel* model = nullptr;  // human's
  std::vector<int> parts;
  std::vector<std::pair<int, int>> baseCrossing;
};

std::string label(const ChartSize& set) {
  char text[80];
  std::snprintf(text, sizeof text, "%s %s (%s) at %.2f m", sexName(set.sex), set.name.c_str(), set.number.c_str(),
                set.stature);
  return text;
}

}  // namespace

TEST_F(MeasuredBodies, EveryCheckSetMeasuresWithin5mmAndCrossesNoNewParts) {
  const std::vector<ChartSize> sets = bodyCheckSets(readSizeChart(defaultSizeChartPath()));
  ASSERT_EQ(sets.size(), 78u);
  EXPECT_TRUE(baseCrossing.empty());  // MakeHuman's base skin crosses nowhere between parts
  const TempDir dir;
  const std::string path = (dir.path() / "body.obj").string();
  for (const ChartSize& set : sets) {
    const std::vector<MeasurementGoal> goals = {
        {"stature", set.stature}, {"bust_girth", set.bust}, {"waist_girth", set.waist}, {"hip_girth", set.hip}};
    MeasuredBody made;
    ASSERT_NO_THROW(made = makeMeasuredBody(*model, startFor(set.sex), goals)) << label(set);
    exportObj(numberedByFirstUse(made.body), path);                 // as figment-body writes it
    const BodyMeasurements m = measureBody(importMesh(path).mesh);  // as figment-measure reads it
    for (const MeasurementGoal& goal : goals) EXPECT_NEAR(m.byName(goal.key), goal.value, 0.005) << label(set);
    const std::vector<std::string> crossing = newPartCrossings(made.body);
    // The one known exception (issue 43): the women's DOB 54 at 160 cm, MakeHuman's heaviest
    // short body, holds its upper arms into its trunk in the A-pose.
    if (set.sex == Sex::Female && set.number == "54" && set.stature < 1.65) {
      for (const std::string& pair : crossing)
        EXPECT_TRUE(pair == "trunk x left upper arm" || pair == "trunk x right upper arm")
            << label(set) << ": " << pair;
      continue;
    }
    EXPECT_TRUE(crossing.empty()) << label(set) << ": " << (crossing.empty() ? "" : crossing.front());
  }
}

// Issue 43's shoppers the solve refused before the chest's window stopped above a belly and
// the girths went on past their targets (the waist by the stomach, the hips by the buttocks,
// the bust by the cup): each made within 5 mm of its four typed values.
TEST_F(MeasuredBodies, TheIssuesFullerBodiesAreReached) {
  const std::vector<ChartSize> sets = {
      {Sex::Female, "about DOB 50", "", 1.68, 1.16, 1.02, 1.24},  // refused: waist nearest 1.006 m
      {Sex::Female, "about DOB 48", "", 1.68, 1.14, 0.98, 1.20},
      {Sex::Male, "belly", "", 1.74, 1.00, 0.94, 1.00},  // refused at 1.78 to 1.86 m: waist 0.926-0.933 m
      {Sex::Male, "belly", "", 1.78, 1.00, 0.94, 1.00},
      {Sex::Male, "belly", "", 1.82, 1.00, 0.94, 1.00},
      {Sex::Male, "belly", "", 1.86, 1.00, 0.94, 1.00},
      {Sex::Male, "apple", "", 1.80, 1.04, 1.02, 1.06},  // the waist 2 cm under the chest
      {Sex::Male, "apple", "", 1.86, 1.20, 1.18, 1.22},
      {Sex::Female, "pear", "", 1.68, 0.88, 0.72, 1.02},  // the hips 30 cm over the waist
      {Sex::Female, "pear", "", 1.68, 1.04, 0.90, 1.20},
      {Sex::Female, "pear", "", 1.60, 1.16, 1.00, 1.30},
      {Sex::Female, "straight", "", 1.68, 0.96, 0.80, 0.96},  // refused: hips nearest 0.977 m
  };
  for (const ChartSize& set : sets) {
    const std::vector<MeasurementGoal> goals = {
        {"stature", set.stature}, {"bust_girth", set.bust}, {"waist_girth", set.waist}, {"hip_girth", set.hip}};
    MeasuredBody made;
    ASSERT_NO_THROW(made = makeMeasuredBody(*model, startFor(set.sex), goals)) << label(set);
    for (const MeasurementGoal& goal : goals)
      EXPECT_NEAR(made.achieved.byName(goal.key), goal.value, 0.005) << label(set) << " " << goal.key;
  }
}

// Not yet reached: a women's apple (the waist 6 cm under the bust) measures its belly as its
// hips (the fullest level between crotch and waist), so the hips come out too full. The refusal
// says which measurement and how near it got.
TEST_F(MeasuredBodies, AWomensAppleIsRefusedNamingTheHips) {
  try {
    makeMeasuredBody(*model, startFor(Sex::Female),
                     {{"stature", 1.68}, {"bust_girth", 1.10}, {"waist_girth", 1.04}, {"hip_girth", 1.14}});
    FAIL() << "made";
  } catch (const UnreachableMeasurement& error) {
    EXPECT_NE(std::string(error.what()).find("hip_girth 1.140 m is out of reach"), std::string::npos) << error.what();
  }
}

TEST_F(MeasuredBodies, LegsPushedTogetherAreFoundCrossing) {
  // The check finds what it is for: the left lower leg moved across the gap to the right one,
  // and 3 cm on, crosses it
  TriangleMesh body = model->make(startFor(Sex::Female));
  EXPECT_TRUE(newPartCrossings(body).empty());
  const std::vector<std::string>& names = skinPartNames();
  std::vector<char> leftLeg(body.vertices.size(), 0);
  double leftInner = 1, rightInner = -1;  // m: the lower legs' inner sides (x)
  for (size_t t = 0; t < body.triangles.size(); ++t) {
    const std::string& name = names[size_t(parts[t])];
    for (int k = 0; k < 3; ++k) {
      const int v = body.triangles[t][k];
      if (name == "left lower leg" || name == "left foot") leftLeg[size_t(v)] = 1;
      if (name == "left lower leg") leftInner = std::min(leftInner, body.vertices[size_t(v)].x());
      if (name == "right lower leg") rightInner = std::max(rightInner, body.vertices[size_t(v)].x());
    }
  }
  ASSERT_GT(leftInner, rightInner);
  for (size_t v = 0; v < body.vertices.size(); ++v)
    if (leftLeg[v]) body.vertices[v].x() -= leftInner - rightInner + 0.03;
  const std::vector<std::string> crossing = newPartCrossings(body);
  EXPECT_NE(std::find(crossing.begin(), crossing.end(), "left lower leg x right lower leg"), crossing.end());
}

TEST_F(MeasuredBodies, EachPartHoldsSkinOnBothSides) {
  std::vector<int> count(skinPartNames().size(), 0);
  for (const int p : parts) ++count[size_t(p)];
  for (size_t p = 0; p < count.size(); ++p) EXPECT_GT(count[p], 100) << skinPartNames()[p];
  for (size_t p = 2; p + 1 < count.size(); p += 2)  // left and right alike (the mesh is symmetric)
    EXPECT_EQ(count[p], count[p + 1]) << skinPartNames()[p];
}

TEST_F(MeasuredBodies, APartialMeasurementIsTheFullOnesPart) {
  // what the maker measures at each step is what figment-measure gives for the same keys
  for (const double weight : {0.2, 0.9}) {
    HumanParameters p = startFor(Sex::Female);
    p.macro.weight = weight;
    const TriangleMesh body = model->make(p);
    const BodyMeasurements full = measureBody(body);
    for (const std::vector<std::string>& keys : {std::vector<std::string>{"stature"},
                                                 {"bust_girth", "waist_girth", "hip_girth"},
                                                 {"underbust_girth"},
                                                 {"neck_girth", "arm_length"},
                                                 {"upper_arm_girth"},
                                                 {"thigh_girth", "inside_leg", "shoulder_width"}}) {
      const BodyMeasurements part = measureBody(body, keys);
      for (const std::string& key : keys) EXPECT_EQ(part.byName(key), full.byName(key)) << key;
    }
  }
  EXPECT_THROW(measureBody(model->make(startFor(Sex::Male)), {"waist"}), std::invalid_argument);
}

TEST_F(MeasuredBodies, BeyondTheWeightsEndsTheMassGoesOnThroughMuscleAndCup) {
  const auto made = [&](double stature, double bust, double waist, double hip) {
    return makeMeasuredBody(*model, startFor(Sex::Female),
                            {{"stature", stature}, {"bust_girth", bust}, {"waist_girth", waist}, {"hip_girth", hip}})
        .parameters.macro;
  };
  // women's 38: within the weight's range, muscle and cup size as they were
  const MacroParameters m38 = made(1.68, 0.88, 0.72, 0.96);
  EXPECT_GT(m38.weight, 0.0);
  EXPECT_LT(m38.weight, 1.0);
  EXPECT_EQ(m38.muscle, 0.5);
  EXPECT_EQ(m38.cupSize, 0.5);
  // women's 46 (graded above the chart): the heaviest weight, and less muscle
  const MacroParameters m46 = made(1.68, 1.04, 0.88, 1.12);
  EXPECT_EQ(m46.weight, 1.0);
  EXPECT_LT(m46.muscle, 0.5);
  // women's 28 (graded below) at 176 cm: the lightest weight, no muscle, and a smaller cup
  // once the bust target is at its end
  const MacroParameters m28 = made(1.76, 0.68, 0.52, 0.76);
  EXPECT_EQ(m28.weight, 0.0);
  EXPECT_EQ(m28.muscle, 0.0);
  EXPECT_LT(m28.cupSize, 0.5);
}
