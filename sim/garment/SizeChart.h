#pragma once
// A size chart: for each sex, the sizes in order from the smallest, each with the body
// dimensions it is cut for (stature, bust or chest, waist and hip girth). The chart's body
// of a size is MakeHuman's body made to those four (sim/body/MeasuredBody.h); a graded garment
// is cut around it (sim/garment/GarmentStyle.h). Read from a file by io/SizeChartFile.h;
// the shipped chart and its source: scenes/sizes/chart.txt, docs/sizes.md.

#include <string>
#include <vector>

namespace figment {

enum class Sex { Female, Male };
const char* sexName(Sex sex);  // "female", "male"

struct ChartSize {
  Sex sex = Sex::Female;
  std::string name;                                  // the letter code: "M"
  std::string number;                                // the chart's own number: "38"
  double stature = 0, bust = 0, waist = 0, hip = 0;  // m
};

class SizeChart {
 public:
  // Throws std::invalid_argument naming the size when a sex's sizes repeat a name, do not
  // grow in every girth from one to the next, or a dimension is not positive.
  explicit SizeChart(std::vector<ChartSize> sizes);

  // One sex's sizes, smallest first.
  const std::vector<ChartSize>& sizes(Sex sex) const { return sex == Sex::Female ? women_ : men_; }
  // The index of `name` (letter code or number) in sizes(sex); -1 when there is none.
  int find(Sex sex, const std::string& name) const;
  // The size whose bust, waist and hip girths lie nearest (least sum of squares) to the given.
  int nearest(Sex sex, double bust, double waist, double hip) const;
  // The nearest size and its neighbours in the chart (one each side), smallest first.
  std::vector<int> candidates(Sex sex, double bust, double waist, double hip) const;

 private:
  std::vector<ChartSize> women_, men_;
};

}  // namespace figment
