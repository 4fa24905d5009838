// MakeHuman's macro target weights (sim/body/MacroBlend.h): products of piecewise-linear
// anchor weights, so each combination's weights sum to 1 where no anchor is neutral.
#include <gtest/gtest.h>

#include <map>
#include <stdexcept>

#include "sim/body/MacroBlend.h"

using namespace figment;

namespace {

std::map<std::string, double> byName(const MacroParameters& p) {
  std::map<std::string, double> weights;
  for (const WeightedTarget& t : macroTargets(p)) weights[t.name] += t.weight;
  return weights;
}

double sumWithPrefix(const std::map<std::string, double>& weights, const std::string& prefix) {
  double sum = 0;
  for (const auto& [name, w] : weights)
    if (name.rfind(prefix, 0) == 0) sum += w;
  return sum;
}

}  // namespace

TEST(MacroBlend, TheDefaultHumanBlendsBothSexesYoungAverage) {
  const auto w = byName(MacroParameters{});
  EXPECT_DOUBLE_EQ(w.at("macrodetails/universal-female-young-averagemuscle-averageweight"), 0.5);
  EXPECT_DOUBLE_EQ(w.at("macrodetails/universal-male-young-averagemuscle-averageweight"), 0.5);
  EXPECT_DOUBLE_EQ(w.at("macrodetails/caucasian-female-young"), 0.5 / 3);
  EXPECT_NEAR(sumWithPrefix(w, "macrodetails/universal-"), 1.0, 1e-15);
  // height and proportions 0.5 are the neutral anchors: no target
  EXPECT_DOUBLE_EQ(sumWithPrefix(w, "macrodetails/height/"), 0.0);
  EXPECT_DOUBLE_EQ(sumWithPrefix(w, "macrodetails/proportions/"), 0.0);
}

TEST(MacroBlend, WeightsAreProductsOfPiecewiseLinearAnchors) {
  MacroParameters p;
  p.gender = 0.25;  // female 0.75, male 0.25
  p.age = 0.75;     // young 0.5, old 0.5 (anchors 0.5 and 1)
  p.weight = 0.9;   // average 0.2, max 0.8
  p.height = 0.2;   // min 0.6, neutral 0.4
  const auto w = byName(p);
  EXPECT_NEAR(w.at("macrodetails/universal-female-old-averagemuscle-maxweight"), 0.75 * 0.5 * 1 * 0.8, 1e-15);
  EXPECT_NEAR(w.at("macrodetails/universal-male-young-averagemuscle-averageweight"), 0.25 * 0.5 * 1 * 0.2, 1e-15);
  EXPECT_NEAR(w.at("macrodetails/height/female-young-averagemuscle-maxweight-minheight"), 0.75 * 0.5 * 0.8 * 0.6,
              1e-15);
  EXPECT_NEAR(sumWithPrefix(w, "macrodetails/height/"), 0.6, 1e-15);
  EXPECT_NEAR(sumWithPrefix(w, "macrodetails/universal-"), 1.0, 1e-15);
  EXPECT_EQ(w.count("macrodetails/universal-female-child-averagemuscle-maxweight"), 0u);  // weight 0: left out
}

TEST(MacroBlend, AMaleHasNoCupSizeTargetsWithWeight) {
  MacroParameters p;
  p.gender = 1;
  p.cupSize = 1;
  for (const WeightedTarget& t : macroTargets(p)) EXPECT_EQ(t.name.find("female"), std::string::npos) << t.name;
  p.gender = 0;
  EXPECT_NEAR(sumWithPrefix(byName(p), "breast/female-young-averagemuscle-averageweight-maxcup-"), 1.0, 1e-15);
}

TEST(MacroBlend, AParameterOutsideItsRangeIsNamed) {
  MacroParameters p;
  p.muscle = 1.2;
  try {
    macroTargets(p);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("muscle"), std::string::npos) << e.what();
  }
  p.muscle = 0.5;
  p.race = {0, 0, 0};
  EXPECT_THROW(macroTargets(p), std::invalid_argument);
}
