// Fabric presets: each one valid, in the ranges its comments document (areal density,
// KES-F thickness and bending rigidity), usable by an explicit solver, and ordered as
// the fabrics are (denim heavier and stiffer than silk).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "sim/cloth/MaterialPresets.h"

using namespace figment;

namespace {
struct Range {
  double low, high;
};
struct Expected {
  Range arealDensity;  // kg/m^2
  Range thickness;     // m
  Range bending;       // D, N.m, from KES-F B in gf.cm^2/cm
};
constexpr double kGfCm = 9.80665e-5;  // 1 gf.cm^2/cm in N.m

const std::map<std::string, Expected>& documented() {
  static const std::map<std::string, Expected> ranges = {
      {"cotton", {{0.110, 0.150}, {0.25e-3, 0.35e-3}, {0.05 * kGfCm, 0.15 * kGfCm}}},
      {"silk", {{0.060, 0.090}, {0.15e-3, 0.30e-3}, {0.01 * kGfCm, 0.03 * kGfCm}}},
      {"denim", {{0.350, 0.450}, {0.70e-3, 1.00e-3}, {0.3 * kGfCm, 1.5 * kGfCm}}},
      {"jersey", {{0.150, 0.200}, {0.50e-3, 0.70e-3}, {0.02 * kGfCm, 0.08 * kGfCm}}},
  };
  return ranges;
}
}  // namespace

TEST(MaterialPresets, NamesAreTheDocumentedOnesInLowerCase) {
  const std::vector<std::string> names = materialPresetNames();
  EXPECT_EQ(names, (std::vector<std::string>{"cotton", "silk", "denim", "jersey"}));
  for (const std::string& name : names) {
    for (char ch : name) EXPECT_TRUE(ch >= 'a' && ch <= 'z') << name;
    EXPECT_TRUE(materialPreset(name).has_value()) << name;
  }
}

TEST(MaterialPresets, EveryPresetValidatesAndLiesInItsDocumentedRanges) {
  for (const std::string& name : materialPresetNames()) {
    SCOPED_TRACE(name);
    const Material m = *materialPreset(name);
    EXPECT_NO_THROW(m.validate());
    const Expected& e = documented().at(name);
    EXPECT_GE(m.arealDensity(), e.arealDensity.low);
    EXPECT_LE(m.arealDensity(), e.arealDensity.high);
    EXPECT_GE(m.thickness, e.thickness.low);
    EXPECT_LE(m.thickness, e.thickness.high);
    EXPECT_GE(m.bendingStiffness(), e.bending.low);
    EXPECT_LE(m.bendingStiffness(), e.bending.high);
    // Effective fabric moduli (0.1-10 MPa), far below fibre moduli (cotton ~5-10 GPa).
    EXPECT_GE(m.youngsModulus, 1e5);
    EXPECT_LE(m.youngsModulus, 1e7);
    // Bulk density of a fabric: fibre (1300-1550 kg/m^3) plus air.
    EXPECT_GT(m.density, 100.0);
    EXPECT_LT(m.density, 1000.0);
    EXPECT_GT(m.poissonRatio, 0.0);
    EXPECT_LT(m.poissonRatio, 0.5);
  }
}

TEST(MaterialPresets, WaveSpeedKeepsTheExplicitTimeStepUsable) {
  for (const std::string& name : materialPresetNames()) {
    const Material m = *materialPreset(name);
    EXPECT_NEAR(membraneWaveSpeed(m), std::sqrt(m.youngsModulus / m.density), 1e-12) << name;
    EXPECT_LE(membraneWaveSpeed(m), kMaxPresetWaveSpeed) << name;
  }
}

TEST(MaterialPresets, DenimIsHeavierAndStifferThanSilk) {
  const Material denim = *materialPreset("denim"), silk = *materialPreset("silk");
  const Material cotton = *materialPreset("cotton"), jersey = *materialPreset("jersey");
  EXPECT_GT(denim.arealDensity(), 4.0 * silk.arealDensity());
  EXPECT_GT(denim.bendingStiffness(), 10.0 * silk.bendingStiffness());
  EXPECT_GT(denim.thickness, silk.thickness);
  // Shirting sits between them; a knit stretches far more easily than any woven.
  EXPECT_GT(cotton.bendingStiffness(), silk.bendingStiffness());
  EXPECT_LT(cotton.bendingStiffness(), denim.bendingStiffness());
  for (const Material& woven : {cotton, silk, denim})
    EXPECT_LT(jersey.youngsModulus * jersey.thickness, woven.youngsModulus * woven.thickness);
}

TEST(MaterialPresets, UnknownNamesGiveNothing) {
  EXPECT_FALSE(materialPreset("kevlar").has_value());
  EXPECT_FALSE(materialPreset("").has_value());
  EXPECT_FALSE(materialPreset("Cotton").has_value());  // names are lower case
}
