#include "sim/pattern/Sewing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

namespace figment {

void SewingParameters::validate() const {
  if (!(rate > 0.0) || !std::isfinite(rate))
    throw std::invalid_argument("sewing rate = " + std::to_string(rate) + " 1/s^2 must be > 0");
  if (!(closedGap > 0.0) || !std::isfinite(closedGap))
    throw std::invalid_argument("sewing closedGap = " + std::to_string(closedGap) + " m must be > 0");
  if (!(maxTime > 0.0) || !std::isfinite(maxTime))
    throw std::invalid_argument("sewing maxTime = " + std::to_string(maxTime) + " s must be > 0");
  if (!(snapGap >= closedGap) || !std::isfinite(snapGap))
    throw std::invalid_argument("sewing snapGap = " + std::to_string(snapGap) + " m must be >= closedGap");
  if (!(stall >= 0.0 && stall < 1.0))
    throw std::invalid_argument("sewing stall = " + std::to_string(stall) + " must be in [0, 1)");
  if (stallSteps < 1)
    throw std::invalid_argument("sewing stallSteps = " + std::to_string(stallSteps) + " must be >= 1");
  if (!(strengthen > 1.0) || !(maxStrength >= 1.0) || !std::isfinite(strengthen) || !std::isfinite(maxStrength))
    throw std::invalid_argument("sewing strengthen = " + std::to_string(strengthen) +
                                " must be > 1 and maxStrength = " + std::to_string(maxStrength) + " >= 1");
}

namespace {

std::array<Vec3, 3> flatCorners(const UnsewnGarment& garment, const Triangle& t) {
  std::array<Vec3, 3> corners;
  for (int k = 0; k < 3; ++k) corners[k] = Vec3(garment.flat[t[k]].x(), garment.flat[t[k]].y(), 0.0);
  return corners;
}

void checkGarment(const UnsewnGarment& garment) {
  const size_t n = garment.placed.vertices.size();
  if (garment.flat.size() != n)
    throw std::invalid_argument("the pattern's garment has " + std::to_string(garment.flat.size()) +
                                " panel coordinates for " + std::to_string(n) + " nodes");
  if (garment.seams.empty()) throw std::invalid_argument("the pattern's garment has no seams to sew");
}

// Union-find over the panel nodes, joined along the closed seam pairs.
class NodeClasses {
 public:
  explicit NodeClasses(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
    return a;
  }
  void join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

}  // namespace

// Each class of panel nodes joined by pairs within reach becomes one sewn node at their
// mean, numbered in the order of their first panel node.
SewnGarment mergeSeams(const UnsewnGarment& garment, const std::vector<Vec3>& x, double snapGap) {
  checkGarment(garment);
  if (x.size() != garment.placed.vertices.size())
    throw std::invalid_argument("mergeSeams: " + std::to_string(x.size()) + " positions for " +
                                std::to_string(garment.placed.vertices.size()) + " panel nodes");
  SewnGarment out;
  const size_t n = x.size();
  NodeClasses classes(n);
  for (const auto& [a, b] : garment.seams) {
    const double gap = (x[a] - x[b]).norm();
    if (gap > snapGap) continue;
    out.closedGap = std::max(out.closedGap, gap);
    classes.join(a, b);
  }
  out.nodeOf.assign(n, -1);
  std::vector<int> members;
  for (size_t i = 0; i < n; ++i) {
    const int root = classes.find(static_cast<int>(i));
    if (out.nodeOf[root] < 0) {
      out.nodeOf[root] = static_cast<int>(out.positions.size());
      out.positions.push_back(Vec3::Zero());
      members.push_back(0);
    }
    out.nodeOf[i] = out.nodeOf[root];
    out.positions[out.nodeOf[i]] += x[i];
    ++members[out.nodeOf[i]];
  }
  for (size_t k = 0; k < out.positions.size(); ++k) out.positions[k] /= members[k];

  std::vector<Triangle> triangles;
  std::vector<std::array<Vec3, 3>> corners;
  for (const Triangle& t : garment.placed.triangles) {
    const Triangle sewn{out.nodeOf[t[0]], out.nodeOf[t[1]], out.nodeOf[t[2]]};
    if (sewn[0] == sewn[1] || sewn[1] == sewn[2] || sewn[0] == sewn[2]) {
      ++out.droppedTriangles;
      continue;
    }
    triangles.push_back(sewn);
    corners.push_back(flatCorners(garment, t));
  }
  out.rest = RestShape::flatPieces(std::move(triangles), std::move(corners), out.positions.size());

  std::set<std::array<int, 2>> open;
  for (size_t s = 0; s < garment.seams.size(); ++s) {
    const int p = out.nodeOf[garment.seams[s][0]], q = out.nodeOf[garment.seams[s][1]];
    if (p == q) continue;
    out.openPairs.push_back(static_cast<int>(s));
    open.insert({std::min(p, q), std::max(p, q)});
  }
  out.openSeams.assign(open.begin(), open.end());
  return out;
}

SewnGarment sewPanels(const UnsewnGarment& garment, const ClothParameters& parameters,
                      std::shared_ptr<const Collider> body, const SewingParameters& sewing) {
  checkGarment(garment);
  sewing.validate();
  ClothParameters pulled = parameters;
  pulled.gravity = Vec3::Zero();  // the panels hang in place while the seams close
  // A seam closing round a shoulder or a hip presses its cloth on the body as it pulls it
  // over; friction would hold it there (a capstan), so the sewing slides freely.
  pulled.friction = 0.0;
  pulled.maxTime = sewing.maxTime;
  // The sewing's steps stay the scene's: its stall rule counts them.
  pulled.implicitSolver.maxTimeStep = 0.0;
  const auto started = std::chrono::steady_clock::now();
  ClothSolver solver(garment.placed.vertices, panelsAtRest(garment), pulled, std::move(body),
                     SeamPull{garment.seams, sewing.rate});
  double strength = 1.0, gap = solver.model().seams().largestGap(solver.positions());
  StallCount stall(sewing);
  while (gap > sewing.closedGap && solver.time() < sewing.maxTime - 1e-12) {
    solver.step();
    const double before = gap;
    gap = solver.model().seams().largestGap(solver.positions());
    if (!stall.stalledAfter(before, gap)) continue;
    if (strength * sewing.strengthen > sewing.maxStrength) break;  // as hard as it pulls: what is left stays
    solver.seams().strengthen(sewing.strengthen);
    strength *= sewing.strengthen;
    stall.restart();
  }

  SewnGarment out = mergeSeams(garment, solver.positions(), sewing.snapGap);
  out.strength = strength;
  out.sewing = solver.ending();
  out.sewing.iterations = solver.iterations();
  out.sewing.simulatedTime = solver.time();
  out.sewing.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  out.sewing.implicitCosts = solver.implicitCosts();
  return out;
}

double largestSeamGap(const UnsewnGarment& garment, const std::vector<Vec3>& positions) {
  double largest = 0.0;
  for (const auto& [a, b] : garment.seams) largest = std::max(largest, (positions[a] - positions[b]).norm());
  return largest;
}

RestShape panelsAtRest(const UnsewnGarment& garment) {
  std::vector<std::array<Vec3, 3>> corners;
  for (const Triangle& t : garment.placed.triangles) corners.push_back(flatCorners(garment, t));
  return RestShape::flatPieces(garment.placed.triangles, std::move(corners), garment.placed.vertices.size());
}

}  // namespace figment
