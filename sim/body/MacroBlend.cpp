// MakeHuman's macro target weights. Based on MPFB2's macro.json (CC0): each parameter is
// piecewise linear between its anchors, so at most two anchors weigh above zero; a
// combination's target weighs the product of its anchors' weights (a multilinear blend),
// and an anchor with no name ("" at height 0.5, proportions 0.5) means no target.

#include "sim/body/MacroBlend.h"

#include <stdexcept>
#include <utility>

namespace figment {

namespace {

struct Anchor {
  double at;
  const char* name;  // "" = the neutral body: no target
};
using Weights = std::vector<std::pair<std::string, double>>;

Weights anchorWeights(const char* parameter, double value, const std::vector<Anchor>& anchors) {
  if (!(value >= 0.0 && value <= 1.0))
    throw std::invalid_argument(std::string(parameter) + " = " + std::to_string(value) + " is outside [0, 1]");
  for (size_t i = 0; i + 1 < anchors.size(); ++i) {
    const Anchor& a = anchors[i];
    const Anchor& b = anchors[i + 1];
    if (value > b.at) continue;
    const double t = (value - a.at) / (b.at - a.at);
    Weights w;
    if (t < 1) w.emplace_back(a.name, 1 - t);
    if (t > 0) w.emplace_back(b.name, t);
    return w;
  }
  return {{anchors.back().name, 1.0}};
}

// Appends every combination of one entry from each list, its name joined with '-'.
void combine(const std::string& prefix, const std::vector<Weights>& parts, size_t next, const std::string& name,
             double weight, std::vector<WeightedTarget>& out) {
  if (next == parts.size()) {
    out.push_back({prefix + name, weight});
    return;
  }
  for (const auto& [anchor, w] : parts[next]) {
    if (anchor.empty()) continue;  // the neutral anchor has no target
    combine(prefix, parts, next + 1, name.empty() ? anchor : name + "-" + anchor, weight * w, out);
  }
}

Weights raceWeights(const std::array<double, 3>& race) {
  const double sum = race[0] + race[1] + race[2];
  if (!(race[0] >= 0 && race[1] >= 0 && race[2] >= 0 && sum > 0))
    throw std::invalid_argument("race shares must be >= 0 and not all 0");
  return {{"african", race[0] / sum}, {"asian", race[1] / sum}, {"caucasian", race[2] / sum}};
}

}  // namespace

std::vector<WeightedTarget> macroTargets(const MacroParameters& p) {
  const Weights gender = anchorWeights("gender", p.gender, {{0, "female"}, {1, "male"}});
  const Weights age = anchorWeights("age", p.age, {{0, "baby"}, {0.1875, "child"}, {0.5, "young"}, {1, "old"}});
  const std::vector<Anchor> levels = {{0, "min"}, {0.5, "average"}, {1, "max"}};
  const auto suffixed = [](Weights w, const char* suffix) {
    for (auto& entry : w) entry.first += suffix;
    return w;
  };
  const Weights muscle = suffixed(anchorWeights("muscle", p.muscle, levels), "muscle");
  const Weights weight = suffixed(anchorWeights("weight", p.weight, levels), "weight");
  const Weights height = anchorWeights("height", p.height, {{0, "minheight"}, {0.5, ""}, {1, "maxheight"}});
  const Weights proportions =
      anchorWeights("proportions", p.proportions, {{0, "uncommonproportions"}, {0.5, ""}, {1, "idealproportions"}});
  const Weights cup = suffixed(anchorWeights("cupSize", p.cupSize, levels), "cup");
  const Weights firmness = suffixed(anchorWeights("firmness", p.firmness, levels), "firmness");

  std::vector<WeightedTarget> targets;
  combine("macrodetails/", {raceWeights(p.race), gender, age}, 0, "", 1.0, targets);
  combine("macrodetails/universal-", {gender, age, muscle, weight}, 0, "", 1.0, targets);
  combine("macrodetails/proportions/", {gender, age, muscle, weight, proportions}, 0, "", 1.0, targets);
  combine("macrodetails/height/", {gender, age, muscle, weight, height}, 0, "", 1.0, targets);
  combine("breast/", {gender, age, muscle, weight, cup, firmness}, 0, "", 1.0, targets);
  std::erase_if(targets, [](const WeightedTarget& t) { return t.weight <= 0; });
  return targets;
}

}  // namespace figment
