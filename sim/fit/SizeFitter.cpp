#include "sim/fit/SizeFitter.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "sim/body/BodyMeasurements.h"
#include "sim/body/MeasuredBody.h"
#include "sim/cloth/MaterialPresets.h"
#include "sim/collision/MeshCollider.h"
#include "sim/collision/TriangleBvh.h"
#include "sim/drape/GarmentDrape.h"
#include "sim/pattern/PatternCutting.h"
#include "sim/pattern/PatternPlacement.h"
#include "sim/pattern/Sewing.h"

namespace figment {

namespace {

constexpr double kPushOutSearch = 0.10;  // m a warm start's node is looked for inside the body

// The order the candidates are draped in: the nearest size (the middle one when there are
// three) first, cold; then outward, each from the drape next to it.
std::vector<int> drapeOrder(int count, int nearest) {
  std::vector<int> order = {nearest};
  for (int step = 1; step < count; ++step)
    for (const int i : {nearest + step, nearest - step})
      if (i >= 0 && i < count) order.push_back(i);
  return order;
}

// The body's regions the style's fit is told for, in the body's order.
std::vector<FitRegion> styleRegions(const TriangleMesh& body, const BodyMeasurements& measured, Sex sex,
                                    const std::vector<std::string>& told) {
  std::vector<FitRegion> regions;
  for (FitRegion& region : bodyRegions(body, measured, sex == Sex::Female))
    if (std::find(told.begin(), told.end(), region.name) != told.end()) regions.push_back(std::move(region));
  return regions;
}

// The barycentric weights of `p` (on the triangle) in triangle (a, b, c).
Vec3 barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a, d = p - a;
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2), dp1 = d.dot(e1), dp2 = d.dot(e2);
  const double denominator = d11 * d22 - d12 * d12;
  if (denominator <= 0) return Vec3(1, 0, 0);  // a degenerate section: its first corner
  const double v = (d22 * dp1 - d12 * dp2) / denominator, w = (d11 * dp2 - d12 * dp1) / denominator;
  return Vec3(1 - v - w, v, w);
}

// Where the point of `earlier`'s rest surface nearest `p` went in its drape.
Vec3 interpolated(const TriangleBvh& earlierRest, const TriangleMesh& earlier, const std::vector<Vec3>& earlierDrape,
                  const Vec3& p) {
  const ClosestPoint nearest = earlierRest.closest(p);
  const Triangle& t = earlier.triangles[nearest.triangle];
  const Vec3 w = barycentric(nearest.point, earlier.vertices[t[0]], earlier.vertices[t[1]], earlier.vertices[t[2]]);
  return w[0] * earlierDrape[t[0]] + w[1] * earlierDrape[t[1]] + w[2] * earlierDrape[t[2]];
}

HumanParameters sexStart(Sex sex) {
  HumanParameters start;
  start.macro.gender = sex == Sex::Male ? 1.0 : 0.0;
  return start;
}

}  // namespace

ClothParameters sizeDrapeParameters(const GarmentStyle& style) {
  return sizeDrapeParameters(std::string(style.fabric));
}

ClothParameters sizeDrapeParameters(const std::string& fabric) {
  ClothParameters p;
  p.material = materialPreset(fabric).value_or(Material{});
  p.integrator = Integrator::Implicit;
  p.timeStep = 0.05;
  p.implicitSolver.maxTimeStep = ImplicitSolverParameters::kShippedMaxTimeStep;
  // A flared skirt slides from the waist to the hips for up to 8 s on the chart's end
  // bodies (test_SixBodyDrapes); the drape stops as soon as it rests, so the bound costs
  // only the drapes that need it.
  p.maxTime = 10.0;
  p.rest = {0.01, 0.25};
  p.friction = 0.5;
  p.clearance = 0.003;
  return p;
}

