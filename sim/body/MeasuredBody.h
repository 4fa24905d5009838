#pragma once
// A MakeHuman body made to typed measurements: the stature first (the macro height), then the
// body's mass along a path through the macro weight and muscle so that the typed girths'
// errors sum to zero, then each typed measurement moves one parameter (stature the macro
// height; a girth or length its measure target, continued past the target's range: a woman's
// bust by her cup size, the waist by the stomach's belly target, the hips by the buttocks'
// volume), solved together by Gauss-Newton with Broyden's updates of a finite-difference
// Jacobian (the measurements are near linear in them), within their ranges; the untyped
// measurements follow the macro model. A set no parameters in range reach is refused, never
// met by a distorted body. docs/bodies.md has the stages and the 60 sets it is checked on.

#include <stdexcept>
#include <string>
#include <vector>

#include "sim/body/BodyMeasurements.h"
#include "sim/body/HumanModel.h"

namespace figment {

struct MeasurementGoal {
  std::string key;  // a BodyMeasurements::named() key with a parameter (measurableKeys())
  double value;     // m
};

// The keys a goal may name, each with the parameter it moves.
const std::vector<std::pair<std::string, std::string>>& measurableKeys();

struct MeasuredBodyOptions {
  double tolerance = 0.005;  // m: each goal met within this
  int maxIterations = 12;
};

struct MeasuredBody {
  HumanParameters parameters;
  TriangleMesh body;
  BodyMeasurements achieved;
  int iterations = 0;
};

// Thrown for a set of goals no parameters in range meet: "hip_girth 0.700 m is out of
// reach: the nearest is 0.861 m".
class UnreachableMeasurement : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Starts from `start` (its macro parameters are kept but for height when stature is a goal,
// weight and muscle when a girth is, and cup size when the bust needs it; its "stomach" and
// "buttocks" measures are set when the waist or the hips need them).
// Throws std::invalid_argument for an unknown or repeated key or a value <= 0, and
// UnreachableMeasurement as above.
MeasuredBody makeMeasuredBody(const HumanModel& model, const HumanParameters& start,
                              const std::vector<MeasurementGoal>& goals, const MeasuredBodyOptions& options = {});

}  // namespace figment
