// Body measurements from landmarks on the mesh. Based on:
// - ISO 8559-1:2017 (body dimensions for clothing: the names and what each measures);
// - girths as convex perimeters: a taut tape is the convex hull of the section it encloses
//   (the hull by Andrew's monotone chain, sim/body/BodySlices.h);
// - landmarks from horizontal sections (sim/body/SectionLoops.h), in windows scaled by
//   stature / 1.7 m: the crotch is the lowest level where one piece of the section spans the
//   body's middle; the armpits the lowest level, above where the arms hang apart, where they
//   have joined the torso; the bust and the hips the fullest torso sections below the armpits
//   and above the crotch (EN 13402-1's "maximum horizontal girth"), the waist and the neck
//   the narrowest; the arm followed by sections perpendicular to its own axis, the wrist its
//   narrowest section before the hand widens;
// - the underbust "directly below the breasts" (ISO 8559-1): the fold under them, found on the
//   torso's front (its most forward z): walking down from the breasts' apex (the most forward
//   level within 4 cm under the bust), the lowest front so far until the front comes forward
//   again by 0.5 mm (the chest wall under the breast), kept between 2 cm under the bust and
//   60 % of the way to the waist. Its depth is how far the front recedes from the apex to it.
//   A flat chest has no fold, or one too shallow to tell from the chest wall's own waves (the
//   men's bodies of issue 31's grid: under 5 mm; the women's: 8 mm and more; human.zae: 11
//   mm): there the underbust is 3.5 cm under the bust, where the women's folds lie (2.8 to
//   4.0 cm). Between 4 and 7 mm of depth it moves linearly from that level to the fold's, so
//   it moves continuously as a bust grows from flat, rather than jump to wherever the lowest
//   front of the whole window is (on the smallest women's bodies, the ribcage's foot 8 cm
//   under the fold, issue 31). Depths and distances at 1.7 m, scaled by the stature.

#include "sim/body/BodyMeasurements.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "sim/body/BodySlices.h"
#include "sim/body/SectionLoops.h"

namespace figment {

namespace {

constexpr double kReferenceStature = 1.7;  // m: the windows below are for this stature, scaled
constexpr double kScanStep = 0.005;        // m between levels scanned
constexpr double kRefineStep = 0.001;      // m: levels found to this
constexpr double kTorsoBand = 0.1;         // m either side of the middle: torso and legs, never arms
constexpr double kArmStep = 0.01;          // m between sections along the arm
constexpr double kHandWidening = 4.0 / 3;  // the hand: sections this much wider than the wrist

struct Level {
  double height = 0;
  double value = 0;
};

class Tape {
 public:
  explicit Tape(const TriangleMesh& body) : body_(body), sections_(body) {
    const Bounds b = boundsOf(body.vertices);
    floor_ = b.min.y();
    stature_ = b.size().y();
    scale_ = stature_ / kReferenceStature;
    middle_ = 0.5 * (b.min.x() + b.max.x());
  }

  double floor() const { return floor_; }
  double stature() const { return stature_; }
  double scaled(double metres) const { return metres * scale_; }  // a length at 1.7 m, at this stature
  double middle() const { return middle_; }
  const TriangleMesh& body() const { return body_; }
  std::vector<SectionLoop> loops(double height) const { return sections_.at(height); }

  bool inTorsoBand(const SectionLoop& loop) const {
    const double band = scaled(kTorsoBand);
    return loop.bounds.max.x() >= middle_ - band && loop.bounds.min.x() <= middle_ + band;
  }
  std::vector<Vec3> torsoPoints(double height) const {
    std::vector<Vec3> points;
    for (const SectionLoop& loop : loops(height))
      if (inTorsoBand(loop)) points.insert(points.end(), loop.points.begin(), loop.points.end());
    return points;
  }
  double girth(double height) const { return convexPerimeter(torsoPoints(height), Vec3::UnitY()); }
  double front(double height) const {  // m: the torso's most forward z
    double z = -std::numeric_limits<double>::infinity();
    for (const Vec3& p : torsoPoints(height)) z = std::max(z, p.z());
    return z;
  }