std::vector<Vec3> warmStart(const TriangleMesh& garment, const TriangleMesh& earlier,
                            const std::vector<Vec3>& earlierDrape, const Collider& body, double clearance) {
  // Graded from one pattern (the same triangles): each point starts where its own went.
  const bool samePattern = garment.triangles == earlier.triangles;
  const TriangleBvh earlierRest = samePattern ? TriangleBvh() : TriangleBvh(earlier);
  std::vector<Vec3> start(garment.vertices.size());
  for (size_t i = 0; i < garment.vertices.size(); ++i) {
    start[i] = samePattern ? earlierDrape[i] : interpolated(earlierRest, earlier, earlierDrape, garment.vertices[i]);
    Contact contact;
    if (body.contact(start[i], clearance, kPushOutSearch, contact) && contact.distance < clearance)
      start[i] = contact.surfacePoint + 1.5 * clearance * contact.normal;
  }
  return start;
}

SizeFitter::SizeFitter(const HumanModel& model, const SizeChart& chart, const GarmentStyle& style)
    : model_(model),
      chart_(chart),
      style_(&style),
      fabric_(style.fabric),
      regions_(style.regions),
      warmStarts_(style.warmStarts),
      parameters_(sizeDrapeParameters(style)) {}

SizeFitter::SizeFitter(const HumanModel& model, const SizeChart& chart, const SewnStyle& style)
    : model_(model),
      chart_(chart),
      sewn_(&style),
      fabric_(style.fabric),
      regions_(style.regions),
      // Unsewn panels cannot start from another size's sewn drape: each is sewn cold.
      warmStarts_(false),
      parameters_(sizeDrapeParameters(style.fabric)) {}

VerdictRule SizeFitter::rule() const {
  VerdictRule rule{fabricLimits(fabric_)};
  rule.stretchAgainstIntended = sewn_ != nullptr;  // a graded pattern's own fit is its maker's
  return rule;
}

const SizePattern& SizeFitter::patternOf(Sex sex, int size) const {
  const auto found = sewn_->sizes.find({sex, size});
  if (found == sewn_->sizes.end())
    throw std::invalid_argument(std::string("sewn style: no pattern for the ") + sexName(sex) + " size " +
                                chart_.sizes(sex).at(size).name);
  return found->second;
}

FitInput SizeFitter::fitInput(const Graded& graded) const {
  FitInput input;
  input.rest = &graded.garment;
  input.restShape = graded.flat ? &*graded.flat : nullptr;
  input.parameters = parameters_;
  return input;
}

const SizeFitter::Graded& SizeFitter::graded(Sex sex, int size) {
  return grade(sex, size);
}

TriangleMesh SizeFitter::makeChartBody(const HumanModel& model, const SizeChart& chart, Sex sex, int size) {
  const ChartSize& chartSize = chart.sizes(sex).at(size);
  const std::vector<MeasurementGoal> goals = {{"stature", chartSize.stature},
                                              {"bust_girth", chartSize.bust},
                                              {"waist_girth", chartSize.waist},
                                              {"hip_girth", chartSize.hip}};
  return makeMeasuredBody(model, sexStart(sex), goals).body;
}

const SizeFitter::Graded& SizeFitter::grade(Sex sex, int size) {
  const auto key = std::make_pair(static_cast<int>(sex), size);
  if (const auto found = graded_.find(key); found != graded_.end()) return found->second;
  Graded made;
  made.body = chartBodies_ ? chartBodies_(sex, size) : makeChartBody(model_, chart_, sex, size);
  if (style_) {
    made.garment = cutGarment(*style_, made.body);
  } else {
    const UnsewnGarment cut = cutOn(sex, size, made.body);
    made.garment = cut.placed;
    made.flat = panelsAtRest(cut);
  }
  return graded_.emplace(key, std::move(made)).first->second;
}

const std::vector<RegionFit>& SizeFitter::ownFit(Sex sex, int size) {
  const auto key = std::make_pair(static_cast<int>(sex), size);
  if (const auto found = ownFits_.find(key); found != ownFits_.end()) return found->second;
  const Graded& made = grade(sex, size);
  const auto collider = std::make_shared<const MeshCollider>(made.body);
  const auto drapeOwn = [&] { return drapeSize(made, sex, size, collider, nullptr); };
  const GarmentDrape& own =
      keptOwnDrapes_.emplace(key, ownDrapes_ ? ownDrapes_(sex, size, drapeOwn) : drapeOwn()).first->second;
  return ownFits_
      .emplace(key,
               fitOn(*collider, styleRegions(made.body, measureBody(made.body), sex, regions_), made, own.positions))
      .first->second;
}

