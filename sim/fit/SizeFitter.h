#pragma once
// A size recommendation by simulation: the candidate sizes of a style (the chart's nearest
// to the body and its neighbours) are draped on the body, their fit measured per region
// (sim/fit/GarmentFit.h) and judged (sim/fit/FitVerdict.h) against the same size on its
// own chart body; the recommendation is the smallest candidate with no region tight (the
// largest when every one is). The sizes share the body's collider, and each later drape
// starts from the nearest earlier one moved onto the new size (a warm start).
//
// A style sewn from patterns (SewnStyle: a shop's own garments, graded as one pattern per
// size) is fitted the same way, but each candidate is its size's pattern placed on the body
// that tries it on (sim/pattern/PatternPlacement.h), cut, sewn shut and draped
// (sim/drape/GarmentDrape.h), cold: its fit is measured against its flat panels (the
// sewn garment's rest shape), and the intended fit is the size's pattern sewn on its own
// chart body.

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/body/HumanModel.h"
#include "sim/cloth/ClothSolver.h"
#include "sim/cloth/RestShape.h"
#include "sim/collision/MeshCollider.h"
#include "sim/drape/GarmentDrape.h"
#include "sim/fit/FitVerdict.h"
#include "sim/fit/GarmentFit.h"
#include "sim/garment/GarmentStyle.h"
#include "sim/garment/SizeChart.h"
#include "sim/pattern/SewingPattern.h"
#include "sim/pattern/UnsewnGarment.h"

namespace figment {

// The drape every size of a cut style gets: implicit steps from 1/20 s, growing to 0.4 s
// while the cloth is quiet, at rest at 1 cm/s held 1/4 s.
ClothParameters sizeDrapeParameters(const GarmentStyle& style);
// A sewn style's, in `fabric` (a material preset; the default Material for another name):
// the same. (Its sewing and the pulling of seams left open keep 1/20 s: sim/drape/GarmentDrape.)
ClothParameters sizeDrapeParameters(const std::string& fabric);

// One size of a style sewn from patterns.
struct SizePattern {
  SewingPattern pattern;      // as read (io/PatternFile.h), placed around the body it was cut for
  double madeForStature = 0;  // m: that body's stature; 0: the same as the body trying it on
};

// A style sewn from patterns: what SizeFitter needs besides the chart.
struct SewnStyle {
  std::string fabric;                                // a material preset (sim/cloth/MaterialPresets.h)
  std::vector<std::string> regions;                  // the body regions its fit is told for (sim/fit/FitRegion.h)
  std::map<std::pair<Sex, int>, SizePattern> sizes;  // (sex, index into the chart's sizes) -> its pattern
  double spacing = 0.02;                             // m: the cloth's node spacing (sim/pattern/PatternCutting.h)
};

struct SizeFit {
  std::string size;
  std::vector<RegionFit> regions;  // of the body's regions, as measureFit gives them
  std::vector<Verdict> verdicts;   // one per region
  std::string text;                // shopperText
  // Its drape (sim/drape/GarmentDrape.h): positions per rest point (a sewn garment: per
  // panel node); a sewn garment's run counts the sewing's steps and wall time too; warm
  // when it started from an earlier size's drape.
  GarmentDrape drape;
};

struct Recommendation {
  std::string recommended;
  bool allTight = false;       // every candidate was tight somewhere: the largest is recommended
  std::vector<SizeFit> sizes;  // the candidates, smallest first
};

// Starts another size from an earlier drape, in its draped shape: graded from the same
// pattern (the same triangles), each point of `garment` starts where the earlier size's
// own point went; else where the nearest point of `earlier`'s rest surface went (its
// triangle's corners' drape by the point's barycentric weights). Then out of `body` by
// its clearance. The new size starts stretched or slack by one size step and springs to
// its own shape (docs/sizes.md: what this saves, and what moving the earlier drape by the
// sizes' offset instead did).
std::vector<Vec3> warmStart(const TriangleMesh& garment, const TriangleMesh& earlier,
                            const std::vector<Vec3>& earlierDrape, const Collider& body, double clearance);

class SizeFitter {
 public:
  // The model, chart and style must outlive the fitter.
  SizeFitter(const HumanModel& model, const SizeChart& chart, const GarmentStyle& style);
  // A style sewn from patterns; throws std::invalid_argument naming a size of the chart
  // without a pattern when asked to fit it.
  SizeFitter(const HumanModel& model, const SizeChart& chart, const SewnStyle& style);

  // A size's chart body (made to its four dimensions) and its garment, made once. Grading
  // drapes nothing: a caller that wants only the garment (a render of a size) pays for no drape.
  struct Graded {
    // A sewn style's garment is its panels cut and placed around the chart body, unsewn:
    // its triangles are the same on every body, `flat` (its flat panels) its rest shape.
    TriangleMesh body, garment;
    std::optional<RestShape> flat;
  };
  const Graded& graded(Sex sex, int size);
  // The size's garment draped on its own chart body, measured by the style's regions: the
  // intended fit a drape on another body is judged against. Draped on the first ask, then kept.
  const std::vector<RegionFit>& ownFit(Sex sex, int size);
  // A size's chart body: MakeHuman's body made to the size's four dimensions.
  static TriangleMesh makeChartBody(const HumanModel& model, const SizeChart& chart, Sex sex, int size);
  // Where a size's chart body comes from: makeChartBody by default. A caller with a fitter
  // per style (the service's worker) shares one set, as the bodies do not depend on the style.
  using ChartBodies = std::function<TriangleMesh(Sex sex, int size)>;
  void shareChartBodies(ChartBodies bodies) { chartBodies_ = std::move(bodies); }
  // Where ownFit gets a size's drape on its own chart body: `drape` makes it. By default it
  // is called; a caller that keeps drapes (the service's drape cache, shared by its workers
  // and instances) looks there first and keeps what `drape` made.
  using OwnDrapes = std::function<GarmentDrape(Sex sex, int size, const std::function<GarmentDrape()>& drape)>;
  void keepOwnDrapes(OwnDrapes drapes) { ownDrapes_ = std::move(drapes); }
  // Whether that drape has been made (a later ownFit costs nothing).
  bool hasOwnFit(Sex sex, int size) const { return ownFits_.count({static_cast<int>(sex), size}) > 0; }

