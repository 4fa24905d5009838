#pragma once
// Sizes beyond a chart's ends and bodies between its sizes: what the made bodies are checked
// over (issue 30: the chart's body dimensions and two sizes beyond each end; issue 43: the
// chart widened to women's DOB 54 and men's HAKA 62, two sizes below each sex's smallest and
// none beyond its largest, which are past MakeHuman's reach, docs/bodies.md). A size beyond
// an end is graded by the chart's own step at that end (the last two sizes' differences in
// stature and every girth, and in the size number), so the women's DOB 32, 34, ... continue
// as 30, 28 and 44, 46 in the same 4 cm girth steps.

#include <vector>

#include "sim/garment/SizeChart.h"

namespace figment {

// One sex's sizes of `chart` with `beyond` more graded past each end, smallest first. An
// extrapolated size is named after its end's with "-1", "-2" (below) or "+1", "+2" (above):
// "XXS-2", "XL+1"; its number is the chart's number stepped on when both end numbers are
// whole numbers, else the name. Throws std::invalid_argument when the sex has fewer than two
// sizes, `beyond` < 0, or a graded size would have a dimension <= 0.
std::vector<ChartSize> gradedSizes(const SizeChart& chart, Sex sex, int beyond);
// The same with `below` sizes graded under the smallest and `above` over the largest.
std::vector<ChartSize> gradedSizes(const SizeChart& chart, Sex sex, int below, int above);

// Every size of gradedSizes(chart, sex, beyond), both sexes (women first), once for each
// stature offset (m, added to the size's stature; 0 keeps it): the in-between bodies a chart's
// sizes leave out, a short and a tall body of each size's girths.
std::vector<ChartSize> measurementSets(const SizeChart& chart, int beyond, const std::vector<double>& statureOffsets);
// The same with `below` and `above` sizes graded past each sex's ends (gradedSizes).
std::vector<ChartSize> measurementSets(const SizeChart& chart, int below, int above,
                                       const std::vector<double>& statureOffsets);

// The sets made bodies are checked over (tests/io/scenarios/test_MeasuredBodies.cpp,
// figment-bench bodies, docs/bodies.md): the chart's sizes and two more below each sex's
// smallest, each at its own stature and 8 cm shorter and taller; 78 over the shipped chart's
// 12 + 10 sizes (60 over its 6 + 6 before issue 43, with two beyond each end).
std::vector<ChartSize> bodyCheckSets(const SizeChart& chart);

}  // namespace figment