GarmentDrape SizeFitter::coldDrape(const Graded& graded, Sex sex, int size, const TriangleMesh& body,
                                   const std::shared_ptr<const MeshCollider>& collider) {
  // The size's own chart body: its cold drape there is the one its own fit was measured on
  // (the same garment, body and parameters). A chart body is recommended among its own size
  // and its neighbours, so without this every chart body's own size was draped twice.
  if (body.vertices == graded.body.vertices && body.triangles == graded.body.triangles) {
    ownFit(sex, size);
    return keptOwnDrapes_.at({static_cast<int>(sex), size});
  }
  return drapeSize(graded, sex, size, collider, nullptr);
}

GarmentDrape SizeFitter::drapeSize(const Graded& graded, Sex sex, int size,
                                   const std::shared_ptr<const MeshCollider>& body,
                                   const std::vector<Vec3>* start) const {
  return sewn_ ? sew(sex, size, body) : drape(graded.garment, body, start);
}

UnsewnGarment SizeFitter::cutOn(Sex sex, int size, const TriangleMesh& body) const {
  if (!sewn_) throw std::logic_error("SizeFitter::cutOn: the style is not sewn from patterns");
  const SizePattern& pattern = patternOf(sex, size);
  return cutPattern(placed(pattern.pattern, placementOn(body, pattern.madeForStature)), sewn_->spacing);
}

GarmentDrape SizeFitter::drapeOn(Sex sex, int size, const std::shared_ptr<const MeshCollider>& body) {
  return drapeSize(grade(sex, size), sex, size, body, nullptr);
}

GarmentDrape SizeFitter::sew(Sex sex, int size, const std::shared_ptr<const MeshCollider>& body) const {
  const UnsewnGarment cut = cutOn(sex, size, body->surface());
  DrapeRequest request;
  request.garment = cut.placed;
  request.parameters = parameters_;
  request.body = body;
  request.sewing = DrapeSewing{cut.flat, cut.seams, {}};
  const GarmentDrape drape = drapeGarment(request);
  GarmentDrape out = drape;
  if (drape.sewing) {
    out.report.run.iterations += drape.sewing->run.iterations;
    out.report.run.wallSeconds += drape.sewing->run.wallSeconds;
  }
  return out;
}

GarmentDrape SizeFitter::drape(const TriangleMesh& garment, const std::shared_ptr<const MeshCollider>& body,
                               const std::vector<Vec3>* start) const {
  ClothSolver solver(garment, parameters_, body);
  if (start) solver.resume(*start, std::vector<Vec3>(start->size(), Vec3::Zero()), 0.0, 0);
  GarmentDrape out;
  out.report.run = solver.run();
  out.positions = solver.positions();
  out.report.warm = start != nullptr;
  return out;
}

std::vector<RegionFit> SizeFitter::fitOn(const MeshCollider& collider, const std::vector<FitRegion>& regions,
                                         const Graded& graded, const std::vector<Vec3>& positions) const {
  FitInput input = fitInput(graded);
  input.positions = &positions;
  input.body = &collider;
  return measureFit(input, regions);
}

SizeFit SizeFitter::fitSize(const Graded& graded, const std::vector<RegionFit>& own, const std::string& name,
                            const MeshCollider& collider, const std::vector<FitRegion>& regions,
                            GarmentDrape drape) const {
  SizeFit fit;
  fit.size = name;
  fit.regions = fitOn(collider, regions, graded, drape.positions);
  for (size_t r = 0; r < fit.regions.size(); ++r) fit.verdicts.push_back(judge(fit.regions[r], own[r], rule()));
  fit.text = shopperText(fit.regions, own, fit.verdicts, rule());
  fit.drape = std::move(drape);
  return fit;
}

SizeFit SizeFitter::tryOn(const TriangleMesh& body, Sex sex, int size) {
  const Graded& graded = grade(sex, size);
  const auto collider = std::make_shared<const MeshCollider>(body);
  const std::vector<FitRegion> regions = styleRegions(body, measureBody(body), sex, regions_);
  GarmentDrape drape = coldDrape(graded, sex, size, body, collider);
  return fitSize(graded, ownFit(sex, size), chart_.sizes(sex).at(size).name, *collider, regions, std::move(drape));
}

