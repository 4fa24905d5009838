#include "serve/workers/FitWorker.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/MakeHumanFiles.h"
#include "io/RecommendationJson.h"
#include "serve/request/FitRequest.h"
#include "sim/fit/SizeFitter.h"

namespace figment::serve {

namespace {

FitWorker::Answer failure(int status, const std::string& error) {
  return {status, nlohmann::json{{"error", error}}.dump()};
}

}  // namespace

FitWorker::FitWorker(SizeChart chart) : chart_(std::move(chart)) {}

FitWorker::~FitWorker() = default;

std::string FitWorker::loadModel() {
  if (human_.dir().empty()) return kMakeHumanDataMissing;
  human_.model();
  return "";
}

FitWorker::Answer FitWorker::advise(const FitRequest& request) {
  if (const std::string error = loadModel(); !error.empty()) return failure(500, error);
  // In figment-size's order (its keys sorted): the fit's least squares see the goals in
  // order, and the same body must get the same answer from the program and the service.
  const std::vector<MeasurementGoal> goals = {{"bust_girth", request.body.bust},
                                              {"hip_girth", request.body.hips},
                                              {"stature", request.body.stature},
                                              {"waist_girth", request.body.waist}};
  TriangleMesh body;
  try {
    body = human_.measuredBody(request.sex, goals).body;
  } catch (const UnreachableMeasurement& error) {
    return failure(422, std::string("no body of these measurements can be made: ") + error.what());
  }
  return {200, recommendationJson(fitter(request.style).recommend(body, request.sex))};
}

std::string FitWorker::unreachable(const BodyMeasures& body, Sex sex) {
  if (const std::string error = loadModel(); !error.empty()) throw std::runtime_error(error);
  // Made as a chart body, in HumanBody's order (nodes/body/HumanBody.cpp: goalsOf), so the
  // answer is the node's.
  try {
    human_.measuredBody(ChartSize{sex, "", "", body.stature, body.bust, body.waist, body.hips});
  } catch (const UnreachableMeasurement& error) {
    return error.what();
  }
  return "";
}

SizeFitter& FitWorker::fitter(const std::string& style) {
  std::unique_ptr<SizeFitter>& fitter = fitters_[style];
  if (!fitter) fitter = std::make_unique<SizeFitter>(human_.model(), chart_, *findStyle(style));
  return *fitter;
}

const TriangleMesh& FitWorker::garment(const std::string& style, Sex sex, const std::string& size) {
  if (const std::string error = loadModel(); !error.empty()) throw std::runtime_error(error);
  const int index = chart_.find(sex, size);
  if (!findStyle(style) || index < 0) throw std::invalid_argument("no graded garment " + style + ":" + size);
  return fitter(style).graded(sex, index).garment;
}

}  // namespace figment::serve
