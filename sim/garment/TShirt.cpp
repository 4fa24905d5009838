#include "sim/garment/TShirt.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "sim/body/BodyParts.h"
#include "sim/body/SkeletonEstimate.h"
#include "sim/core/BoundaryLoops.h"
#include "sim/core/ParameterChecks.h"
#include "sim/core/PlaneClip.h"
#include "sim/progressive/Resampling.h"

namespace figment {

void TShirtOptions::validate() const {
  requireNonNegative("ease", ease);
  requireNonNegative("hemAboveCrotch", hemAboveCrotch);
  requireNonNegative("necklineDrop", necklineDrop);
  requireOpenRange("sleeveShare", sleeveShare, 0.0, 1.0);
  requirePositive("triangles", triangles);
}

namespace {

constexpr double kHemSnap = 0.005;  // m: a third of the skin's shortest edges or so
constexpr double kNeckBand = 0.01;  // m above and below the neck's base where the neck is measured
// The decimation's perimeterWeight (CollapseEnergy.h): 30 times its default keeps the
// openings' vertices where they curve, so the sleeves' ends (26 to 28 of the skin's
// vertices round) and the neckline keep enough to read as curves. At 10 the default shirt's
// openings turn a median 12.1 degrees (559 vertices), at 300 8.9 (581); the thinnest
// sections' area stays that of the decimation alone.
constexpr double kOpeningWeight = 300.0;
constexpr int kSmoothingSteps = 20;  // Taubin steps along each opening
constexpr int kCountRounds = 6;      // at most, to find how coarse to decimate
// m the neckline's sphere is centred above the neck's base: it then crosses the upright neck
// at 50 degrees or so, not grazing it (centred at the base it crossed at about 23 degrees, and
// the 5 mm snap stepped its edge up and down the neck's back).
constexpr double kNecklineCentreRise = 0.05;

// Which of the body's triangles the shirt is cut from, and the surfaces its openings are cut
// along: the hem level, the neckline round the neck, each sleeve's end across its upper arm's
// axis. The parts are kept whole up to past each cut, so every opening's edge runs along a
// plane or sphere (a smooth curve round the body) rather than along the skin's triangles,
// which zig-zag (the shirt's openings turned a median 49 degrees at each vertex).
class ShirtRegion {
 public:
  ShirtRegion(const Skeleton& skeleton, const TShirtOptions& options)
      : skeleton_(skeleton),
        hem_(skeleton["pelvisFloor"].position.y() + options.hemAboveCrotch),
        drop_(options.necklineDrop),
        share_(options.sleeveShare) {}

  double hemHeight() const { return hem_; }

  // `top`: the triangle's highest corner; a triangle across the hem is kept whole here
  // and cut along it later, as are the neck and the upper arms.
  bool covers(const std::string& part, double top) const {
    if (part == "upperTorso" || part == "lowerTorso" || part == "neck") return true;
    if (part == "upperArmL" || part == "upperArmR") return true;
    // Over the hips' sides the thighs' parts reach above the hem.
    if (part == "hips" || part == "thighL" || part == "thighR") return top > hem_;
    return false;
  }

  // The surfaces the openings are cut along, each keeping the shirt's side.
  Plane hem() const { return {Vec3(0.0, hem_, 0.0), Vec3::UnitY()}; }
  // Round the neck: the sphere through the neck's section at its base (`neck`: the skin's
  // vertices about that height), crossing the upright neck `drop` below the base, and lower
  // in front, where the chest slopes away from the neck.
  Sphere neckline(const std::vector<Vec3>& neck) const {
    const Vec3 base = skeleton_["neckBase"].position + Vec3(0.0, kNecklineCentreRise, 0.0);
    std::vector<double> across;
    for (const Vec3& x : neck) across.push_back(std::hypot(x.x() - base.x(), x.z() - base.z()));
    std::nth_element(across.begin(), across.begin() + static_cast<long>(across.size() / 2), across.end());
    const double r = across[across.size() / 2];
    const double h = drop_ + kNecklineCentreRise;
    return {base, std::sqrt(r * r + h * h)};
  }
  double neckBaseHeight() const { return skeleton_["neckBase"].position.y(); }
  Plane sleeveEnd(const char* shoulder, const char* elbow) const {
    const Vec3 from = skeleton_[shoulder].position, to = skeleton_[elbow].position;
    return {from + share_ * (to - from), (from - to).normalized()};
  }