  // Drapes `garment` on `body` (its collider), cold or from `start`.
  GarmentDrape drape(const TriangleMesh& garment, const std::shared_ptr<const MeshCollider>& body,
                     const std::vector<Vec3>* start = nullptr) const;
  // A sewn style's size: its pattern placed on `body`, cut, sewn and draped.
  GarmentDrape sew(Sex sex, int size, const std::shared_ptr<const MeshCollider>& body) const;
  // A sewn style's size cut and placed around `body`, unsewn (what sew starts from): the
  // same triangles as graded(sex, size).garment, its nodes where the placement puts them.
  UnsewnGarment cutOn(Sex sex, int size, const TriangleMesh& body) const;
  // A size draped cold on `body` as an advice drapes it: sewn on it, or its graded garment
  // draped (a caller that keeps the drapes of several bodies: the service's worker).
  GarmentDrape drapeOn(Sex sex, int size, const std::shared_ptr<const MeshCollider>& body);
  // Whether the style is sewn from patterns.
  bool sewn() const { return sewn_ != nullptr; }
  // The sizes a body is advised among (indices into the chart's sizes of `sex`, smallest
  // first): recommendFrom asks drapeOf for each of these.
  std::vector<int> candidates(const TriangleMesh& body, Sex sex) const;
  // A size draped cold on `body` from its graded garment (graded(sex, size), made first):
  // const, so several sizes may drape at once on threads of their own (the service's advice).
  GarmentDrape drapeGraded(const Graded& graded, Sex sex, int size,
                           const std::shared_ptr<const MeshCollider>& body) const {
    return drapeSize(graded, sex, size, body, nullptr);
  }

  // Drapes the candidate sizes on `body` and recommends one, each size from its cut shape
  // (cold), as the service does. `warm` starts each size but the nearest from its
  // neighbour's drape (a style with warmStarts): a few steps fewer, but that start is one
  // size stretched or slack, which friction keeps, and near a verdict's edge it decides
  // the verdict (over 32 women's bodies along the chart, 2 of 32 advised another size
  // warm; docs/sizes.md, "Warm starts").
  Recommendation recommend(const TriangleMesh& body, Sex sex, bool warm = false);
  // As recommend, each candidate's drape on `body` given by `drapeOf` (the size's index in
  // the chart's sizes of `sex`): a caller that keeps drapes (the service, whose pictures
  // draw the same drapes) judges the ones it keeps.
  Recommendation recommendFrom(const TriangleMesh& body, Sex sex, const std::function<GarmentDrape(int)>& drapeOf);

  // Drapes one size (cold) on `body` and judges it: what a shopper sees trying it on.
  SizeFit tryOn(const TriangleMesh& body, Sex sex, int size);

  const ClothParameters& parameters() const { return parameters_; }
  VerdictRule rule() const;
  // How a drape of a size's garment is measured (rest, its rest shape, the parameters);
  // positions and body left for the caller.
  FitInput fitInput(const Graded& graded) const;

 private:
  const Graded& grade(Sex sex, int size);
  // The candidates for `measured` (indices into the chart's sizes) and the nearest's place.
  std::vector<int> candidatesFor(const BodyMeasurements& measured, Sex sex, int& centre) const;
  std::vector<RegionFit> fitOn(const MeshCollider& collider, const std::vector<FitRegion>& regions,
                               const Graded& graded, const std::vector<Vec3>& positions) const;
  SizeFit fitSize(const Graded& graded, const std::vector<RegionFit>& own, const std::string& name,
                  const MeshCollider& collider, const std::vector<FitRegion>& regions, GarmentDrape drape) const;

  GarmentDrape drapeSize(const Graded& graded, Sex sex, int size, const std::shared_ptr<const MeshCollider>& body,
                         const std::vector<Vec3>* start) const;
  // A cold drape of the size on `body` (its collider given): the own drape again when `body`
  // is the size's chart body.
  GarmentDrape coldDrape(const Graded& graded, Sex sex, int size, const TriangleMesh& body,
                         const std::shared_ptr<const MeshCollider>& collider);
  const SizePattern& patternOf(Sex sex, int size) const;
  // The candidates for a body nearest chart size `nearest`: that size and its neighbours, among
  // the sizes this style is made in (a sewn style: those it has patterns for).
  std::vector<int> candidatesAround(Sex sex, int nearest) const;

  const HumanModel& model_;
  const SizeChart& chart_;
  const GarmentStyle* style_ = nullptr;  // a generator's style, or
  const SewnStyle* sewn_ = nullptr;      // a style sewn from patterns
  std::string fabric_;
  std::vector<std::string> regions_;
  bool warmStarts_ = false;
  ClothParameters parameters_;
  std::map<std::pair<int, int>, Graded> graded_;                   // (sex, size index) -> made
  std::map<std::pair<int, int>, std::vector<RegionFit>> ownFits_;  // (sex, size index) -> its own fit
  ChartBodies chartBodies_;
  OwnDrapes ownDrapes_;
  // (sex, size index) -> the drape its own fit was measured on, kept for coldDrape
  std::map<std::pair<int, int>, GarmentDrape> keptOwnDrapes_;
};

}  // namespace figment
