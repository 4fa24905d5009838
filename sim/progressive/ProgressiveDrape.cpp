#include "sim/progressive/ProgressiveDrape.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sim/progressive/SplitPlacement.h"

namespace figment {

namespace {
constexpr int kBatches = 10;  // the splits come in at most this many rebuilds (and a last one)
// After the splits no edge of the level is longer or shorter than its rest length by
// more than this share (as far as the sweeps get; see settle()). At 5 % with 4 rounds
// of 5 sweeps, Heun's dress blew up after the all-at-once split at 1.01 x 1.5e-4 s; at
// 1 % in 20 rounds of 2 (short rounds: lifting out of the body undoes less of each)
// it rests (the engine's tests); a few strap edges still start 10-15 % long there,
// where the body holds their ends apart.
constexpr double kSettledStrain = 0.01;
constexpr int kSettleRounds = 20, kSweepsPerRound = 2;

// An explicit step's stability bound scales with the shortest period of the mesh's
// nodes, sqrt(m_i / k_i): a node's mass goes with the area of its sections, its
// membrane stiffness with the sum of 1 / length over its edges (same material, same
// thickness at every level; the constant factors cancel in a ratio of two levels).
// Light nodes on a strap's edge set it, not the shortest edge (which coarse levels
// keep wherever the decimation left a region alone).
double stabilityTime(const TriangleMesh& mesh) {
  std::vector<double> area(mesh.vertices.size(), 0.0), stiffness(mesh.vertices.size(), 0.0);
  for (const Triangle& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double third = (b - a).cross(c - a).norm() / 6.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.vertices[t[k]];
      area[t[k]] += third;
      stiffness[t[k]] +=
          1.0 / (mesh.vertices[t[(k + 1) % 3]] - p).norm() + 1.0 / (mesh.vertices[t[(k + 2) % 3]] - p).norm();
    }
  }
  double shortest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < area.size(); ++i)
    if (stiffness[i] > 0.0 && area[i] > 0.0) shortest = std::min(shortest, area[i] / stiffness[i]);
  return std::sqrt(shortest);
}
}  // namespace

