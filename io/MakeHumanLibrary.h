#pragma once
// MakeHumanLibrary: MakeHuman's model as one owner uses it (a HumanBody or CatalogueGarment
// node, a service's worker, a program's run): the data folder found once, the base mesh and
// the targets a body blends read once and kept, and bodies made to measurements from them.
// Nothing is shared between libraries (no process-wide state): two owners read the data twice.

#include <memory>
#include <string>
#include <vector>

#include "sim/body/MeasuredBody.h"
#include "sim/garment/SizeChart.h"

namespace figment {

class TargetLibrary;

class MakeHumanLibrary {
 public:
  // Looks for nothing yet: a library never asked for a body costs nothing.
  MakeHumanLibrary();
  // Defined where TargetLibrary is complete. Neither copied (its unique_ptr members) nor
  // moved (a declared destructor leaves no implicit move): one library, one model.
  ~MakeHumanLibrary();

  // The data folder (findMakeHumanData), looked for until found and then kept; "" while
  // there is none.
  const std::string& dir();
  // The model, read on the first call. Throws std::runtime_error(kMakeHumanDataMissing)
  // when there is no data (looked for again on the next call), and as readHumanBase.
  const HumanModel& model();

  // A body made to `goals` from `start` (sim/body/MeasuredBody.h; the least squares see the
  // goals in their order, so an owner that must answer as another keeps its order).
  // Throws as model() and makeMeasuredBody (UnreachableMeasurement for a set out of reach).
  MeasuredBody measuredBody(const HumanParameters& start, const std::vector<MeasurementGoal>& goals);
  // The same from MakeHuman's default body of `sex` (macro gender 0 or 1).
  MeasuredBody measuredBody(Sex sex, const std::vector<MeasurementGoal>& goals);
  // A body of `size`'s sex made to its stature, bust, waist and hip girth, in that order:
  // a size's chart body, as CatalogueGarment and SizeFitter make it.
  MeasuredBody measuredBody(const ChartSize& size);

  // MakeHuman's default body of `sex`: macro gender 0 (female) or 1 (male), the rest 0.5.
  static HumanParameters start(Sex sex);
  // A chart body's goals: `size`'s stature, bust, waist and hip girth, in that order.
  static std::vector<MeasurementGoal> goals(const ChartSize& size);

 private:
  std::string dir_;
  std::unique_ptr<TargetLibrary> library_;  // declared first, so it outlives the model that looks targets up in it
  std::unique_ptr<HumanModel> model_;
};

}  // namespace figment
