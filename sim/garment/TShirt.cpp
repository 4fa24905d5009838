#include "sim/garment/TShirt.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "sim/body/BodyParts.h"
#include "sim/body/SkeletonEstimate.h"
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

// Whether the shirt covers triangle t of the body.
class ShirtRegion {
 public:
  ShirtRegion(const Skeleton& skeleton, const TShirtOptions& options)
      : skeleton_(skeleton),
        hem_(skeleton["pelvisFloor"].position.y() + options.hemAboveCrotch),
        neckline_(skeleton["neckBase"].position.y() - options.necklineDrop),
        share_(options.sleeveShare) {}

  double hemHeight() const { return hem_; }

  // `top`: the triangle's highest corner; a triangle across the hem is kept whole here
  // and cut along it later.
  bool covers(const std::string& part, const Vec3& centroid, double top) const {
    if (part == "upperTorso" || part == "lowerTorso") return true;
    // Over the hips' sides the thighs' parts reach above the hem.
    if (part == "hips" || part == "thighL" || part == "thighR") return top > hem_;
    if (part == "neck") return centroid.y() < neckline_;  // the slopes down to the shoulders
    if (part == "upperArmL") return withinSleeve(centroid, "shoulderL", "elbowL");
    if (part == "upperArmR") return withinSleeve(centroid, "shoulderR", "elbowR");
    return false;
  }

 private:
  bool withinSleeve(const Vec3& c, const char* shoulder, const char* elbow) const {
    const Vec3 from = skeleton_[shoulder].position, to = skeleton_[elbow].position;
    const Vec3 axis = to - from;
    return (c - from).dot(axis) <= share_ * axis.squaredNorm();
  }

  const Skeleton& skeleton_;
  double hem_, neckline_, share_;
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

// The skin region with each vertex moved `ease` out along its area-weighted normal.
TriangleMesh offsetSkin(const TriangleMesh& body, const std::vector<Triangle>& triangles, double ease) {
  TriangleMesh skin{body.vertices, triangles};
  std::vector<Vec3> normal(body.vertices.size(), Vec3::Zero());
  for (const Triangle& t : triangles) {
    const Vec3 n = (body.vertices[t[1]] - body.vertices[t[0]]).cross(body.vertices[t[2]] - body.vertices[t[0]]);
    for (int c : t) normal[c] += n;
  }
  for (size_t v = 0; v < skin.vertices.size(); ++v)
    if (normal[v].norm() > 0.0) skin.vertices[v] += ease * normal[v].normalized();
  return numberedByFirstUse(skin);
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
    const Vec3 centroid = (body.vertices[t[0]] + body.vertices[t[1]] + body.vertices[t[2]]) / 3.0;
    const double top = std::max({body.vertices[t[0]].y(), body.vertices[t[1]].y(), body.vertices[t[2]].y()});
    if (region.covers(skeleton.parts[parts[f]].name, centroid, top)) chosen.push_back(t);
  }
  removeSpikes(chosen);

  chosen = largestPiece(chosen);
  TShirt shirt;
  // The hem level and straight: cut along the plane (corners within kHemSnap of it moved
  // onto it, so the cut leaves no slivers).
  const Plane hem{Vec3(0.0, region.hemHeight(), 0.0), Vec3::UnitY()};
  const TriangleMesh skin = clippedByPlane(offsetSkin(body, chosen, options.ease), hem, kHemSnap);
  shirt.skinTriangles = static_cast<int>(skin.triangles.size());
  shirt.mesh = resampled(skin, options.triangles);
  shirt.hemHeight = region.hemHeight();
  shirt.area = surfaceArea(shirt.mesh);
  return shirt;
}

}  // namespace figment
