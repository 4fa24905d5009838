#include "sim/body/SkeletonEstimate.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "sim/body/BodySlices.h"
#include "sim/body/BodyStance.h"

namespace figment {

namespace {

constexpr double kHeight = 1.66;      // m: the default body's, where BodySlices' thresholds hold
constexpr double kWaistShare = 0.66;  // the default body's waist, crotch to armpits

Vec3 findUp(const std::vector<Vec3>& vertices) {
  if (const std::optional<Vec3> up = standingUpDirection(vertices)) return *up;
  throw std::invalid_argument("no up axis with two feet below and one head above: not a standing humanoid");
}

// The centroid of a cluster's section points, as (x, y, z) at height y.
Vec3 centroidAt(const XCluster& c, double y) {
  Vec2 m = Vec2::Zero();
  for (const Vec2& p : c.points) m += p;
  m /= static_cast<double>(std::max<size_t>(1, c.points.size()));
  return {m.x(), y, m.y()};
}

// The two leg clusters at height y (the torso-band clusters, left = +x first), or none.
std::vector<XCluster> legsAt(const TriangleMesh& body, double y) {
  std::vector<XCluster> legs;
  for (XCluster& c : clusterByX(planeSection(body, SectionAxis::Y, y), 0.02))
    if (c.maxX > -0.25 && c.minX < 0.25) legs.push_back(std::move(c));
  if (legs.size() != 2) return {};
  if (legs[0].minX < legs[1].minX) std::swap(legs[0], legs[1]);
  return legs;
}

Vec3 torsoCentre(const TriangleMesh& body, double y) {
  const TorsoSlice s = sliceTorso(body, y);
  if (s.empty()) throw std::invalid_argument("no torso section at height " + std::to_string(y));
  const Vec2 c = s.centroid();
  return {c.x(), y, c.y()};
}

// The body in the estimate's frame: y up, facing +z, 1.66 m tall, centred in x, feet
// at y = 0; a point p of it is R^T ((p - shift) / scale) in the input's frame.
struct NormalisedBody {
  TriangleMesh body;
  Eigen::Matrix3d R;
  double scale;
  Vec3 shift;
};

// Forward (horizontal, unit) of a body already turned y up, `bounds` its bounds: from the
// legs just above the ankles towards the feet.
Vec3 forwardOf(const std::vector<Vec3>& turned, const Bounds& bounds) {
  const double height = bounds.size().y();
  const double ankleSlab = bounds.min.y() + 0.08 * height, footSlab = bounds.min.y() + 0.03 * height;
  Vec3 legs = Vec3::Zero(), feet = Vec3::Zero();
  int nLegs = 0, nFeet = 0;
  for (const Vec3& v : turned) {
    if (std::abs(v.y() - ankleSlab) < 0.01 * height) legs += v, ++nLegs;
    if (v.y() < footSlab) feet += v, ++nFeet;
  }
  if (nLegs == 0 || nFeet == 0) throw std::invalid_argument("no feet found");
  Vec3 forward = feet / nFeet - legs / nLegs;
  forward.y() = 0.0;
  if (forward.norm() < 1e-9) throw std::invalid_argument("the feet do not point anywhere");
  return forward.normalized();
}

// Steps 1-2: up, forward, scale.
NormalisedBody normalise(const TriangleMesh& input) {
  const Vec3 up = findUp(input.vertices);
  NormalisedBody n;
  n.R = Eigen::Quaterniond::FromTwoVectors(up, Vec3::UnitY()).toRotationMatrix();
  std::vector<Vec3> turned;
  for (const Vec3& v : input.vertices) turned.push_back(n.R * v);
  Bounds b = boundsOf(turned);
  const double height = b.size().y();
  const Vec3 forward = forwardOf(turned, b);
  n.R = Eigen::AngleAxisd(std::atan2(forward.x(), forward.z()), -Vec3::UnitY()).toRotationMatrix() * n.R;
  n.scale = kHeight / height;
  n.body = input;
  for (Vec3& v : n.body.vertices) v = n.scale * (n.R * v);
  b = boundsOf(n.body.vertices);
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : n.body.vertices) mean += v;
  mean /= static_cast<double>(n.body.vertices.size());
  n.shift = Vec3(-mean.x(), -b.min.y(), 0.0);
  for (Vec3& v : n.body.vertices) v += n.shift;
  return n;
}

struct Landmarks {
  double crotch, armpit, neck, waist;  // heights, m
};

// Step 3a: the heights the joints are placed at.
Landmarks landmarksOf(const TriangleMesh& body) {
  Landmarks l;
  l.crotch = -1.0;
  for (double y = 0.3 * kHeight; y < 0.6 * kHeight; y += 0.005)
    if (!legsAt(body, y).empty()) l.crotch = y;
  if (l.crotch < 0.0) throw std::invalid_argument("the legs never part: no crotch found");
  l.armpit = armpitHeight(body);
  l.neck = neckHeight(body, l.armpit);
  l.waist = l.crotch + 0.1;
  double narrowest = std::numeric_limits<double>::max();
  const double highest = l.armpit - 0.05;
  for (double y = l.crotch + 0.1; y < highest; y += 0.005) {
    const TorsoSlice s = sliceTorso(body, y);
    if (!s.empty() && s.maxX() - s.minX() < narrowest) narrowest = s.maxX() - s.minX(), l.waist = y;
  }
  // A torso that narrows all the way up to the armpits (a broad-hipped or barrel-chested
  // body without a waist) has its narrowest section at the top of the range, just under
  // the chest, which would leave the lower torso a sliver: take the default body's
  // proportion instead, its waist 66 % of the way from the crotch to the armpits.
  if (l.waist > highest - 0.01) l.waist = l.crotch + kWaistShare * (l.armpit - l.crotch);
  return l;
}

// The humanoid's joint positions (humanoidJointNames' order), set by name.
struct Joints {
  std::array<Vec3, 25> at;
  void set(const char* name, const Vec3& p) {
    const auto& names = humanoidJointNames();
    at[std::find(names.begin(), names.end(), name) - names.begin()] = p;
  }
};

// Step 3b: the spine and the head.
void placeSpine(const TriangleMesh& body, const Landmarks& l, Joints& j) {
  j.set("pelvisFloor", torsoCentre(body, l.crotch + 0.02) - Vec3(0, 0.02, 0));
  j.set("pelvis", torsoCentre(body, l.crotch + 0.08));
  j.set("waist", torsoCentre(body, l.waist));
  j.set("chest", torsoCentre(body, l.armpit - 0.03));
  j.set("neckBase", torsoCentre(body, l.neck - 0.04));
  j.set("neckTop", torsoCentre(body, l.neck + 0.03));
  Vec3 top = body.vertices.front();
  for (const Vec3& v : body.vertices)
    if (v.y() > top.y()) top = v;
  j.set("headTop", Vec3(0.5 * (j.at[3].x() + j.at[4].x()), top.y(), j.at[4].z()));
}

// Step 3c: hips, knees, ankles from the leg sections; toes, each foot's front point.
void placeLegs(const TriangleMesh& body, const Landmarks& l, Joints& j) {
  const double legHeights[3] = {l.crotch - 0.03, 0.285 * kHeight, 0.045 * kHeight};
  const char* legJoints[2][3] = {{"hipL", "kneeL", "ankleL"}, {"hipR", "kneeR", "ankleR"}};
  for (int k = 0; k < 3; ++k) {
    const std::vector<XCluster> pair = legsAt(body, legHeights[k]);
    if (pair.empty()) throw std::invalid_argument("no pair of legs at height " + std::to_string(legHeights[k]));
    for (int side = 0; side < 2; ++side) {
      Vec3 c = centroidAt(pair[side], legHeights[k]);
      if (k == 0) c.y() = l.crotch + 0.04;  // the hip joint sits above the crotch
      j.set(legJoints[side][k], c);
    }
  }
  for (int side = 0; side < 2; ++side) {
    Vec3 toe(0, 0, -std::numeric_limits<double>::max());
    for (const Vec3& v : body.vertices)
      if (v.y() < 0.04 * kHeight && (side == 0 ? v.x() > 0 : v.x() < 0) && v.z() > toe.z()) toe = v;
    j.set(side == 0 ? "toeL" : "toeR", toe);
  }
}

// The arm's fingertip on one side (sign +1: +x): the farthest from `shoulder` of the
// points that are surely arm. Below the armpits: the section points of the clusters clear
// of the torso on that side (arm, hand, fingers), scanned down until there are none, and
// the vertices between those sections or just below the last (the tip lies between two
// scans). Above the armpits: the vertices beyond the torso's edge (an arm held out level).
// Not every vertex beyond the torso's edge: where the arms hang close to the sides
// (HUMAN.blend), a wide hip's flank is beyond the chest's edge and farther from the
// shoulder than a hand that ends above it.
Vec3 fingertip(const TriangleMesh& body, const Landmarks& l, const Vec3& shoulder, double torsoEdge, double sign) {
  constexpr double kStep = 0.005, kTipMargin = 0.03;  // m
  std::vector<Vec3> candidates;
  for (const Vec3& v : body.vertices)
    if (v.y() >= l.armpit && sign * v.x() > sign * torsoEdge + 0.02) candidates.push_back(v);
  // A cluster clear of the torso on this side: its inner edge beyond the torso's edge.
  const auto clear = [&](const XCluster& c) { return (sign > 0 ? c.minX : -c.maxX) >= sign * torsoEdge; };
  struct ArmSection {
    double y, minX, maxX;  // the x range of the arm's clusters at height y
  };
  std::vector<ArmSection> arm;
  for (double y = l.armpit - kStep; y > l.crotch; y -= kStep) {
    std::optional<ArmSection> here;
    for (const XCluster& c : clusterByX(planeSection(body, SectionAxis::Y, y), 0.02)) {
      if (!clear(c)) continue;  // the torso, the legs or the other arm
      for (const Vec2& p : c.points) candidates.emplace_back(p.x(), y, p.y());
      here = here ? ArmSection{y, std::min(here->minX, c.minX), std::max(here->maxX, c.maxX)}
                  : ArmSection{y, c.minX, c.maxX};
    }
    if (!here) break;  // the arm has ended (or joins the torso)
    arm.push_back(*here);
  }
  // Vertices between two sections, or just below the lowest, within the x range of the
  // sections beside them (1 cm more for the slope between).
  for (const Vec3& v : body.vertices)
    for (const ArmSection& a : arm)
      if (std::abs(v.y() - a.y) <= (&a == &arm.back() ? kTipMargin : kStep) && v.x() >= a.minX - 0.01 &&
          v.x() <= a.maxX + 0.01) {
        candidates.push_back(v);
        break;
      }
  Vec3 tip = shoulder;
  for (const Vec3& v : candidates)
    if ((v - shoulder).squaredNorm() > (tip - shoulder).squaredNorm()) tip = v;
  return tip;
}

// Step 3d: shoulders from the section above the armpits; elbow and wrist along the line
// to the fingertip (above).
void placeArms(const TriangleMesh& body, const Landmarks& l, Joints& j) {
  const TorsoSlice shoulders = sliceTorso(body, l.armpit + 0.07);
  const Vec3 chest = torsoCentre(body, l.armpit + 0.07);
  const double outline[2] = {shoulders.maxX(), shoulders.minX()};
  const double torsoEdge[2] = {sliceTorso(body, l.armpit - 0.03).maxX(), sliceTorso(body, l.armpit - 0.03).minX()};
  const char* armJoints[2][5] = {{"shoulderBaseL", "shoulderL", "elbowL", "wristL", "fingertipL"},
                                 {"shoulderBaseR", "shoulderR", "elbowR", "wristR", "fingertipR"}};
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 0 ? 1.0 : -1.0;
    const Vec3 shoulder(outline[side] - sign * 0.04, l.armpit + 0.07, chest.z());
    j.set(armJoints[side][0], Vec3(chest.x() + sign * 0.05, l.armpit + 0.09, chest.z()));
    j.set(armJoints[side][1], shoulder);
    const Vec3 tip = fingertip(body, l, shoulder, torsoEdge[side], sign);
    j.set(armJoints[side][2], shoulder + 0.42 * (tip - shoulder));
    j.set(armJoints[side][3], shoulder + 0.75 * (tip - shoulder));
    j.set(armJoints[side][4], tip);
  }
}

}  // namespace

Skeleton estimateSkeleton(const TriangleMesh& input) {
  if (input.vertices.size() < 100) throw std::invalid_argument("too few vertices for a body");
  const NormalisedBody n = normalise(input);
  const Landmarks landmarks = landmarksOf(n.body);
  Joints joints;
  placeSpine(n.body, landmarks, joints);
  placeLegs(n.body, landmarks, joints);
  placeArms(n.body, landmarks, joints);
  // 4. Back into the input's frame and unit.
  std::vector<Vec3> positions;
  for (const Vec3& p : joints.at) positions.push_back(n.R.transpose() * ((p - n.shift) / n.scale));
  return humanoidSkeleton(positions);
}

}  // namespace figment