  // The level in [low, high] where f is largest (sign +1) or smallest (-1): scanned, then refined.
  Level best(double low, double high, double sign, const std::function<double(double)>& f) const {
    Level found{low, sign * f(low)};
    for (double y = low + kScanStep; y <= high; y += kScanStep)
      if (const double v = sign * f(y); v > found.value) found = {y, v};
    const double centre = found.height;
    for (double y = std::max(low, centre - kScanStep); y <= std::min(high, centre + kScanStep); y += kRefineStep)
      if (const double v = sign * f(y); v > found.value) found = {y, v};
    found.value *= sign;
    return found;
  }

 private:
  const TriangleMesh& body_;
  HorizontalSections sections_;
  double floor_ = 0, stature_ = 0, scale_ = 1, middle_ = 0;
};

bool spansMiddle(const SectionLoop& loop, double middle) {
  return loop.bounds.min.x() < middle && loop.bounds.max.x() > middle;
}

// The crotch: the lowest level between 30 % and 65 % of the stature where one piece of the
// section spans the middle (below it, the legs are apart), found to 0.1 mm by bisection.
double crotchHeight(const Tape& tape) {
  const auto joined = [&](double y) {
    for (const SectionLoop& loop : tape.loops(y))
      if (spansMiddle(loop, tape.middle())) return true;
    return false;
  };
  const double low = tape.floor() + 0.3 * tape.stature(), high = tape.floor() + 0.65 * tape.stature();
  for (double y = low; y <= high; y += kScanStep) {
    if (!joined(y)) continue;
    double apart = y - kScanStep, together = y;
    while (together - apart > 1e-4) {
      const double mid = 0.5 * (apart + together);
      (joined(mid) ? together : apart) = mid;
    }
    return together;
  }
  throw std::invalid_argument("body: no crotch found (the legs never join between 30% and 65% of the stature)");
}

// The armpits: scanning up from the crotch, past the first level where a piece lies apart on
// each side of the torso band (the arms), the lowest level where none does any more (the arms
// have joined the torso); found to 1 mm.
double armpitHeight(const Tape& tape, double crotch) {
  const auto armsApart = [&](double y) {
    bool left = false, right = false;
    for (const SectionLoop& loop : tape.loops(y)) {
      if (tape.inTorsoBand(loop)) continue;
      left = left || loop.bounds.max.x() < tape.middle();
      right = right || loop.bounds.min.x() > tape.middle();
    }
    return left && right;
  };
  const double top = tape.floor() + 0.9 * tape.stature();
  double y = crotch + tape.scaled(0.1);
  while (y < top && !armsApart(y)) y += kScanStep;
  while (y < top && armsApart(y)) y += kScanStep;
  if (y >= top)
    throw std::invalid_argument("body: no armpits found (the arms never part from the torso and join it again)");
  double apart = y - kScanStep, joined = y;
  while (joined - apart > kRefineStep) {
    const double mid = 0.5 * (apart + joined);
    (armsApart(mid) ? apart : joined) = mid;
  }
  return apart;
}

// The arm's centre in the horizontal section at `height`: the piece on the +x side farthest
// from the middle outside the torso band.
Vec3 armCentre(const Tape& tape, double height) {
  const std::vector<SectionLoop> loops = tape.loops(height);
  const SectionLoop* arm = nullptr;
  for (const SectionLoop& loop : loops)
    if (!tape.inTorsoBand(loop) && loop.bounds.min.x() > tape.middle() &&
        (!arm || loop.points.size() > arm->points.size()))
      arm = &loop;
  if (!arm) throw std::invalid_argument("body: no arm found below the armpit");
  return arm->centroid();
}

// The piece of the section through `at` (normal `axis`) nearest `at`, within `reach` of it.
const SectionLoop* nearestLoop(const std::vector<SectionLoop>& loops, const Vec3& at, double reach) {
  const SectionLoop* nearest = nullptr;
  double distance = reach;
  for (const SectionLoop& loop : loops)
    if (const double d = (loop.centroid() - at).norm(); d < distance) distance = d, nearest = &loop;
  return nearest;
}

struct ArmTrack {
  std::vector<double> arc;    // m from the first section's centre
  std::vector<double> girth;  // m, perpendicular to the arm
};

// Follows the arm from `start` along `direction` (unit, towards the hand) in sections
// perpendicular to it, the direction turning with the sections' centres, to the fingertip.
ArmTrack followArm(const Tape& tape, Vec3 at, Vec3 direction) {
  ArmTrack track;
  std::vector<Vec3> centres;
  double arc = 0;
  for (int k = 0; k < 400; ++k) {
    const std::vector<SectionLoop> loops = sectionLoops(tape.body(), at, direction);
    const SectionLoop* loop = nearestLoop(loops, at, tape.scaled(0.05));
    if (!loop) break;
    const Vec3 centre = loop->centroid();
    if (!centres.empty()) arc += (centre - centres.back()).norm();
    centres.push_back(centre);
    track.arc.push_back(arc);
    track.girth.push_back(convexPerimeter(loop->points, direction));
    if (centres.size() > 3) direction = (centre - centres[centres.size() - 4]).normalized();
    at = centre + tape.scaled(kArmStep) * direction;
  }
  return track;
}

void measureArm(const Tape& tape, BodyMeasurements& m) {
  const Vec3 upper = armCentre(tape, tape.floor() + m.landmarks.armpit - tape.scaled(0.03));
  const Vec3 lower = armCentre(tape, tape.floor() + m.landmarks.armpit - tape.scaled(0.10));
  const Vec3 up = (upper - lower).normalized();  // along the upper arm, towards the shoulder
  const ArmTrack track = followArm(tape, upper, -up);
  if (track.girth.size() < 10) throw std::invalid_argument("body: the arm could not be followed to the hand");
  m.upperArmGirth = track.girth.front();
  // the wrist: the narrowest section past a quarter of the way to the fingertip, before the
  // hand widens the sections by a third (beyond, the sections are the fingers')
  const size_t n = track.girth.size();
  size_t wrist = n / 4;
  for (size_t k = n / 4; k < n && track.girth[k] < kHandWidening * track.girth[wrist]; ++k)
    if (track.girth[k] < track.girth[wrist]) wrist = k;
  // the shoulder point: the upper arm's axis continued up to the shoulder level
  const double rise = tape.floor() + m.landmarks.shoulder - upper.y();
  const double toShoulder = up.y() > 0.1 ? rise / up.y() : 0.0;
  m.armLength = toShoulder + track.arc[wrist];
}

constexpr double kApexReach = 0.04;     // m under the bust within which the breast's apex lies
constexpr double kFoldDetect = 0.0005;  // m the front comes forward again under a fold
constexpr double kFoldFaint = 0.004;    // m of depth (apex to fold) up to which a fold counts for nothing
constexpr double kFoldFull = 0.007;     // m of depth from which the fold alone is the underbust
constexpr double kFlatDrop = 0.035;     // m under the bust: the underbust where there is no fold

struct Fold {
  double height = 0;  // m, absolute
  double depth = 0;   // m the front recedes from the apex to the fold: 0 where there is none
};

// The fold under the breasts, at most `top` and at least `bottom` (absolute heights): walking
// down from the apex (the torso's most forward level within kApexReach under the bust), the
// lowest front so far until the front comes forward kFoldDetect past it. Depth 0 where it
// never comes forward again above `bottom`.
Fold findFold(const Tape& tape, double bust, double top, double bottom) {
  const auto front = [&](double y) { return tape.front(y); };
  std::vector<double> levels, fronts;  // from the bottom up as Tape::best scans them, on up to the bust
  for (double y = bottom; y <= bust; y += kScanStep) levels.push_back(y), fronts.push_back(front(y));
  size_t apex = levels.size();
  for (size_t k = 0; k < levels.size(); ++k)
    if (levels[k] >= bust - tape.scaled(kApexReach) && (apex == levels.size() || fronts[k] > fronts[apex])) apex = k;
  if (apex == levels.size() || apex == 0) return {};
  size_t lowest = apex;
  for (size_t k = apex; k-- > 0;) {
    if (fronts[k] < fronts[lowest])
      lowest = k;
    else if (fronts[k] > fronts[lowest] + tape.scaled(kFoldDetect))
      break;
    if (k == 0) return {};  // receding all the way down: no fold
  }
  // to the millimetre within the window, about the level it was found at
  const double centre = std::clamp(levels[lowest], std::min(bottom, top), top);
  const Level fold = tape.best(std::max(bottom, centre - kScanStep), std::min(top, centre + kScanStep), -1, front);
  return {fold.height, fronts[apex] - fold.value};
}

// The underbust (rules at the top of the file) under the bust at `bust` and above the waist
// at `waist` (absolute heights), searched as far down as 60 % of the way to the waist.
double underbustHeight(const Tape& tape, double bust, double waist) {
  const double top = bust - tape.scaled(0.02), bottom = bust - 0.6 * (bust - waist);
  const double flat = std::clamp(bust - tape.scaled(kFlatDrop), std::min(bottom, top), top);
  const Fold fold = findFold(tape, bust, top, bottom);
  const double share =
      std::clamp((fold.depth - tape.scaled(kFoldFaint)) / tape.scaled(kFoldFull - kFoldFaint), 0.0, 1.0);
  return share > 0 ? flat + share * (fold.height - flat) : flat;
}

// Which landmarks and parts a set of measurements needs (each landmark's own inputs
// included: the waist's window is anchored on the crotch and the armpits, ...).
struct Needs {
  bool crotch = false, armpit = false, neck = false, bust = false, waist = false, underbust = false, hip = false;
  bool arm = false;