ProgressiveDrape::ProgressiveDrape(const ProgressiveMesh& mesh, const ClothParameters& parameters,
                                   std::shared_ptr<const Collider> body, const ProgressiveSchedule& schedule)
    : mesh_(mesh),
      parameters_(parameters),
      body_(std::move(body)),
      schedule_(schedule),
      endLevel_(schedule.endLevel < 0 ? mesh.levels() : schedule.endLevel),
      fullArea_(surfaceArea(mesh.full)),
      fullStabilityTime_(stabilityTime(mesh.full)),
      level_(mesh) {
  if (schedule.beginLevel < 0 || schedule.beginLevel > endLevel_ || endLevel_ > mesh.levels())
    throw std::invalid_argument("beginLevel = " + std::to_string(schedule.beginLevel) +
                                " and endLevel = " + std::to_string(schedule.endLevel) +
                                " must satisfy 0 <= begin <= end <= " + std::to_string(mesh.levels()));
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

std::vector<int> ProgressiveDrape::splitTo(int target) {
  std::vector<int> placed;
  while (level_.level() < target) {
    const VertexSplit& split = mesh_.splits[level_.level()];
    placeSplit(split, level_, x_, v_);
    placed.push_back(split.kept);
    placed.push_back(split.added);
    level_.splitTo(level_.level() + 1);
  }
  return placed;
}

void ProgressiveDrape::settle(const std::vector<int>& placed) {
  if (body_) liftOutOfBody(placed);
  std::vector<std::pair<int, int>> edges;  // of the level, each once
  std::vector<int> active;
  for (int f = 0; f < static_cast<int>(mesh_.full.triangles.size()); ++f) {
    if (!level_.faceActive(f)) continue;
    const Triangle& t = level_.corners(f);
    for (int e = 0; e < 3; ++e) edges.emplace_back(std::minmax(t[e], t[(e + 1) % 3]));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (int i = 0; i < static_cast<int>(x_.size()); ++i)
    if (level_.vertexActive(i)) active.push_back(i);
  // Lifting stretches the sections around, relaxing may pull a vertex back in: in turns.
  // Every vertex is lifted after the first round; after later ones, those relaxing moved
  // (the others stand where the last lift left them).
  for (int round = 0; round < kSettleRounds; ++round) {
    const std::vector<int> moved = relaxStrain(edges);
    if (body_) liftOutOfBody(round == 0 ? active : moved);
  }
}

std::vector<int> ProgressiveDrape::relaxStrain(const std::vector<std::pair<int, int>>& edges) {
  std::vector<char> changed(x_.size(), 0);
  for (int sweep = 0; sweep < kSweepsPerRound; ++sweep) {
    for (auto [a, b] : edges) {
      const Vec3 d = x_[b] - x_[a];
      const double length = d.norm(), rest = (level_.rest(b) - level_.rest(a)).norm();
      const double target = std::clamp(length, (1.0 - kSettledStrain) * rest, (1.0 + kSettledStrain) * rest);
      if (length == target || length == 0.0) continue;
      const Vec3 half = 0.5 * (length - target) / length * d;
      x_[a] += half;
      x_[b] -= half;
      changed[a] = changed[b] = 1;
    }
  }
  std::vector<int> moved;
  for (int i = 0; i < static_cast<int>(changed.size()); ++i)
    if (changed[i]) moved.push_back(i);
  return moved;
}

void ProgressiveDrape::liftOutOfBody(const std::vector<int>& vertices) {
  const double clearance = parameters_.clearance;
  for (int i : vertices) {
    Contact contact;
    if (!body_->contact(x_[i], clearance, std::numeric_limits<double>::infinity(), contact)) continue;
    const Vec3& n = contact.normal;
    x_[i] = contact.surfacePoint + clearance * n;
    v_[i] -= std::min(0.0, v_[i].dot(n)) * n;
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
  if (p.integrator != Integrator::Implicit)
    p.timeStep *= std::min(kMaxStepGrowth, stabilityTime(rest) / fullStabilityTime_);
  solver_ = std::make_unique<ClothSolver>(rest, p, body_);
  std::vector<Vec3> x(fullIndex_.size()), v(fullIndex_.size());
  for (size_t i = 0; i < fullIndex_.size(); ++i) x[i] = x_[fullIndex_[i]], v[i] = v_[fullIndex_[i]];
  solver_->resume(x, v, time, iterations);
  if (level_.level() == endLevel_) endLevelArrival_ = time, endLevelPlaced_ = solver_->positions();
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
  settle(splitTo(target));
  rebuild();
}

DrapeResult ProgressiveDrape::run(const std::function<void(const DrapeProgress&)>& progress, double progressInterval) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto lastReport = start;
  // Until maxTime: the explicit levels' steps differ, so it is counted in time.
  while (solver_->time() < parameters_.maxTime - 1e-9 * parameters_.timeStep && !atRest()) {
    step();
    if (progress && std::chrono::duration<double>(Clock::now() - lastReport).count() >= progressInterval) {
      progress({solver_->iterations(), solver_->time(), solver_->maxSpeed()});
      lastReport = Clock::now();
    }
  }
  DrapeResult result = solver_->ending();  // its stretch: the level's sections
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

EndLevelSettling ProgressiveDrape::endLevelSettling() const {
  EndLevelSettling out;
  if (endLevelArrival_ < 0.0) return out;
  out.arrival = endLevelArrival_;
  const std::vector<Vec3>& now = solver_->positions();
  for (size_t i = 0; i < now.size(); ++i) {
    const double moved = (now[i] - endLevelPlaced_[i]).norm();
    out.meanMove += moved;
    out.maxMove = std::max(out.maxMove, moved);
  }
  if (!now.empty()) out.meanMove /= static_cast<double>(now.size());
  return out;
}

std::vector<Triangle> ProgressiveDrape::levelTriangles() const {
  std::vector<Triangle> out;
  for (int f = 0; f < static_cast<int>(mesh_.full.triangles.size()); ++f)
    if (level_.faceActive(f)) out.push_back(level_.corners(f));
  return out;
}

}  // namespace figment