std::vector<int> SizeFitter::candidatesAround(Sex sex, int nearest) const {
  std::vector<int> offered;  // the chart's sizes this style is made in, smallest first
  for (int k = 0; k < static_cast<int>(chart_.sizes(sex).size()); ++k)
    if (!sewn_ || sewn_->sizes.count({sex, k})) offered.push_back(k);
  if (offered.empty() || nearest < 0) return {};
  // the offered size nearest the body's and its neighbours among the offered: a sewn style
  // whose patterns stop before the chart's end (women's XL while the chart goes to 7XL)
  // recommends among its own sizes, never a size it has no pattern for
  const auto at = std::min_element(offered.begin(), offered.end(),
                                   [&](int a, int b) { return std::abs(a - nearest) < std::abs(b - nearest); });
  const auto first = at == offered.begin() ? at : at - 1, last = at + 1 == offered.end() ? at + 1 : at + 2;
  return {first, last};
}

std::vector<int> SizeFitter::candidatesFor(const BodyMeasurements& measured, Sex sex, int& centre) const {
  const int nearest = chart_.nearest(sex, measured.bustGirth, measured.waistGirth, measured.hipGirth);
  const std::vector<int> candidates = candidatesAround(sex, nearest);
  if (candidates.empty()) throw std::invalid_argument(std::string("size chart: no ") + sexName(sex) + " sizes");
  centre =
      static_cast<int>(std::min_element(candidates.begin(), candidates.end(),
                                        [&](int a, int b) { return std::abs(a - nearest) < std::abs(b - nearest); }) -
                       candidates.begin());
  return candidates;
}

namespace {

// The smallest candidate with no region tight, or the largest when every one is.
void choose(Recommendation& out) {
  out.allTight = true;
  for (const SizeFit& fit : out.sizes)
    if (std::find(fit.verdicts.begin(), fit.verdicts.end(), Verdict::Tight) == fit.verdicts.end()) {
      out.recommended = fit.size, out.allTight = false;
      break;
    }
  if (out.allTight) out.recommended = out.sizes.back().size;
}

}  // namespace

Recommendation SizeFitter::recommend(const TriangleMesh& body, Sex sex, bool warm) {
  const BodyMeasurements measured = measureBody(body);
  int centre = 0;
  const std::vector<int> candidates = candidatesFor(measured, sex, centre);
  const int count = static_cast<int>(candidates.size());
  const auto collider = std::make_shared<const MeshCollider>(body);
  const std::vector<FitRegion> regions = styleRegions(body, measured, sex, regions_);
  Recommendation out;
  out.sizes.resize(candidates.size());
  for (const int k : drapeOrder(count, centre)) {
    const Graded& graded = grade(sex, candidates[k]);
    std::vector<Vec3> start;
    if (const int from = k > centre ? k - 1 : k + 1; warm && warmStarts_ && k != centre)
      start = warmStart(graded.garment, grade(sex, candidates[from]).garment, out.sizes[from].drape.positions,
                        *collider, parameters_.clearance);
    GarmentDrape drape = start.empty() ? coldDrape(graded, sex, candidates[k], body, collider)
                                       : drapeSize(graded, sex, candidates[k], collider, &start);
    out.sizes[k] = fitSize(graded, ownFit(sex, candidates[k]), chart_.sizes(sex)[candidates[k]].name, *collider,
                           regions, std::move(drape));
  }
  choose(out);
  return out;
}

std::vector<int> SizeFitter::candidates(const TriangleMesh& body, Sex sex) const {
  int centre = 0;
  return candidatesFor(measureBody(body), sex, centre);
}

Recommendation SizeFitter::recommendFrom(const TriangleMesh& body, Sex sex,
                                         const std::function<GarmentDrape(int)>& drapeOf) {
  const BodyMeasurements measured = measureBody(body);
  int centre = 0;
  const std::vector<int> candidates = candidatesFor(measured, sex, centre);
  const MeshCollider collider(body);
  const std::vector<FitRegion> regions = styleRegions(body, measured, sex, regions_);
  Recommendation out;
  for (const int size : candidates)
    out.sizes.push_back(
        fitSize(grade(sex, size), ownFit(sex, size), chart_.sizes(sex)[size].name, collider, regions, drapeOf(size)));
  choose(out);
  return out;
}

}  // namespace figment