 private:
  const Skeleton& skeleton_;
  double hem_, drop_, share_;
};

// How many triangles use each edge.
std::map<std::pair<int, int>, int> edgeUse(const std::vector<Triangle>& triangles) {
  std::map<std::pair<int, int>, int> use;
  for (const Triangle& t : triangles)
    for (int e = 0; e < 3; ++e) ++use[std::minmax(t[e], t[(e + 1) % 3])];
  return use;
}

// Takes off, again and again, triangles with two or three edges on the boundary (the
// spikes a cut along triangle edges leaves), so the openings' edges run smoothly.
void removeSpikes(std::vector<Triangle>& triangles) {
  for (bool removed = true; removed;) {
    const std::map<std::pair<int, int>, int> use = edgeUse(triangles);
    const size_t before = triangles.size();
    std::erase_if(triangles, [&](const Triangle& t) {
      int open = 0;
      for (int e = 0; e < 3; ++e) open += use.at(std::minmax(t[e], t[(e + 1) % 3])) == 1;
      return open >= 2;
    });
    removed = triangles.size() < before;
  }
}

// The largest piece of `triangles` connected through edges.
std::vector<Triangle> largestPiece(const std::vector<Triangle>& triangles) {
  std::map<std::pair<int, int>, std::vector<int>> byEdge;
  for (int f = 0; f < static_cast<int>(triangles.size()); ++f)
    for (int e = 0; e < 3; ++e) byEdge[std::minmax(triangles[f][e], triangles[f][(e + 1) % 3])].push_back(f);
  std::vector<int> piece(triangles.size(), -1);
  std::vector<int> sizes;
  for (int seed = 0; seed < static_cast<int>(triangles.size()); ++seed) {
    if (piece[seed] >= 0) continue;
    const int id = static_cast<int>(sizes.size());
    sizes.push_back(0);
    std::vector<int> stack{seed};
    piece[seed] = id;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      ++sizes[id];
      for (int e = 0; e < 3; ++e)
        for (int g : byEdge[std::minmax(triangles[f][e], triangles[f][(e + 1) % 3])])
          if (piece[g] < 0) piece[g] = id, stack.push_back(g);
    }
  }
  const int largest = static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  std::vector<Triangle> out;
  for (size_t f = 0; f < triangles.size(); ++f)
    if (piece[f] == largest) out.push_back(triangles[f]);
  return out;
}

// The skin region with each vertex moved `ease` out along its area-weighted normal; vertices
// numbered as the body's.
TriangleMesh offsetSkin(const TriangleMesh& body, const std::vector<Triangle>& triangles, double ease) {
  TriangleMesh skin{body.vertices, triangles};
  std::vector<Vec3> normal(body.vertices.size(), Vec3::Zero());
  for (const Triangle& t : triangles) {
    const Vec3 n = (body.vertices[t[1]] - body.vertices[t[0]]).cross(body.vertices[t[2]] - body.vertices[t[0]]);
    for (int c : t) normal[c] += n;
  }
  for (size_t v = 0; v < skin.vertices.size(); ++v)
    if (normal[v].norm() > 0.0) skin.vertices[v] += ease * normal[v].normalized();
  return skin;
}

// The surfaces the openings are cut along and which cuts each of the skin's vertices (numbered
// as the body's): the sleeves' ends across each upper arm's axis, each plane cutting only its
// own arm's vertices (the plane runs on through the torso beside the arm), the neckline round
// the neck's base, and the hem level, cutting the rest.
struct OpeningCuts {
  std::vector<CutSurface> surfaces;  // sleeves' ends (left, right), neckline, hem
  std::vector<int> surfaceOf;        // per vertex
};

OpeningCuts openingCuts(const TriangleMesh& skin, const TriangleMesh& body, const Skeleton& skeleton,
                        const std::vector<int>& triangleParts, const ShirtRegion& region) {
  const std::vector<int> vertexPart = vertexParts(body, triangleParts, skeleton.parts.size());
  std::vector<Vec3> neck;  // the neck's skin about its base
  for (size_t v = 0; v < skin.vertices.size(); ++v)
    if (vertexPart[v] >= 0 && skeleton.parts[vertexPart[v]].name == "neck" &&
        std::abs(body.vertices[v].y() - region.neckBaseHeight()) < kNeckBand)
      neck.push_back(skin.vertices[v]);
  if (neck.empty()) throw std::invalid_argument("body: no neck at the neck's base");
  OpeningCuts cuts;
  cuts.surfaces = {region.sleeveEnd("shoulderL", "elbowL"), region.sleeveEnd("shoulderR", "elbowR"),
                   region.neckline(neck), region.hem()};
  cuts.surfaceOf.assign(skin.vertices.size(), 2);
  for (size_t v = 0; v < skin.vertices.size(); ++v) {
    if (vertexPart[v] < 0) continue;
    const std::string& part = skeleton.parts[vertexPart[v]].name;
    if (part == "upperArmL") cuts.surfaceOf[v] = 0;
    if (part == "upperArmR") cuts.surfaceOf[v] = 1;
  }
  return cuts;
}

// `skin` at `triangles` sections whose openings have twice the vertices decimation alone
// leaves them: decimated to fewer sections, as many fewer as the openings have edges at the
// full count, and those edges split (about a third of the skin's boundary vertices stay).
TriangleMesh resampledWithFineOpenings(const TriangleMesh& skin, int triangles) {
  DecimationOptions decimation;
  decimation.perimeterWeight = kOpeningWeight;
  auto openingEdges = [](const TriangleMesh& mesh) {
    int edges = 0;
    for (const std::vector<int>& loop : boundaryLoops(mesh.triangles)) edges += static_cast<int>(loop.size());
    return edges;
  };
  // Fewer sections, as many fewer as the openings then have edges: a few rounds find the count.
  int coarser = triangles;
  TriangleMesh mesh = resampled(skin, coarser, decimation);
  for (int round = 0; round < kCountRounds && coarser + openingEdges(mesh) != triangles; ++round) {
    coarser = std::max(1, std::min(triangles, coarser + triangles - (coarser + openingEdges(mesh))));
    mesh = resampled(skin, coarser, decimation);
  }
  return numberedByFirstUse(withBoundaryEdgesSplit(mesh, triangles - static_cast<int>(mesh.triangles.size())));
}

// The openings of `shirt` smoothed along the surfaces they were cut along: each loop on the
// surface its vertices lie nearest, Taubin-smoothed there (decimation leaves its vertices
// unevenly spaced, and a snapped corner may step off the curve by a few millimetres).
void smoothOpenings(TriangleMesh& shirt, const std::vector<CutSurface>& surfaces) {
  for (const std::vector<int>& loop : boundaryLoops(shirt.triangles)) {
    double nearest = std::numeric_limits<double>::infinity();
    const CutSurface* on = nullptr;
    for (const CutSurface& surface : surfaces) {
      double farthest = 0;
      for (int v : loop) farthest = std::max(farthest, std::abs(signedDistance(surface, shirt.vertices[v])));
      if (farthest < nearest) nearest = farthest, on = &surface;
    }
    smoothLoop(shirt.vertices, loop, kSmoothingSteps, [on](const Vec3& x) { return projected(*on, x); });
  }
}

}  // namespace

