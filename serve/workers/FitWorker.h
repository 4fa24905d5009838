#pragma once
// A worker's size advice (GET /api/fit): figment-size's recommendation made in the worker
// process, with what it needs kept between requests. MakeHuman's model is read on the first
// fit request (a render-only worker never pays for it), and one SizeFitter per style keeps
// its graded sizes (each size's chart body and garment) and, once a fit needs them, their
// fit-model drapes (about 1 s each), so a later request for another body in that style only
// drapes its candidates.
//
// One body, one drape per size: the shopper's body is made as a HumanBody node makes it
// (madeBody), and each size's garment is draped on it once, cold (sizeDrape), kept in
// memory and in the worker's drape cache (on disk, shared by the workers and, with Redis,
// by the instances). The advice judges those drapes and a render of the made body at rest
// draws them, so a picture of an advised size costs a render, not a drape.

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "io/MakeHumanLibrary.h"
#include "serve/request/ShopperChoices.h"
#include "sim/core/TriangleMesh.h"
#include "sim/drape/GarmentDrape.h"
#include "sim/fit/SizeFitter.h"
#include "sim/garment/SizeChart.h"

namespace figment {
class DrapeCache;
class GarmentCatalogue;
struct SewnStyle;
}  // namespace figment

namespace figment::serve {

class FitRequest;

class FitWorker {
 public:
  // `chart` is the size chart the server checked the request against. The styles sewn from
  // patterns (a shop's own garments) come from `catalogue`, which must outlive the worker;
  // without one only the generators' styles are fitted.
  explicit FitWorker(SizeChart chart, const GarmentCatalogue* catalogue = nullptr);
  ~FitWorker();
  FitWorker(const FitWorker&) = delete;
  FitWorker& operator=(const FitWorker&) = delete;

  struct Answer {
    int status = 500;  // 200; 422 for a body MakeHuman cannot make; 500
    std::string body;  // the recommendation's JSON (io/RecommendationJson.h), or {"error": ...}
  };
  Answer advise(const FitRequest& request);
  // `style`'s garment graded to the chart's `size` of `sex` (a render's measured outfit):
  // the same garment the advice drapes (a sewn style's: its panels placed round the size's
  // chart body, and their flat shapes). Throws when MakeHuman's data is missing or the
  // style or size is unknown.
  const SizeFitter::Graded& graded(const std::string& style, Sex sex, const std::string& size);
  // A sewn style's size cut and placed around the made body of `body`, unsewn: what a
  // ClothEngine sews when the garment is not the advice's drape (an outer layer). Throws as
  // graded(), and std::invalid_argument for a style that is not sewn.
  UnsewnGarment cutOn(const BodyMeasures& body, Sex sex, const std::string& style, const std::string& size);
  // Whether `style` is one this worker fits: a generator's, or a sewn one of the catalogue.
  bool fits(const std::string& style) const;
  const SizeChart& chart() const { return chart_; }
  // Why MakeHuman cannot make a body of `body`'s measurements (the fit's one line, naming the
  // measurement and the nearest it reaches), as HumanBody fits them; "" when it can. Throws
  // when MakeHuman's data is missing.
  std::string unreachable(const BodyMeasures& body, Sex sex);

  // The body of `body`'s measurements made as a HumanBody node at rest makes it (its fields'
  // float values, its goals' order, its default macros): the mesh a render of the made body
  // draws. Kept for the last few bodies. Throws UnreachableMeasurement, and as loadModel.
  const TriangleMesh& madeBody(const BodyMeasures& body, Sex sex);
  // The text a made body is known by: the sex and each measurement to the mm.
  static std::string bodyKey(const BodyMeasures& body, Sex sex);
  // Keeps `mesh` as madeBody(body, sex): the collision surface of a HumanBody node at rest of
  // those measurements, which is the same mesh (test_FitWorker), so it is not made twice.
  void keepBody(const BodyMeasures& body, Sex sex, TriangleMesh mesh);
  // `style`'s garment of the chart's `size` draped cold on madeBody(body, sex) with the
  // advice's settings: from memory, else the drape cache, else draped and kept in both.
  // Its report says whether it came from a cache. Throws as garment() and madeBody().
  GarmentDrape sizeDrape(const BodyMeasures& body, Sex sex, const std::string& style, const std::string& size);
  // The drape cache sizeDrape keeps its drapes in (the render worker's); none: memory only.
  // The sizes' drapes on their own chart bodies (the intended fits an advice judges against,
  // which depend on no shopper) are kept there too, so a new worker or instance finds them.
  void useCache(std::shared_ptr<const DrapeCache> cache) { cache_ = std::move(cache); }