  static Needs all() { return {true, true, true, true, true, true, true, true}; }
  static Needs of(const std::vector<std::string>& keys) {
    Needs n;
    for (const std::string& key : keys) {
      BodyMeasurements{}.byName(key);  // throws for an unknown key
      n.bust = n.bust || key == "bust_girth";
      n.underbust = n.underbust || key == "underbust_girth";
      n.waist = n.waist || key == "waist_girth";
      n.hip = n.hip || key == "hip_girth";
      n.neck = n.neck || key == "neck_girth" || key == "shoulder_width" || key == "arm_length";
      n.arm = n.arm || key == "upper_arm_girth" || key == "arm_length";
      n.crotch = n.crotch || key == "thigh_girth" || key == "inside_leg";
    }
    n.bust = n.bust || n.underbust;
    n.waist = n.waist || n.underbust || n.hip;
    n.neck = n.neck || n.arm;  // the arm's length starts at the shoulder level
    n.armpit = n.bust || n.waist || n.neck;
    n.crotch = n.crotch || n.armpit;
    return n;
  }
};

constexpr double kBellyRise = 0.02;   // m of girth regained over the dip above: a belly
constexpr double kChestDepth = 0.12;  // m under the armpits within which the chest itself lies
constexpr double kDipDepth = 0.005;   // m of girth a dip lies under the window's top girth

// The bust: the fullest level from 2 cm under the armpits down to 25 cm under them, or only
// down to the narrowest level above a belly (issue 43): walking down, where the girth more
// than 12 cm under the armpits is 2 cm over the narrowest girth above it, and that narrowest
// is 5 mm under the girth at the window's top (a waist between chest and belly, not the
// window's own top), the window ends at that narrowest level. Under a full belly the window's
// foot is fuller than the chest (a women's DOB 48 body: the "bust" found 8 cm under the waist;
// a men's HAKA 62 body, whose girth grows from just under the armpits to the belly: the belly),
// and the bust is the part above. A breast's own rise lies within the 12 cm (the apex 4 to 8
// cm under the armpits on the chart bodies); where the girth never regains 2 cm below, the
// window is the whole one, as before.
double bustHeight(const Tape& tape, double armpit) {
  const double top = armpit - tape.scaled(0.02), bottom = armpit - tape.scaled(0.25);
  const double topGirth = tape.girth(top);
  double dip = top, dipGirth = topGirth, foot = bottom;
  for (double y = top - kScanStep; y >= bottom; y -= kScanStep) {
    const double g = tape.girth(y);
    if (y < armpit - tape.scaled(kChestDepth) && g > dipGirth + tape.scaled(kBellyRise) &&
        dipGirth < topGirth - tape.scaled(kDipDepth)) {
      foot = dip;
      break;
    }
    if (g < dipGirth) dip = y, dipGirth = g;
  }
  return tape.best(foot, top, +1, [&](double y) { return tape.girth(y); }).height;
}

void findLandmarks(const Tape& tape, const Needs& needs, BodyLandmarks& l) {
  const double floor = tape.floor();
  if (needs.crotch) l.crotch = crotchHeight(tape) - floor;
  if (needs.armpit) l.armpit = armpitHeight(tape, floor + l.crotch) - floor;
  const auto girth = [&](double y) { return tape.girth(y); };
  if (needs.neck) {
    l.neck =
        tape.best(floor + l.armpit + tape.scaled(0.08), floor + tape.stature() - tape.scaled(0.12), -1, girth).height -
        floor;
    l.shoulder = 0.5 * (l.armpit + l.neck);
  }
  // fullest and narrowest levels in windows anchored on the crotch and the armpits, which move
  // continuously with the body: the girths then do too, and a fit can meet them
  if (needs.bust) l.bust = bustHeight(tape, floor + l.armpit) - floor;
  if (needs.waist)
    l.waist =
        tape.best(floor + l.crotch + tape.scaled(0.1), floor + l.armpit - tape.scaled(0.15), -1, girth).height - floor;
  if (needs.underbust) l.underbust = underbustHeight(tape, floor + l.bust, floor + l.waist) - floor;
  if (needs.hip) l.hip = tape.best(floor + l.crotch + tape.scaled(0.01), floor + l.waist, +1, girth).height - floor;
}

double thighGirth(const Tape& tape, double crotch) {
  double fullest = 0;
  for (const SectionLoop& loop : tape.loops(tape.floor() + crotch - tape.scaled(0.02)))
    if (tape.inTorsoBand(loop)) fullest = std::max(fullest, convexPerimeter(loop.points, Vec3::UnitY()));
  return fullest;
}

double shoulderWidth(const Tape& tape, double shoulder) {
  Bounds across;
  for (const SectionLoop& loop : tape.loops(tape.floor() + shoulder)) {
    across.extend(loop.bounds.min);
    across.extend(loop.bounds.max);
  }
  return across.empty() ? 0.0 : across.size().x();
}

}  // namespace

double convexPerimeter(const std::vector<Vec3>& points, const Vec3& normal) {
  const Vec3 u = normal.unitOrthogonal(), v = normal.normalized().cross(u);
  std::vector<Vec2> flat;
  flat.reserve(points.size());
  for (const Vec3& p : points) flat.emplace_back(p.dot(u), p.dot(v));
  const std::vector<Vec2> hull = convexHull(std::move(flat));
  if (hull.size() < 2) return 0.0;
  double perimeter = 0;
  for (size_t i = 0; i < hull.size(); ++i) perimeter += (hull[(i + 1) % hull.size()] - hull[i]).norm();
  return perimeter;
}

namespace {

BodyMeasurements measure(const TriangleMesh& body, const Needs& needs) {
  if (body.vertices.empty() || body.triangles.empty()) throw std::invalid_argument("body: no triangles");
  BodyMeasurements m;
  m.stature = boundsOf(body.vertices).size().y();
  if (!needs.crotch) return m;  // the stature alone: no sections
  const Tape tape(body);
  BodyLandmarks& l = m.landmarks;
  findLandmarks(tape, needs, l);
  const double floor = tape.floor();
  if (needs.bust) m.bustGirth = tape.girth(floor + l.bust);
  if (needs.underbust) m.underbustGirth = tape.girth(floor + l.underbust);
  if (needs.waist) m.waistGirth = tape.girth(floor + l.waist);
  if (needs.hip) m.hipGirth = tape.girth(floor + l.hip);
  if (needs.neck) {
    m.neckGirth = tape.girth(floor + l.neck);
    m.shoulderWidth = shoulderWidth(tape, l.shoulder);
  }
  if (needs.crotch) {
    m.thighGirth = thighGirth(tape, l.crotch);
    m.insideLeg = l.crotch;
  }
  if (needs.arm) measureArm(tape, m);
  return m;
}

}  // namespace

BodyMeasurements measureBody(const TriangleMesh& body) {
  return measure(body, Needs::all());
}

BodyMeasurements measureBody(const TriangleMesh& body, const std::vector<std::string>& keys) {
  return measure(body, Needs::of(keys));
}

std::vector<std::pair<std::string, double>> BodyMeasurements::named() const {
  return {{"stature", stature},
          {"bust_girth", bustGirth},
          {"underbust_girth", underbustGirth},
          {"waist_girth", waistGirth},
          {"hip_girth", hipGirth},
          {"neck_girth", neckGirth},
          {"shoulder_width", shoulderWidth},
          {"upper_arm_girth", upperArmGirth},
          {"thigh_girth", thighGirth},
          {"inside_leg", insideLeg},
          {"arm_length", armLength}};
}

double BodyMeasurements::byName(const std::string& key) const {
  for (const auto& [name, value] : named())
    if (name == key) return value;
  throw std::invalid_argument("no measurement named '" + key + "'");
}

}  // namespace figment
