#include "serve/workers/FitWorker.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "io/DrapeCache.h"
#include "io/DrapeRecord.h"
#include "io/GarmentCatalogue.h"
#include "io/MakeHumanFiles.h"
#include "io/RecommendationJson.h"
#include "serve/request/FitRequest.h"
#include "serve/workers/Digest.h"
#include "sim/drape/DrapeReport.h"
#include "sim/fit/SizeFitter.h"

namespace figment::serve {

namespace {

FitWorker::Answer failure(int status, const std::string& error) {
  return {status, nlohmann::json{{"error", error}}.dump()};
}

// Kept in memory at most: a worker serves a few shoppers at a time.
constexpr size_t kBodiesKept = 8, kDrapesKept = 48;

template <class T>
void bound(std::map<std::string, T>& kept, size_t most) {
  if (kept.size() > most) kept.clear();  // a worker's working set is small: start again
}

}  // namespace

FitWorker::FitWorker(SizeChart chart, const GarmentCatalogue* catalogue)
    : chart_(std::move(chart)),
      catalogue_(catalogue),
      drapeThreads_(std::max(1u, std::thread::hardware_concurrency())) {}

FitWorker::~FitWorker() = default;

std::string FitWorker::loadModel() {
  if (human_.dir().empty()) return kMakeHumanDataMissing;
  human_.model();
  return "";
}

FitWorker::Answer FitWorker::advise(const FitRequest& request) {
  if (const std::string error = loadModel(); !error.empty()) return failure(500, error);
  const TriangleMesh* body = nullptr;
  try {
    body = &madeBody(request.body, request.sex);
  } catch (const UnreachableMeasurement& error) {
    return failure(422, std::string("no body of these measurements can be made: ") + error.what());
  }
  const std::vector<ChartSize>& sizes = chart_.sizes(request.sex);
  SizeFitter& style = fitter(request.style);
  // Each candidate's one drape on this body, the one its picture draws (cold: a size's drape
  // is the same whichever was asked first), the new ones draped side by side.
  std::map<int, GarmentDrape> made =
      drapeCandidates(request.body, request.sex, request.style, style.candidates(*body, request.sex));
  const Recommendation advice = style.recommendFrom(*body, request.sex, [&](int size) {
    if (auto fresh = made.find(size); fresh != made.end()) return fresh->second;
    return sizeDrape(request.body, request.sex, request.style, sizes.at(size_t(size)).name);
  });
  return {200, recommendationJson(advice)};
}

const TriangleMesh& FitWorker::madeBody(const BodyMeasures& body, Sex sex) {
  if (const std::string error = loadModel(); !error.empty()) throw std::runtime_error(error);
  const std::string key = bodyKey(body, sex);
  if (auto kept = bodies_.find(key); kept != bodies_.end()) return kept->second;
  // As HumanBody::load makes it: its float fields' values, its goals in its order, its
  // default macros (0.5, the gender 0 or 1), at rest.
  const auto field = [](double value) { return double(float(value)); };
  HumanParameters start = MakeHumanLibrary::start(sex);
  start.macro.gender = field(start.macro.gender);
  const std::vector<MeasurementGoal> goals = {{"stature", field(body.stature)},
                                              {"bust_girth", field(body.bust)},
                                              {"waist_girth", field(body.waist)},
                                              {"hip_girth", field(body.hips)}};
  TriangleMesh made = human_.measuredBody(start, goals).body;
  bound(bodies_, kBodiesKept);
  return bodies_.emplace(key, std::move(made)).first->second;
}

void FitWorker::keepBody(const BodyMeasures& body, Sex sex, TriangleMesh mesh) {
  const std::string key = bodyKey(body, sex);
  if (bodies_.count(key)) return;
  bound(bodies_, kBodiesKept);
  bodies_.emplace(key, std::move(mesh));
}

std::string FitWorker::bodyKey(const BodyMeasures& body, Sex sex) {
  char text[96];  // to the mm, as the requests round them
  std::snprintf(text, sizeof text, "%s %.3f %.3f %.3f %.3f", sexName(sex), body.stature, body.bust, body.waist,
                body.hips);
  return text;
}

std::string FitWorker::sizeDrapeKey(const BodyMeasures& body, Sex sex, const std::string& style, int size) {
  const TriangleMesh& mesh = madeBody(body, sex);
  const std::string_view vertices(reinterpret_cast<const char*>(mesh.vertices.data()),
                                  mesh.vertices.size() * sizeof(Vec3));
  return "figment size drape 1\nbody " + bodyKey(body, sex) + " " + Digest().add(vertices).hex() + "\nstyle " + style +
         "\nsize " + chartRow(sex, size) + "\nbuild " + Digest::buildDigest() + "\n";
}

std::string FitWorker::chartRow(Sex sex, int size) const {
  const ChartSize& row = chart_.sizes(sex).at(size_t(size));
  char chart[128];
  std::snprintf(chart, sizeof chart, "%s %s %s %.4f %.4f %.4f %.4f", sexName(sex), row.name.c_str(), row.number.c_str(),
                row.stature, row.bust, row.waist, row.hip);
  return chart;
}

const TriangleMesh& FitWorker::chartBody(Sex sex, int size) {
  const auto key = std::make_pair(int(sex), size);
  if (auto made = chartBodies_.find(key); made != chartBodies_.end()) return made->second;
  ++chartBodiesMade_;
  return chartBodies_.emplace(key, SizeFitter::makeChartBody(human_.model(), chart_, sex, size)).first->second;
}

GarmentDrape FitWorker::ownDrape(const std::string& style, Sex sex, int size,
                                 const std::function<GarmentDrape()>& drape) {
  const TriangleMesh& body = chartBody(sex, size);
  const std::string_view vertices(reinterpret_cast<const char*>(body.vertices.data()),
                                  body.vertices.size() * sizeof(Vec3));
  const std::string key = "figment own drape 1\nbody " + Digest().add(vertices).hex() + "\nstyle " + style + "\nsize " +
                          chartRow(sex, size) + "\nbuild " + Digest::buildDigest() + "\n";
  std::string problem;
  if (cache_)
    if (auto record = cache_->find(key, problem))
      if (auto read = readDrapeRecord(*record, problem)) return *read;
  ++ownDrapesMade_;
  return kept(key, drape());
}

GarmentDrape FitWorker::kept(const std::string& key, GarmentDrape made) {
  made.report.verdict = verdictOf(made.report);
  // As the record keeps it (float points): the drape a worker finds in the cache later is
  // the one judged (and drawn) here, to the bit.
  std::string problem;
  const std::vector<unsigned char> record = writeDrapeRecord(made);
  made = readDrapeRecord(record, problem).value();
  if (cache_) cache_->store(key, record);  // a cache that cannot keep it costs a drape later
  return made;
}

bool FitWorker::fits(const std::string& style) const {
  if (findStyle(style)) return true;
  const CatalogueStyle* sold = catalogue_ ? catalogue_->style(style) : nullptr;
  return sold && sold->sewn();
}

int FitWorker::sizeIndex(const std::string& style, Sex sex, const std::string& size) const {
  const int index = chart_.find(sex, size);
  if (!fits(style) || index < 0) throw std::invalid_argument("no graded garment " + style + ":" + size);
  return index;
}

const GarmentDrape* FitWorker::fromCache(const std::string& key) {
  std::string problem;
  auto record = cache_->find(key, problem);
  if (!record) return nullptr;
  auto read = readDrapeRecord(*record, problem);
  if (!read) return nullptr;
  read->report.fromCache = true;
  bound(drapes_, kDrapesKept);
  return &drapes_.emplace(key, *read).first->second;
}

GarmentDrape FitWorker::sizeDrape(const BodyMeasures& body, Sex sex, const std::string& style,
                                  const std::string& size) {
  const int index = sizeIndex(style, sex, size);
  const std::string key = sizeDrapeKey(body, sex, style, index);
  if (auto kept = drapes_.find(key); kept != drapes_.end()) {
    GarmentDrape again = kept->second;
    again.report.fromCache = true;
    return again;
  }
  if (cache_)
    if (const GarmentDrape* found = fromCache(key)) return *found;
  const GarmentDrape made =
      kept(key, fitter(style).drapeOn(sex, index, std::make_shared<const MeshCollider>(madeBody(body, sex))));
  bound(drapes_, kDrapesKept);
  drapes_.emplace(key, made);
  return made;
}

std::map<int, GarmentDrape> FitWorker::drapeCandidates(const BodyMeasures& body, Sex sex, const std::string& style,
                                                       const std::vector<int>& sizes) {
  std::vector<int> missing;
  std::vector<std::string> keys;
  for (const int size : sizes) {
    const std::string key = sizeDrapeKey(body, sex, style, size);
    if (drapes_.count(key) || (cache_ && fromCache(key))) continue;
    missing.push_back(size);
    keys.push_back(key);
  }
  if (missing.size() < 2 || drapeThreads_ < 2) return {};
  SizeFitter& fitter = this->fitter(style);
  std::vector<const SizeFitter::Graded*> graded;
  for (const int size : missing) graded.push_back(&fitter.graded(sex, size));  // grading is not thread-safe
  const auto collider = std::make_shared<const MeshCollider>(madeBody(body, sex));
  std::vector<GarmentDrape> drapes(missing.size());
  std::vector<std::exception_ptr> errors(missing.size());
  // drapeThreads_ at a time: each drape is its own solver on the shared, read-only body.
  for (size_t first = 0; first < missing.size(); first += drapeThreads_) {
    std::vector<std::thread> threads;
    for (size_t i = first; i < std::min(missing.size(), first + drapeThreads_); ++i)
      threads.emplace_back([&, i] {
        try {
          drapes[i] = fitter.drapeGraded(*graded[i], sex, missing[i], collider);
        } catch (...) {
          errors[i] = std::current_exception();
        }
      });
    for (std::thread& thread : threads) thread.join();
  }
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
  std::map<int, GarmentDrape> out;
  for (size_t i = 0; i < missing.size(); ++i) {
    GarmentDrape made = kept(keys[i], std::move(drapes[i]));
    bound(drapes_, kDrapesKept);
    drapes_.emplace(keys[i], made);
    out.emplace(missing[i], std::move(made));
  }
  sideBySide_ += int(missing.size());
  return out;
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
  if (!fitter) {
    if (const figment::GarmentStyle* cut = findStyle(style)) {
      fitter = std::make_unique<SizeFitter>(human_.model(), chart_, *cut);
    } else {
      // A shop's own garment: its sizes' patterns read once (io/GarmentCatalogue.h).
      std::unique_ptr<SewnStyle>& patterns = sewn_[style];
      patterns = std::make_unique<SewnStyle>(sewnStyle(*catalogue_->style(style), chart_));
      fitter = std::make_unique<SizeFitter>(human_.model(), chart_, *patterns);
    }
    fitter->shareChartBodies([this](Sex sex, int size) { return chartBody(sex, size); });
    fitter->keepOwnDrapes([this, style](Sex sex, int size, const std::function<GarmentDrape()>& drape) {
      return ownDrape(style, sex, size, drape);
    });
  }
  return *fitter;
}

const SizeFitter::Graded& FitWorker::graded(const std::string& style, Sex sex, const std::string& size) {
  if (const std::string error = loadModel(); !error.empty()) throw std::runtime_error(error);
  return fitter(style).graded(sex, sizeIndex(style, sex, size));
}

UnsewnGarment FitWorker::cutOn(const BodyMeasures& body, Sex sex, const std::string& style, const std::string& size) {
  if (const std::string error = loadModel(); !error.empty()) throw std::runtime_error(error);
  const int index = sizeIndex(style, sex, size);
  SizeFitter& sizes = fitter(style);
  if (!sizes.sewn()) throw std::invalid_argument(style + " is cut by a generator, not sewn from a pattern");
  return sizes.cutOn(sex, index, madeBody(body, sex));
}

}  // namespace figment::serve
