// The material's derived quantities against their formulas, and its check naming the field.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/cloth/Material.h"

using namespace figment;

namespace {

TEST(Material, ArealDensityIsDensityTimesThickness) {
  Material m;
  m.thickness = 0.002;
  m.density = 500.0;
  EXPECT_DOUBLE_EQ(m.arealDensity(), 1.0);  // kg/m^2
}

TEST(Material, BendingStiffnessIsThePlateFormula) {
  Material m;
  m.thickness = 0.001;
  m.youngsModulus = 1.2e6;
  m.poissonRatio = 0.0;
  EXPECT_DOUBLE_EQ(m.bendingStiffness(), 1.2e6 * 1e-9 / 12.0);  // E h^3 / 12
  m.poissonRatio = 0.4;                                         // 1 - nu^2 = 0.84: stiffer by 1 / 0.84
  EXPECT_DOUBLE_EQ(m.bendingStiffness(), 1.2e6 * 1e-9 / (12.0 * 0.84));
}

TEST(Material, ValidateNamesTheFieldOutOfRange) {
  EXPECT_NO_THROW(Material().validate());
  Material m;
  m.poissonRatio = 0.5;
  try {
    m.validate();
    FAIL() << "poissonRatio 0.5 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "poissonRatio = 0.5 must be in (-1, 0.5)");
  }
  m = Material();
  m.density = 0;
  EXPECT_THROW(m.validate(), std::invalid_argument);
}

}  // namespace
