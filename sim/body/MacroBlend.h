#pragma once
// MakeHuman's macro parameters and the weights they give its macro targets (CC0 data,
// MPFB2's targets/macrodetails/macro.json): each parameter is a point between named anchors
// (gender: female 0, male 1; age: baby 0, child 0.1875, young 0.5, old 1; ...); a target is
// named by one anchor of each parameter of its combination
// ("macrodetails/universal-female-young-averagemuscle-maxweight") and weighs the product of
// those anchors' weights. Learned from MakeHuman's documentation and naver/anny's
// Apache-2.0 sources; our own code.

#include <array>
#include <string>
#include <vector>

namespace figment {

// Each in [0, 1]; 0.5 is MakeHuman's default human (an average young adult, age 0.5 = 25
// years, 1 = 90 years), except gender, female 0 to male 1.
struct MacroParameters {
  double gender = 0.5;
  double age = 0.5;
  double muscle = 0.5;
  double weight = 0.5;
  double height = 0.5;
  double proportions = 0.5;  // 0 uncommon, 1 ideal
  double cupSize = 0.5;      // female only (MakeHuman has no male breast targets)
  double firmness = 0.5;
  // African, Asian, Caucasian shares (each >= 0, not all 0; normalised). Default 1/3 each.
  std::array<double, 3> race{1.0 / 3, 1.0 / 3, 1.0 / 3};
};

struct WeightedTarget {
  std::string name;  // path under MPFB2's targets/, without ".target.gz"
  double weight = 0;
};

// The macro targets `p` blends with a weight above zero. A target the data lacks (MakeHuman
// has none for some combinations, e.g. a baby's proportions) adds nothing. Throws
// std::invalid_argument naming the parameter when one lies outside [0, 1].
std::vector<WeightedTarget> macroTargets(const MacroParameters& p);

}  // namespace figment