  // How many of an advice's sizes drape at once, each on a thread of its own (1: one after
  // another). By default the cores the machine has: a shopper's advice waits on its slowest
  // size, not their sum. The drapes are the same either way, to the bit (test_FitWorker).
  void drapeSizesOn(unsigned threads) { drapeThreads_ = threads < 1 ? 1 : threads; }

  // What this worker has made so far: chart bodies (one per sex and size, shared by every
  // style) and drapes of a size on its own chart body (not found in memory or the cache).
  int chartBodiesMade() const { return chartBodiesMade_; }
  int ownDrapesMade() const { return ownDrapesMade_; }
  // Size drapes made side by side on threads (drapeSizesOn), of all made so far.
  int sizesDrapedSideBySide() const { return sideBySide_; }

 private:
  // "" once the model is read, else why not.
  std::string loadModel();
  SizeFitter& fitter(const std::string& style);

  // The text that names a size drape: the body (its measurements and its mesh's digest),
  // the style, the size and its chart row, and the build.
  std::string sizeDrapeKey(const BodyMeasures& body, Sex sex, const std::string& style, int size);
  // The chart's row of a size as text, for the keys.
  std::string chartRow(Sex sex, int size) const;
  const TriangleMesh& chartBody(Sex sex, int size);
  // A size's drape on its own chart body: the cache's, else `drape`'s, kept there.
  GarmentDrape ownDrape(const std::string& style, Sex sex, int size, const std::function<GarmentDrape()>& drape);
  // `made` as the drape record keeps it (float points), stored under `key` when there is a cache.
  GarmentDrape kept(const std::string& key, GarmentDrape made);
  // The drape stored under `key` in the cache (which there must be), kept in memory and marked
  // as from a cache; null when the cache has none that reads.
  const GarmentDrape* fromCache(const std::string& key);
  // The candidates' drapes on the made body that neither memory nor the cache has, draped
  // drapeThreads_ at a time and kept; by size index. Fewer than two: none (sizeDrape drapes it).
  std::map<int, GarmentDrape> drapeCandidates(const BodyMeasures& body, Sex sex, const std::string& style,
                                              const std::vector<int>& sizes);

  // The chart's index of `size` for `style`, which must be one this worker fits; throws
  // std::invalid_argument naming the garment.
  int sizeIndex(const std::string& style, Sex sex, const std::string& size) const;

  SizeChart chart_;
  const GarmentCatalogue* catalogue_ = nullptr;
  std::map<std::string, std::unique_ptr<SewnStyle>> sewn_;      // by style: read on first use
  MakeHumanLibrary human_;                                      // the worker's: read on its first fit request
  std::map<std::string, std::unique_ptr<SizeFitter>> fitters_;  // by style
  std::map<std::string, TriangleMesh> bodies_;                  // by sex and measurements: the last few
  std::map<std::string, GarmentDrape> drapes_;                  // by sizeDrapeKey: the last few dozen
  std::map<std::pair<int, int>, TriangleMesh> chartBodies_;     // by sex and size index
  std::shared_ptr<const DrapeCache> cache_;
  int chartBodiesMade_ = 0, ownDrapesMade_ = 0;
  unsigned drapeThreads_ = 1;
  int sideBySide_ = 0;
};

}  // namespace figment::serve
