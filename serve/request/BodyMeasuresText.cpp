#include "serve/request/BodyMeasuresText.h"

#include <cmath>
#include <cstdio>

namespace figment::serve {

namespace {

constexpr double kBeyondChart = 0.08;                     // m: two of the chart's 4 cm steps each side
constexpr double kMinStature = 1.45, kMaxStature = 1.95;  // m: MakeHuman's adults at default age

double rounded(double metres) {
  return std::round(metres * 1000.0) / 1000.0;  // mm
}

}  // namespace

std::vector<MeasureRange> BodyMeasuresText::ranges(const SizeChart& chart, Sex sex) {
  const std::vector<ChartSize>& sizes = chart.sizes(sex);
  const ChartSize& small = sizes.front();
  const ChartSize& large = sizes.back();
  return {{"stature", kMinStature, kMaxStature, 0},
          {"bust", rounded(small.bust - kBeyondChart), rounded(large.bust + kBeyondChart), 0},
          {"waist", rounded(small.waist - kBeyondChart), rounded(large.waist + kBeyondChart), 0},
          {"hips", rounded(small.hip - kBeyondChart), rounded(large.hip + kBeyondChart), 0}};
}

std::optional<ParameterError> BodyMeasuresText::read(const std::string& parameter, const std::string& value,
                                                     const MeasureRange& range, double& out) {
  char accepted[96];
  std::snprintf(accepted, sizeof accepted, "%.2f to %.2f (metres)", range.minimum, range.maximum);
  double v = 0;
  if (!RequestParameters::number(value, v))
    return RequestParameters::refusal(parameter, value, "not a number", accepted);
  if (v < range.minimum || v > range.maximum)
    return RequestParameters::refusal(parameter, value, "out of range", accepted);
  out = rounded(v);
  return std::nullopt;
}

}  // namespace figment::serve
