#include "sim/core/BoundaryTurning.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "sim/core/BoundaryLoops.h"

namespace figment {

namespace {

constexpr double kDegrees = 180.0 / M_PI;
// Geodesic turns smaller than this (degrees) are straight: they have no sign, so rounding
// along a straight cut is no zig-zag.
constexpr double kStraightDegrees = 1e-6;

// The angle (radians) at `at` between the directions to `a` and `b`; 0 where one is at `at`.
double angleAt(const Vec3& at, const Vec3& a, const Vec3& b) {
  const Vec3 u = a - at, w = b - at;
  return std::atan2(u.cross(w).norm(), u.dot(w));
}

// Triangle `t` turned so that it starts at vertex `v` (which it must hold).
Triangle startingAt(const Triangle& t, int v) {
  if (t[1] == v) return {t[1], t[2], t[0]};
  if (t[2] == v) return {t[2], t[0], t[1]};
  return t;
}

// The triangles at `v` from the one with the edge v -> q (as wound) round through the
// cloth to the one with p -> v, each next one across the edge its predecessor ends on.
// Empty where the walk does not get there.
std::vector<int> fanThroughCloth(const std::vector<Triangle>& triangles,
                                 const std::map<std::pair<int, int>, int>& byEdge, int p, int v, int q) {
  std::vector<int> fan;
  auto edge = byEdge.find({v, q});
  while (edge != byEdge.end() && fan.size() < triangles.size()) {
    fan.push_back(edge->second);
    const Triangle t = startingAt(triangles[edge->second], v);  // v, a, b: next holds v -> b
    if (t[2] == p) return fan;
    edge = byEdge.find({v, t[2]});
  }
  return {};
}

}  // namespace

BoundaryTurning::BoundaryTurning(const std::vector<Triangle>& triangles)
    : triangles_(triangles), loops_(boundaryLoops(triangles)) {
  std::map<std::pair<int, int>, int> byEdge;  // a directed edge, as wound, to its triangle
  std::multimap<int, int> around;             // a vertex to its triangles
  for (int i = 0; i < static_cast<int>(triangles.size()); ++i)
    for (int e = 0; e < 3; ++e) {
      byEdge.emplace(std::make_pair(triangles[i][e], triangles[i][(e + 1) % 3]), i);
      around.emplace(triangles[i][e], i);
    }
  for (const std::vector<int>& loop : loops_) {
    const size_t n = loop.size();
    std::vector<std::vector<int>>& fans = fans_.emplace_back();
    for (size_t k = 0; k < n; ++k) {
      std::vector<int> fan = fanThroughCloth(triangles, byEdge, loop[(k + n - 1) % n], loop[k], loop[(k + 1) % n]);
      if (fan.empty())
        for (auto [at, end] = around.equal_range(loop[k]); at != end; ++at) fan.push_back(at->second);
      fans.push_back(std::move(fan));
    }
  }
}

std::vector<std::vector<BoundaryTurning::Turn>> BoundaryTurning::turns(const std::vector<Vec3>& positions) const {
  std::vector<std::vector<Turn>> out;
  for (size_t l = 0; l < loops_.size(); ++l) {
    const std::vector<double> totals = boundaryTurningAngles(positions, {loops_[l]});
    std::vector<Turn>& loopTurns = out.emplace_back();
    for (size_t k = 0; k < loops_[l].size(); ++k) {
      const int v = loops_[l][k];
      double angles = 0.0;
      for (int i : fans_[l][k]) {
        const Triangle t = startingAt(triangles_[i], v);
        angles += angleAt(positions[v], positions[t[1]], positions[t[2]]);
      }
      Turn turn{{totals[k], (M_PI - angles) * kDegrees, 0.0}, v};
      turn.normal = std::sqrt(std::max(turn.total * turn.total - turn.geodesic * turn.geodesic, 0.0));
      loopTurns.push_back(turn);
    }
  }
  return out;
}

BoundaryTurning::Summary BoundaryTurning::summary(const std::vector<Vec3>& positions) const {
  const std::vector<std::vector<Turn>> all = turns(positions);
  std::vector<double> total, geodesic, normal;
  for (const std::vector<Turn>& loop : all)
    for (const Turn& turn : loop) {
      total.push_back(turn.total);
      geodesic.push_back(std::abs(turn.geodesic));
      normal.push_back(turn.normal);
    }
  Summary out;
  out.vertices = static_cast<int>(total.size());
  out.total = median(std::move(total));
  out.geodesic = median(std::move(geodesic));
  out.normal = median(std::move(normal));
  out.zigZagShare = zigZagShare(all);
  return out;
}

std::vector<double> BoundaryTurning::geodesicStrainAllowance(const std::vector<Vec3>& rest,
                                                             const std::vector<Vec3>& deformed) const {
  std::vector<double> out;
  for (size_t l = 0; l < loops_.size(); ++l)
    for (size_t k = 0; k < loops_[l].size(); ++k) {
      double allowed = 0.0;
      for (int i : fans_[l][k]) {
        const Triangle t = startingAt(triangles_[i], loops_[l][k]);
        double strain = 0.0;  // the largest |log strain| of the triangle's sides
        for (int e = 0; e < 3; ++e) {
          const int a = t[e], b = t[(e + 1) % 3];
          const double length = (rest[b] - rest[a]).norm();
          if (length > 0.0) strain = std::max(strain, std::abs(std::log((deformed[b] - deformed[a]).norm() / length)));
        }
        const double cotA = 1.0 / std::tan(angleAt(rest[t[1]], rest[t[2]], rest[t[0]]));
        const double cotB = 1.0 / std::tan(angleAt(rest[t[2]], rest[t[0]], rest[t[1]]));
        allowed += (std::abs(cotA + cotB) + std::abs(cotA) + std::abs(cotB)) * strain;
      }
      out.push_back(allowed * kDegrees);
    }
  return out;
}

double BoundaryTurning::zigZagShare(const std::vector<std::vector<Turn>>& turns) {
  const auto sign = [](double degrees) { return std::abs(degrees) < kStraightDegrees ? 0 : (degrees > 0.0 ? 1 : -1); };
  double zigZag = 0.0, all = 0.0;
  for (const std::vector<Turn>& loop : turns) {
    const size_t n = loop.size();
    for (size_t k = 0; k < n; ++k) {
      const int here = sign(loop[k].geodesic);
      all += loop[k].total;
      if (n >= 3 && here != 0 && sign(loop[(k + n - 1) % n].geodesic) == -here &&
          sign(loop[(k + 1) % n].geodesic) == -here)
        zigZag += std::abs(loop[k].geodesic);
    }
  }
  return all > 0.0 ? zigZag / all : 0.0;
}

double BoundaryTurning::median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(middle), values.end());
  if (values.size() % 2 == 1) return values[middle];
  const double upper = values[middle];
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + static_cast<long>(middle)));
}

}  // namespace figment
