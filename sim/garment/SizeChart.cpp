#include "sim/garment/SizeChart.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {

std::string label(const ChartSize& size) {
  return std::string(sexName(size.sex)) + " " + size.name;
}

void check(const std::vector<ChartSize>& sizes) {
  for (size_t i = 0; i < sizes.size(); ++i) {
    const ChartSize& s = sizes[i];
    for (const double value : {s.stature, s.bust, s.waist, s.hip})
      if (!(value > 0)) throw std::invalid_argument("size " + label(s) + ": " + formatNumber(value) + " is not > 0");
    for (size_t j = 0; j < i; ++j)
      if (sizes[j].name == s.name || sizes[j].number == s.number)
        throw std::invalid_argument("size " + label(s) + " appears twice");
    // A chart's sizes grow: the recommendation's candidates are neighbours by index.
    if (i > 0 && !(s.bust > sizes[i - 1].bust && s.waist > sizes[i - 1].waist && s.hip > sizes[i - 1].hip))
      throw std::invalid_argument("size " + label(s) + " is not larger than " + sizes[i - 1].name + " in every girth");
  }
}

}  // namespace

const char* sexName(Sex sex) {
  return sex == Sex::Female ? "female" : "male";
}

SizeChart::SizeChart(std::vector<ChartSize> sizes) {
  for (ChartSize& size : sizes) (size.sex == Sex::Female ? women_ : men_).push_back(std::move(size));
  check(women_);
  check(men_);
}

int SizeChart::find(Sex sex, const std::string& name) const {
  const std::vector<ChartSize>& list = sizes(sex);
  for (size_t i = 0; i < list.size(); ++i)
    if (list[i].name == name || list[i].number == name) return static_cast<int>(i);
  return -1;
}

int SizeChart::nearest(Sex sex, double bust, double waist, double hip) const {
  const std::vector<ChartSize>& list = sizes(sex);
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < list.size(); ++i) {
    const double db = list[i].bust - bust, dw = list[i].waist - waist, dh = list[i].hip - hip;
    if (const double d = db * db + dw * dw + dh * dh; d < bestDistance) bestDistance = d, best = static_cast<int>(i);
  }
  return best;
}

std::vector<int> SizeChart::candidates(Sex sex, double bust, double waist, double hip) const {
  const int centre = nearest(sex, bust, waist, hip);
  if (centre < 0) return {};
  const int count = static_cast<int>(sizes(sex).size());
  std::vector<int> out;
  for (int i = std::max(0, centre - 1); i <= std::min(count - 1, centre + 1); ++i) out.push_back(i);
  return out;
}

}  // namespace figment
