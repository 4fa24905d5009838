#pragma once
// The small size charts the sim and serve tests build in code (tests/sim/garment/
// test_SizeChart.cpp, test_SizeGrading.cpp, tests/serve/test_FitRequest.cpp): rows of the
// German charts (EN 13402-3's 4 cm steps), women's S to L and men's M to XXL, each test
// taking the run of sizes its assertions are about.

#include <vector>

#include "sim/garment/SizeChart.h"

namespace figment::test {

// The women's first `women` of S, M, L (36-40, stature 1.68 m), then the men's `men` from
// the `firstMan`th of M, L, XL, XXL (48-54), in that order.
inline SizeChart smallSizeChart(int women, int firstMan, int men) {
  const std::vector<ChartSize> female = {{Sex::Female, "S", "36", 1.68, 0.84, 0.68, 0.92},
                                         {Sex::Female, "M", "38", 1.68, 0.88, 0.72, 0.96},
                                         {Sex::Female, "L", "40", 1.68, 0.92, 0.76, 1.00}};
  const std::vector<ChartSize> male = {{Sex::Male, "M", "48", 1.74, 0.96, 0.84, 1.00},
                                       {Sex::Male, "L", "50", 1.77, 1.00, 0.88, 1.04},
                                       {Sex::Male, "XL", "52", 1.80, 1.04, 0.92, 1.08},
                                       {Sex::Male, "XXL", "54", 1.82, 1.08, 0.98, 1.12}};
  std::vector<ChartSize> sizes(female.begin(), female.begin() + women);
  sizes.insert(sizes.end(), male.begin() + firstMan, male.begin() + firstMan + men);
  return SizeChart(std::move(sizes));
}

}  // namespace figment::test