TShirt makeTShirt(const TriangleMesh& body, const TShirtOptions& options) {
  options.validate();
  const Skeleton skeleton = estimateSkeleton(body);
  const std::vector<int> parts = assignTriangles(body, skeleton);
  const ShirtRegion region(skeleton, options);
  std::vector<Triangle> chosen;
  for (size_t f = 0; f < body.triangles.size(); ++f) {
    const Triangle& t = body.triangles[f];
    const double top = std::max({body.vertices[t[0]].y(), body.vertices[t[1]].y(), body.vertices[t[2]].y()});
    if (region.covers(skeleton.parts[parts[f]].name, top)) chosen.push_back(t);
  }
  removeSpikes(chosen);
  chosen = largestPiece(chosen);

  TShirt shirt;
  // Each opening cut along its surface (corners within kHemSnap of it moved onto it, so the
  // cut leaves no slivers): the hem level and straight, the neckline round the neck, the
  // sleeves' ends square to the arms.
  TriangleMesh skin = offsetSkin(body, chosen, options.ease);
  const OpeningCuts cuts = openingCuts(skin, body, skeleton, parts, region);
  skin = clippedBySurfaces(skin, cuts.surfaces, cuts.surfaceOf, kHemSnap);
  skin = clippedByPlane(skin, region.hem(), kHemSnap);
  skin.triangles = largestPiece(skin.triangles);  // what the cuts parted from the shirt goes
  skin = numberedByFirstUse(skin);
  shirt.skinTriangles = static_cast<int>(skin.triangles.size());
  shirt.mesh = resampledWithFineOpenings(skin, options.triangles);
  smoothOpenings(shirt.mesh, cuts.surfaces);
  shirt.hemHeight = region.hemHeight();
  shirt.area = surfaceArea(shirt.mesh);
  return shirt;
}

}  // namespace figment
