#include "sim/progressive/ProgressiveDrape.h"

#include "sim/progressive/SplitPlacement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace figment {

namespace {
constexpr int kBatches = 10;  // the splits come in at most this many rebuilds (and a last one)
}  // namespace

ProgressiveDrape::ProgressiveDrape(const ProgressiveMesh& mesh, const ClothParameters& parameters,
                                   std::shared_ptr<const Collider> body, const ProgressiveSchedule& schedule)
    : mesh_(mesh),
      parameters_(parameters),
      body_(std::move(body)),
      schedule_(schedule),
      endLevel_(schedule.endLevel < 0 ? mesh.levels() : schedule.endLevel),
      fullArea_(surfaceArea(mesh.full)),
      level_(mesh) {
  if (schedule.beginLevel < 0 || schedule.beginLevel > endLevel_ || endLevel_ > mesh.levels())
    throw std::invalid_argument("beginLevel = " + std::to_string(schedule.beginLevel) + " and endLevel = " +
                                std::to_string(schedule.endLevel) + " must satisfy 0 <= begin <= end <= " +
                                std::to_string(mesh.levels()));
  if (!(schedule.splitsPerSecond >= 0.0) || !std::isfinite(schedule.splitsPerSecond))
    throw std::invalid_argument("splitRate = " + std::to_string(schedule.splitsPerSecond) + " must be >= 0");
  batch_ = std::max(1, (endLevel_ - schedule.beginLevel) / kBatches);
  x_ = mesh.full.vertices;
  v_.assign(x_.size(), Vec3::Zero());
  // The coarse levels' vertices start at their rest positions (the garment's placement).
  for (size_t i = 0; i < x_.size(); ++i) x_[i] = level_.rest(static_cast<int>(i));
  splitTo(schedule.beginLevel);
  rebuild();
}

void ProgressiveDrape::splitTo(int target) {
  while (level_.level() < target) {
    const VertexSplit& split = mesh_.splits[level_.level()];
    placeSplit(split, level_, x_, v_);
    level_.splitTo(level_.level() + 1);
  }
}

void ProgressiveDrape::rebuild() {
  double time = 0.0;
  int iterations = 0;
  if (solver_) {
    time = solver_->time();
    iterations = solver_->iterations();
    retiredCosts_ += solver_->implicitCosts();
  }
  const TriangleMesh rest = level_.restMesh(fullIndex_);
  ClothParameters p = parameters_;
  p.material.density *= fullArea_ / surfaceArea(rest);  // the same mass at every level
  solver_ = std::make_unique<ClothSolver>(rest, p, body_);
  std::vector<Vec3> x(fullIndex_.size()), v(fullIndex_.size());
  for (size_t i = 0; i < fullIndex_.size(); ++i) x[i] = x_[fullIndex_[i]], v[i] = v_[fullIndex_[i]];
  solver_->resume(x, v, time, iterations);
}

int ProgressiveDrape::dueLevel() const {
  const int level = level_.level();
  if (level == endLevel_) return level;
  if (schedule_.splitsPerSecond == 0.0) return solver_->atRest() ? endLevel_ : level;
  const double due = schedule_.beginLevel + schedule_.splitsPerSecond * solver_->time();
  const int target = std::min(endLevel_, static_cast<int>(std::floor(due)));
  return target == endLevel_ || target - level >= batch_ ? target : level;
}

void ProgressiveDrape::step() {
  solver_->step();
  const int target = dueLevel();
  if (target == level_.level()) return;
  const std::vector<Vec3>& x = solver_->positions();
  const std::vector<Vec3>& v = solver_->velocities();
  for (size_t i = 0; i < fullIndex_.size(); ++i) x_[fullIndex_[i]] = x[i], v_[fullIndex_[i]] = v[i];
  splitTo(target);
  rebuild();
}

DrapeResult ProgressiveDrape::run(const std::function<void(const DrapeProgress&)>& progress,
                                  double progressInterval) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto lastReport = start;
  const int totalSteps = static_cast<int>(std::ceil(parameters_.maxTime / parameters_.timeStep - 1e-9));
  while (solver_->iterations() < totalSteps && !atRest()) {
    step();
    if (progress && std::chrono::duration<double>(Clock::now() - lastReport).count() >= progressInterval) {
      progress({solver_->iterations(), solver_->time(), solver_->maxSpeed()});
      lastReport = Clock::now();
    }
  }
  DrapeResult result;
  result.iterations = solver_->iterations();
  result.simulatedTime = solver_->time();
  result.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  result.atRest = atRest();
  result.implicitCosts = retiredCosts_;
  result.implicitCosts += solver_->implicitCosts();
  return result;
}

double ProgressiveDrape::mass() const {
  double sum = 0.0;
  for (double m : solver_->model().masses()) sum += m;
  return sum;
}

std::vector<Vec3> ProgressiveDrape::fullPositions() const {
  std::vector<Vec3> x = x_, v = v_;
  const std::vector<Vec3>& now = solver_->positions();
  for (size_t i = 0; i < fullIndex_.size(); ++i) x[fullIndex_[i]] = now[i];
  if (level_.level() < mesh_.levels()) {
    MeshLevel rest = level_;
    while (rest.level() < mesh_.levels()) {
      placeSplit(mesh_.splits[rest.level()], rest, x, v);
      rest.splitTo(rest.level() + 1);
    }
  }
  return x;
}

std::vector<Triangle> ProgressiveDrape::levelTriangles() const {
  std::vector<Triangle> out;
  for (int f = 0; f < static_cast<int>(mesh_.full.triangles.size()); ++f)
    if (level_.faceActive(f)) out.push_back(level_.corners(f));
  return out;
}

}  // namespace figment
