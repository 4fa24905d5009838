#include "sim/garment/SizeGrading.h"

#include <charconv>
#include <stdexcept>
#include <string>

namespace figment {

namespace {

bool wholeNumber(const std::string& text, int& value) {
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  return error == std::errc() && stop == end;
}

// The size `k` steps (of `from` minus `towards`) beyond `from`, named after it.
ChartSize graded(const ChartSize& from, const ChartSize& towards, int k) {
  ChartSize size = from;
  size.stature += k * (from.stature - towards.stature);
  size.bust += k * (from.bust - towards.bust);
  size.waist += k * (from.waist - towards.waist);
  size.hip += k * (from.hip - towards.hip);
  int a = 0, b = 0;
  const bool below = from.bust < towards.bust;
  size.name = from.name + (below ? "-" : "+") + std::to_string(k);
  size.number =
      wholeNumber(from.number, a) && wholeNumber(towards.number, b) ? std::to_string(a + k * (a - b)) : size.name;
  for (const double value : {size.stature, size.bust, size.waist, size.hip})
    if (!(value > 0))
      throw std::invalid_argument("size " + size.name + " graded beyond the chart has a dimension <= 0");
  return size;
}

}  // namespace

std::vector<ChartSize> gradedSizes(const SizeChart& chart, Sex sex, int below, int above) {
  const std::vector<ChartSize>& sizes = chart.sizes(sex);
  if (sizes.size() < 2)
    throw std::invalid_argument(std::string("the chart's ") + sexName(sex) + " sizes are too few to grade beyond");
  for (const int beyond : {below, above})
    if (beyond < 0) throw std::invalid_argument("sizes beyond the chart: " + std::to_string(beyond) + " < 0");
  std::vector<ChartSize> out;
  for (int k = below; k >= 1; --k) out.push_back(graded(sizes[0], sizes[1], k));
  out.insert(out.end(), sizes.begin(), sizes.end());
  const size_t n = sizes.size();
  for (int k = 1; k <= above; ++k) out.push_back(graded(sizes[n - 1], sizes[n - 2], k));
  return out;
}

std::vector<ChartSize> gradedSizes(const SizeChart& chart, Sex sex, int beyond) {
  return gradedSizes(chart, sex, beyond, beyond);
}

std::vector<ChartSize> measurementSets(const SizeChart& chart, int beyond, const std::vector<double>& statureOffsets) {
  return measurementSets(chart, beyond, beyond, statureOffsets);
}

std::vector<ChartSize> measurementSets(const SizeChart& chart, int below, int above,
                                       const std::vector<double>& statureOffsets) {
  std::vector<ChartSize> sets;
  for (const Sex sex : {Sex::Female, Sex::Male})
    for (const ChartSize& size : gradedSizes(chart, sex, below, above))
      for (const double offset : statureOffsets) {
        ChartSize set = size;
        set.stature += offset;
        if (!(set.stature > 0)) throw std::invalid_argument("size " + set.name + ": stature <= 0 with its offset");
        sets.push_back(set);
      }
  return sets;
}

std::vector<ChartSize> bodyCheckSets(const SizeChart& chart) {
  return measurementSets(chart, 2, 0, {-0.08, 0.0, 0.08});
}

}  // namespace figment
