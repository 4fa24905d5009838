#pragma once
// A body's four measurements as both requests take them: a render's measured body
// (RenderRequest with `sex`) and the size advice's shopper (FitRequest) accept the same
// ranges, those the size chart's bodies span widened by two sizes, and read each value the
// same way, rounded to the millimetre.

#include <optional>
#include <string>
#include <vector>

#include "serve/request/RequestParameters.h"
#include "serve/request/ShopperChoices.h"
#include "sim/garment/SizeChart.h"

namespace figment::serve {

class BodyMeasuresText {
 public:
  // The accepted range of each measurement (stature, bust, waist, hips, in that order) of a
  // measured body of `sex`: MakeHuman's adults' statures, the chart's girths two sizes wider.
  static std::vector<MeasureRange> ranges(const SizeChart& chart, Sex sex);
  // `value` read into `out` (m, rounded to the mm) when it is a number within `range`, else
  // the refusal naming `parameter` and the range.
  static std::optional<ParameterError> read(const std::string& parameter, const std::string& value,
                                            const MeasureRange& range, double& out);
};

}  // namespace figment::serve
