#include "sim/fit/GarmentFit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include "sim/body/BodyMeasurements.h"
#include "sim/cloth/ClothModel.h"

namespace figment {

namespace {

constexpr double kTouchMargin = 0.002;  // m beyond the clearance a node still touches
constexpr double kSearchRadius = 0.10;  // m a distance query looks
constexpr double kJoinGrid = 1e-7;      // m: section points closer than this are one
constexpr double kMaxGap = M_PI / 3;    // rad: a section with a wider gap does not go round
constexpr double kLevelStep = 0.01;     // m down the band when the garment misses the level
// An edge carried back to the standing body (PosedSkin) that grows by more than half (and
// 5 mm) has its ends on skin the pose brought together (an armpit, a groin), told apart at
// rest; past kTornShare of a region's edges its girth and drop are not told.
constexpr double kTearGrowth = 1.5, kTearSlack = 0.005;
constexpr double kTornShare = 0.10;
constexpr double kStray = 0.03;  // m a node may be carried off its neighbours' move (see toldPositions)

// Each node's share of the draped area (a third of each section it is a corner of), m^2.
std::vector<double> nodeAreas(const TriangleMesh& rest, const std::vector<Vec3>& x) {
  std::vector<double> area(x.size(), 0.0);
  for (const Triangle& t : rest.triangles) {
    const double a = 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
    for (int k = 0; k < 3; ++k) area[t[k]] += a / 3.0;
  }
  return area;
}

// Whether `points` go all round `centre`: no gap between them wider than kMaxGap seen from it.
bool surrounds(std::vector<Vec2> points, const Vec2& centre) {
  if (points.size() < 3) return false;
  std::vector<double> angles;
  for (const Vec2& p : points) angles.push_back(std::atan2(p.y() - centre.y(), p.x() - centre.x()));
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * M_PI - angles.back();
  for (size_t i = 1; i < angles.size(); ++i) gap = std::max(gap, angles[i] - angles[i - 1]);
  return gap <= kMaxGap;
}

// Which loop each segment of a section is on: segments that share an end (to kJoinGrid)
// are one loop's. Union-find over the ends.
std::vector<int> loopOf(const std::vector<Segment2>& segments) {
  std::vector<int> parent(segments.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&parent](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::map<std::pair<long long, long long>, int> ends;
  for (size_t i = 0; i < segments.size(); ++i)
    for (const Vec2& p : {segments[i].a, segments[i].b}) {
      const std::pair<long long, long long> key(std::llround(p.x() / kJoinGrid), std::llround(p.y() / kJoinGrid));
      const auto [at, added] = ends.emplace(key, static_cast<int>(i));
      if (!added) parent[root(static_cast<int>(i))] = root(at->second);
    }
  std::vector<int> loop(segments.size());
  for (size_t i = 0; i < segments.size(); ++i) loop[i] = root(static_cast<int>(i));
  return loop;
}

// The garment's section points at `level` on the loops that go round the body's section
// (each on its own): not a sleeve beside it, not a strap over it.
std::vector<Vec2> garmentSection(const TriangleMesh& draped, const TorsoSlice& body, double level,
                                 const FitRegion& region) {
  const std::vector<Segment2> segments = planeSection(draped, SectionAxis::Y, level);
  const std::vector<int> loop = loopOf(segments);
  std::map<int, std::vector<Vec2>> loops;
  for (size_t i = 0; i < segments.size(); ++i) {
    loops[loop[i]].push_back(segments[i].a);
    loops[loop[i]].push_back(segments[i].b);
  }
  std::vector<Vec2> points;
  for (const auto& [id, loopPoints] : loops)
    if (surrounds(loopPoints, body.centroid()))
      for (const Vec2& p : loopPoints)
        if (!region.girthWithinAcross || (p.x() >= region.minX && p.x() <= region.maxX)) points.push_back(p);
  return points;
}

double perimeterOf(const std::vector<Vec2>& points) {
  std::vector<Vec3> lifted;
  for (const Vec2& p : points) lifted.emplace_back(p.x(), 0.0, p.y());
  return convexPerimeter(lifted, Vec3::UnitY());
}

// The region's girths (garment, body) at its level, or, where the garment does not go all
// round the body there (it slid below the level, its neckline dips), at the highest level
// below it in the band where it does, every kLevelStep. NaNs where it never does.
std::pair<double, double> girths(const TriangleMesh& draped, const TriangleMesh& body, const FitRegion& region) {
  for (double level = region.girthLevel; level >= region.low; level -= kLevelStep) {
    const TorsoSlice section =
        level == region.girthLevel ? region.bodySection : sliceTorso(body, level, region.slicing);
    if (section.empty()) continue;
    const std::vector<Vec2> points = garmentSection(draped, section, level, region);
    if (!points.empty()) return {perimeterOf(points), perimeterOf(section.hull)};
  }
  const double none = std::numeric_limits<double>::quiet_NaN();
  return {none, none};
}

void checkInput(const FitInput& input) {
  if (!input.rest || !input.positions || !input.body) throw std::invalid_argument("fit: no garment, drape or body");
  if (input.positions->size() != input.rest->vertices.size())
    throw std::invalid_argument("fit: " + std::to_string(input.positions->size()) + " positions for " +
                                std::to_string(input.rest->vertices.size()) + " rest points");
  if (input.restShape && (input.restShape->triangles() != input.rest->triangles ||
                          input.restShape->nodeCount() != input.rest->vertices.size()))
    throw std::invalid_argument("fit: the rest shape's " + std::to_string(input.restShape->triangles().size()) +
                                " sections are not the garment's " + std::to_string(input.rest->triangles.size()));
}

// Section t's corners at rest: the rest shape's own, else the rest mesh's.
std::array<Vec3, 3> restCorners(const FitInput& input, size_t t) {
  if (input.restShape) return input.restShape->corners(t);
  const Triangle& tri = input.rest->triangles[t];
  return {input.rest->vertices[tri[0]], input.rest->vertices[tri[1]], input.rest->vertices[tri[2]]};
}

// Stretch over each region's sections (by the centroid's region), area-weighted.
// `at`: where each node is told (PosedSkin).
void addStretch(const FitInput& input, const std::vector<Vec3>& at, const std::vector<FitRegion>& regions,
                std::vector<RegionFit>& fits) {
  const TriangleMesh& rest = *input.rest;
  const std::vector<Vec3>& x = *input.positions;
  std::vector<double> weight(regions.size(), 0.0);
  for (size_t i = 0; i < rest.triangles.size(); ++i) {
    const Triangle& t = rest.triangles[i];
    const int r = regionOf(regions, (at[t[0]] + at[t[1]] + at[t[2]]) / 3.0);
    if (r < 0) continue;
    const auto [a, b, c] = restCorners(input, i);
    const double area = 0.5 * (b - a).cross(c - a).norm();
    if (area <= 0) continue;
    const double strain = largestPrincipalStrain(a, b, c, x[t[0]], x[t[1]], x[t[2]]);
    fits[r].meanStrain += area * strain;
    fits[r].maxStrain = weight[r] > 0 ? std::max(fits[r].maxStrain, strain) : strain;
    weight[r] += area;
  }
  for (size_t r = 0; r < regions.size(); ++r)
    if (weight[r] > 0) fits[r].meanStrain /= weight[r];
}

}  // namespace

double largestPrincipalStrain(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x, const Vec3& y,
                              const Vec3& z) {
  // The rest triangle in its own plane's frame (u along a->b), and F = Ds Dm^-1.
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 u = e1.normalized();
  const Vec3 w = e1.cross(e2).cross(e1).normalized();
  Eigen::Matrix2d restFrame;
  restFrame << e1.dot(u), e2.dot(u), e1.dot(w), e2.dot(w);
  Eigen::Matrix<double, 3, 2> deformed;
  deformed.col(0) = y - x;
  deformed.col(1) = z - x;
  const Eigen::Matrix<double, 3, 2> f = deformed * restFrame.inverse();
  const Eigen::Matrix2d cauchyGreen = f.transpose() * f;
  const double largest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cauchyGreen).eigenvalues().maxCoeff();
  return std::sqrt(std::max(largest, 0.0)) - 1.0;
}

std::vector<double> contactPressures(const FitInput& input) {
  checkInput(input);
  const std::vector<Vec3>& x = *input.positions;
  const ClothModel model =
      input.restShape ? ClothModel(*input.restShape, input.parameters) : ClothModel(*input.rest, input.parameters);
  ClothModel::Evaluation forces;
  ClothModel::Request request;
  request.damping = false;
  request.external = false;  // at rest: no air, and the wind is not the body's
  model.evaluate(x, std::vector<Vec3>(x.size(), Vec3::Zero()), 0.0, request, forces);
  const std::vector<double> area = nodeAreas(*input.rest, x);
  std::vector<double> pressure(x.size(), 0.0);
  for (size_t i = 0; i < x.size(); ++i) {
    Contact contact;
    if (area[i] <= 0 || !input.body->contact(x[i], input.parameters.clearance + kTouchMargin, kSearchRadius, contact))
      continue;
    pressure[i] = std::max(0.0, -forces.forces[i].dot(contact.normal)) / area[i];
  }
  return pressure;
}

// A region the garment goes on up out of (an edge from one of its nodes to above its top) has
// no drop: its highest node is then just the garment's nearest row below the top, up to an
// edge's length (2 cm on the pencil skirt) lower on one body than on another, not where the
// garment sits.
void reachedTops(const TriangleMesh& rest, const std::vector<Vec3>& x, const std::vector<FitRegion>& regions,
                 std::vector<RegionFit>& fits) {
  for (const Triangle& t : rest.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      for (const auto& [inside, other] : {std::pair(a, b), std::pair(b, a)})
        if (const int r = regionOf(regions, x[inside]); r >= 0 && x[other].y() >= regions[r].high) fits[r].drop = 0;
    }
}

namespace {

// Whether the edge a-b parts when carried back to the standing body (`at`).
bool torn(const std::vector<Vec3>& at, const std::vector<Vec3>& x, int a, int b) {
  return (at[a] - at[b]).norm() > kTearGrowth * (x[a] - x[b]).norm() + kTearSlack;
}

// On a posed body: each region whose garment edges tear past kTornShare when carried back
// to the standing body (`at`) is told unmeasured, its girth and drop left out.
void markTorn(const FitInput& input, const std::vector<Vec3>& at, const std::vector<FitRegion>& regions,
              std::vector<RegionFit>& fits) {
  const std::vector<Vec3>& x = *input.positions;
  std::vector<int> edges(regions.size(), 0), parted(regions.size(), 0);
  for (const Triangle& t : input.rest->triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const int r = regionOf(regions, at[a]);
      if (r < 0) continue;
      edges[r] += 1;
      parted[r] += torn(at, x, a, b);
    }
  for (size_t r = 0; r < regions.size(); ++r) {
    if (edges[r] == 0 || parted[r] <= kTornShare * edges[r]) continue;
    const int percent = static_cast<int>(std::lround(100.0 * parted[r] / edges[r]));
    fits[r].unmeasured = "the pose folds the skin under it: " + std::to_string(percent) +
                         " % of its garment's edges part when carried back to the standing body";
    fits[r].garmentGirth = fits[r].girthEase = std::numeric_limits<double>::quiet_NaN();
    fits[r].drop = 0;
  }
}

// The garment's girths where it goes round, on the standing body (`at`, `body`).
void addGirths(const FitInput& input, const std::vector<Vec3>& at, const std::vector<FitRegion>& regions,
               std::vector<RegionFit>& fits) {
  const TriangleMesh draped{at, input.rest->triangles};
  const TriangleMesh& body = input.pose ? input.pose->rest() : input.body->surface();
  for (size_t r = 0; r < regions.size(); ++r) {
    if (fits[r].nodes == 0 || !regions[r].hasGirth()) continue;
    const auto [garment, skin] = girths(draped, body, regions[r]);
    fits[r].garmentGirth = garment;
    fits[r].girthEase = garment - skin;
  }
}

// The component-wise median of `values`.
Vec3 median(std::vector<Vec3> values) {
  Vec3 m;
  const size_t middle = values.size() / 2;
  for (int k = 0; k < 3; ++k) {
    std::nth_element(values.begin(), values.begin() + middle, values.end(),
                     [k](const Vec3& a, const Vec3& b) { return a[k] < b[k]; });
    m[k] = values[middle][k];
  }
  return m;
}

// Where each node is told: where it lies, or on a posed body where it would lie on the
// standing one (PosedSkin). A node whose closest skin is another limb's than its
// neighbours' (a skirt's front touching the thigh that steps forward) goes back with that
// limb, away from them (35 cm out of the walking body's hip loop): a node carried more
// than kStray from the median of its neighbours' moves takes that median instead.
std::vector<Vec3> toldPositions(const FitInput& input) {
  const std::vector<Vec3>& x = *input.positions;
  if (!input.pose) return x;
  const std::vector<Vec3> carried = input.pose->toRest(x);
  std::vector<std::vector<int>> neighbours(x.size());
  for (const Triangle& t : input.rest->triangles)
    for (int k = 0; k < 3; ++k) neighbours[t[k]].push_back(t[(k + 1) % 3]), neighbours[t[k]].push_back(t[(k + 2) % 3]);
  std::vector<Vec3> at = carried;
  for (size_t i = 0; i < x.size(); ++i) {
    if (neighbours[i].empty()) continue;
    std::vector<Vec3> moves;
    for (const int j : neighbours[i]) moves.push_back(carried[j] - x[j]);
    const Vec3 usual = median(std::move(moves));
    if ((carried[i] - x[i] - usual).norm() > kStray) at[i] = x[i] + usual;
  }
  return at;
}

}  // namespace

std::vector<int> nodeRegions(const FitInput& input, const std::vector<FitRegion>& regions) {
  checkInput(input);
  const std::vector<Vec3> at = toldPositions(input);
  std::vector<int> region;
  region.reserve(at.size());
  for (const Vec3& p : at) region.push_back(regionOf(regions, p));
  return region;
}

std::vector<RegionFit> measureFit(const FitInput& input, const std::vector<FitRegion>& regions) {
  checkInput(input);
  const std::vector<Vec3>& x = *input.positions;
  const std::vector<Vec3> at = toldPositions(input);
  std::vector<RegionFit> fits(regions.size());
  for (size_t r = 0; r < regions.size(); ++r) {
    fits[r].name = regions[r].name;
    fits[r].drop = regions[r].high - regions[r].low;
  }
  addStretch(input, at, regions, fits);
  const std::vector<double> pressure = contactPressures(input);
  const std::vector<double> area = nodeAreas(*input.rest, x);
  std::vector<double> force(regions.size(), 0.0), regionArea(regions.size(), 0.0);
  for (size_t i = 0; i < x.size(); ++i) {
    const int r = regionOf(regions, at[i]);
    if (r < 0) continue;
    const double distance = std::sqrt(input.body->bvh().closest(x[i]).distanceSquared);
    fits[r].ease += std::max(0.0, distance - input.parameters.clearance);
    fits[r].nodes += 1;
    fits[r].drop = std::min(fits[r].drop, regions[r].high - at[i].y());
    force[r] += pressure[i] * area[i];
    regionArea[r] += area[i];
    fits[r].maxPressure = std::max(fits[r].maxPressure, pressure[i]);
  }
  reachedTops(*input.rest, at, regions, fits);
  for (size_t r = 0; r < regions.size(); ++r) {
    if (fits[r].nodes == 0) continue;
    fits[r].ease /= fits[r].nodes;
    fits[r].pressure = regionArea[r] > 0 ? force[r] / regionArea[r] : 0.0;
  }
  addGirths(input, at, regions, fits);
  if (input.pose) markTorn(input, at, regions, fits);
  return fits;
}

}  // namespace figment
