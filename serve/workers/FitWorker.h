#pragma once
// A worker's size advice (GET /api/fit): figment-size's recommendation made in the worker
// process, with what it needs kept between requests. MakeHuman's model is read on the first
// fit request (a render-only worker never pays for it), and one SizeFitter per style keeps
// its graded sizes (each size's chart body and garment) and, once a fit needs them, their
// fit-model drapes (about 1 s each), so a later request for another body in that style only
// drapes its candidates. A render of a measured outfit takes the graded garment alone: no drape.

#include <map>
#include <memory>
#include <string>

#include "io/MakeHumanLibrary.h"
#include "serve/request/ShopperChoices.h"
#include "sim/core/TriangleMesh.h"
#include "sim/garment/SizeChart.h"

namespace figment {
class SizeFitter;
}  // namespace figment

namespace figment::serve {

class FitRequest;

class FitWorker {
 public:
  // `chart` is the size chart the server checked the request against.
  explicit FitWorker(SizeChart chart);
  ~FitWorker();
  FitWorker(const FitWorker&) = delete;
  FitWorker& operator=(const FitWorker&) = delete;

  struct Answer {
    int status = 500;  // 200; 422 for a body MakeHuman cannot make; 500
    std::string body;  // the recommendation's JSON (io/RecommendationJson.h), or {"error": ...}
  };
  Answer advise(const FitRequest& request);
  // `style`'s garment graded to the chart's `size` of `sex` (a render's measured outfit):
  // the same garment the advice drapes. Throws when MakeHuman's data is missing or the
  // style or size is unknown.
  const TriangleMesh& garment(const std::string& style, Sex sex, const std::string& size);
  const SizeChart& chart() const { return chart_; }
  // Why MakeHuman cannot make a body of `body`'s measurements (the fit's one line, naming the
  // measurement and the nearest it reaches), as HumanBody fits them; "" when it can. Throws
  // when MakeHuman's data is missing.
  std::string unreachable(const BodyMeasures& body, Sex sex);

 private:
  // "" once the model is read, else why not.
  std::string loadModel();
  SizeFitter& fitter(const std::string& style);

  SizeChart chart_;
  MakeHumanLibrary human_;                                      // the worker's: read on its first fit request
  std::map<std::string, std::unique_ptr<SizeFitter>> fitters_;  // by style
};

}  // namespace figment::serve
