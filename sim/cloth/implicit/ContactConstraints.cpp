#include "sim/cloth/implicit/ContactConstraints.h"

#include <algorithm>
#include <limits>

#include "sim/cloth/ContactResponse.h"

namespace figment {

namespace {
constexpr double kSearchMargin = 0.02;  // m a query looks beyond what it must, so later steps may skip
// A sticking node slides when |J_t| > (1 + this) mu j_n: a node at the cone's edge does
// not switch back and forth.
constexpr double kReleaseMargin = 0.05;
constexpr double kBand = 1e-5;  // m
// A node held and pressing that ends a step above the clearance by at most this is put
// back on it. Sliding held on a curved or faceted body ends a step off the surface by
// about d^2 / 2R (0.8 mm on a 5 mm radius: 60 um), past kBand: let go, the node fell
// back in, was pushed out and held again, every other step for ever (a strap node of
// the dress at 1/20 s: 0.8 mm a step, so never at rest). Farther off, it lifted off.
constexpr double kFollowBand = 2e-4;  // m
// A node pushed out of one side of a crease is pushed out of the other at most this many
// times more (ContactConstraints::leaveCrease).
constexpr int kCreasePushes = 4;
// A crease's two normals this close to opposite (|n1 + n2| under it: sides 179 degrees
// apart) give no bisector to leave along; the node is pushed along the normal as before.
constexpr double kCreaseParallel = 0.02;
// Leaving a crease along its bisector moves a node at most this many clearances a push: in
// a crease of 160 degrees, 2.9 times the push along the normal.
constexpr double kCreaseExitClearances = 4.0;
// Nodes per parallel task: far nodes skip the body's query, so the work per node varies.
constexpr int kNodesPerTask = 64;

Vec3 tangential(const Vec3& v, const Vec3& normal) {
  return v - v.dot(normal) * normal;
}
}  // namespace

ContactConstraints::ContactConstraints(std::shared_ptr<const Collider> body, const ClothParameters& parameters,
                                       size_t nodes)
    : body_(std::move(body)),
      clearance_(parameters.clearance),
      mu_(parameters.friction),
      leaveCreases_(parameters.implicitSolver.leaveCreases),
      // A node sliding on a curved or faceted surface drifts off it by rounding; within
      // this band it is still held (at its height). No more: a node held above the
      // clearance rests there, and a garment held a band farther out rests elsewhere
      // (a band of 0.25 clearance left a skirt's waistband 4 mm higher on the hips).
      band_(kBand),
      distanceBound_(nodes, 0.0),
      released_(nodes, 0),
      held_(nodes, 0),
      switched_(nodes, 0),
      sticking_(nodes, 0),
      normalImpulse_(nodes, 0.0),
      normalChange_(nodes, Vec3::Zero()),
      friction_(nodes, Vec3::Zero()) {}

void ContactConstraints::stick(int i, const Vec3& v, NodeFilter& filter) {
  sticking_[i] = 1;
  friction_[i] = Vec3::Zero();
  filter.kind[i] = NodeFilter::Fixed;
  filter.prescribed[i] = normalChange_[i] - tangential(v, filter.normal[i]);
}

void ContactConstraints::slide(int i, NodeFilter& filter) {
  sticking_[i] = 0;
  filter.kind[i] = NodeFilter::Sliding;
  filter.prescribed[i] = normalChange_[i];
}

void ContactConstraints::constrain(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double dt, bool firstStep,
                                   NodeFilter& filter) {
  if (!body_) return;
  const double reach = clearance_ + band_;
  const double search = firstStep ? std::numeric_limits<double>::infinity() : reach + kSearchMargin;
  const int n = static_cast<int>(x.size());
  // Each node's query and state are its own: the nodes in parallel, in any order.
#pragma omp parallel for schedule(dynamic, kNodesPerTask)
  for (int i = 0; i < n; ++i) {
    const bool released = released_[i];
    released_[i] = held_[i] = switched_[i] = 0;  // a release lasts one step
    friction_[i] = Vec3::Zero();
    if (filter.kind[i] == NodeFilter::Fixed || distanceBound_[i] > reach) {
      sticking_[i] = 0;
      continue;
    }
    Contact contact;
    const bool touching = body_->contact(x[i], reach, search, contact);
    distanceBound_[i] = contact.distance;
    if (!touching || (released && contact.distance >= clearance_)) {
      sticking_[i] = 0;
      continue;
    }
    const Vec3& normal = contact.normal;
    held_[i] = 1;
    filter.normal[i] = normal;
    // Out to the clearance by the step's end; a node in the band above it keeps its
    // height (pulled down, it would read as lifting off, a pull, and be let go).
    const double targetSpeed = std::max(0.0, clearance_ - contact.distance) / dt;
    normalChange_[i] = (targetSpeed - v[i].dot(normal)) * normal;
    if (sticking_[i]) {
      stick(i, v[i], filter);
      continue;
    }
    slide(i, filter);
    // Sliding on: friction against the motion, as large as the last step's normal impulse allows.
    const Vec3 vt = tangential(v[i], normal);
    const double speed = vt.norm();
    if (speed > 0.0) friction_[i] = (-mu_ * std::max(0.0, normalImpulse_[i]) / speed) * vt;
  }
}

double ContactConstraints::updateNode(int i, const Vec3& impulse, const Vec3& vEnd, const Vec3& vStart, double mass,
                                      NodeFilter& filter) {
  const Vec3& normal = filter.normal[i];
  const double jn = impulse.dot(normal);
  normalImpulse_[i] = jn;
  released_[i] = jn < 0.0;
  const double limit = mu_ * std::max(0.0, jn);
  if (sticking_[i] && filter.kind[i] == NodeFilter::Fixed) {
    // Held by J_t: it slides when that leaves the cone, with friction along J_t.
    const Vec3 held = tangential(impulse, normal);
    const double force = held.norm();
    if (force <= (1.0 + kReleaseMargin) * limit || switched_[i]) return 0.0;
    switched_[i] = 1;
    slide(i, filter);
    friction_[i] = (limit / force) * held;
    return force - limit;
  }
  const Vec3 vt = tangential(vEnd, normal);
  const double speed = vt.norm();
  const bool hadFriction = friction_[i].squaredNorm() > 0.0;
  if (hadFriction && vt.dot(friction_[i]) >= 0.0) {
    // Friction turned it around: it stops. Once a step: a node that slid off this step
    // stops at the step's end (finish()) and sticks from the next.
    sticking_[i] = 1;
    if (switched_[i]) return 0.0;
    switched_[i] = 1;
    stick(i, vStart, filter);
    return mass * speed;
  }
  friction_[i] = speed > 0.0 ? Vec3((-limit / speed) * vt) : Vec3(Vec3::Zero());
  return hadFriction ? 0.0 : std::min(limit, mass * speed);
}

double ContactConstraints::update(const std::vector<Vec3>& impulse, const std::vector<Vec3>& v,
                                  const std::vector<Vec3>& y, const std::vector<double>& masses, NodeFilter& filter) {
  if (!body_) return 0.0;
  double changed = 0.0;
  const int n = static_cast<int>(v.size());
  for (int i = 0; i < n; ++i)
    if (held_[i]) changed += updateNode(i, impulse[i], v[i] + y[i], v[i], masses[i], filter);
  return changed;
}

void ContactConstraints::finish(const NodeFilter& filter, const std::vector<Vec3>& xStart,
                                const std::vector<Vec3>& vStart, double dt, bool firstStep, std::vector<Vec3>& x,
                                std::vector<Vec3>& v) {
  if (!body_) return;
  const int n = static_cast<int>(x.size());
#pragma omp parallel for schedule(dynamic, kNodesPerTask)
  for (int i = 0; i < n; ++i) {
    if (filter.kind[i] == NodeFilter::Fixed && !held_[i]) continue;
    if (held_[i]) {
      const Vec3& normal = filter.normal[i];
      if (sticking_[i]) v[i] = v[i].dot(normal) * normal;
      const double normalSpeed = v[i].dot(normal);
      v[i] += (std::min(normalSpeed, std::max(0.0, vStart[i].dot(normal))) - normalSpeed) * normal;
    }
    const Vec3 solved = x[i];
    respondIfTouching(*body_, clearance_, mu_, dt, firstStep, kSearchMargin, xStart[i], x[i], v[i], distanceBound_[i]);
    if (held_[i] && !released_[i]) followSurface(x[i], v[i], distanceBound_[i]);
    if (leaveCreases_ && x[i] != solved) leaveCrease(x[i], v[i]);
  }
}

void ContactConstraints::leaveCrease(Vec3& x, Vec3& v) const {
  Vec3 previous = Vec3::Zero();  // the last push's direction out of the other side
  for (int push = 0; push < kCreasePushes; ++push) {
    Contact contact;
    if (!body_->contact(x, clearance_, clearance_ + kSearchMargin, contact)) return;
    // Outside the body, or deeper in it than a clearance (not a crease's other side: a
    // node through the body, which a push would tear from its neighbours).
    if (contact.distance >= 0.0 || contact.distance < -clearance_) return;
    Vec3 out = contact.normal;
    double distance = clearance_ - contact.distance;
    // Two sides facing each other across a crease narrower than a right angle (an arm
    // pressed to the torso): pushes along each normal in turn land inside the other side
    // (the women's 7XL T-shirt: 1 mm inside after four). Leave along the crease's
    // bisector instead, which moves away from both: as far as puts the node at the
    // clearance from this side, and farther from the side it left.
    const Vec3 bisector = previous + contact.normal;
    if (previous.dot(contact.normal) < 0.0 && bisector.norm() > kCreaseParallel) {
      out = bisector.normalized();
      distance = std::min(distance / out.dot(contact.normal), kCreaseExitClearances * clearance_);
    }
    x += distance * out;
    v -= std::min(0.0, v.dot(contact.normal)) * contact.normal;
    if (v.dot(previous) < 0.0) {
      // Still moving into the side it left: only along the crease's line is into neither.
      const Vec3 line = previous.cross(contact.normal);
      v = line.squaredNorm() > 0.0 ? Vec3((v.dot(line) / line.squaredNorm()) * line)
                                   : Vec3(v - v.dot(previous) * previous);
    }
    previous = contact.normal;
  }
}

void ContactConstraints::followSurface(Vec3& x, Vec3& v, double& distanceBound) const {
  Contact contact;
  if (!body_->contact(x, clearance_ + kFollowBand, clearance_ + kFollowBand, contact)) return;
  if (contact.distance <= clearance_) return;  // on it (respondIfTouching put it there)
  x += (clearance_ - contact.distance) * contact.normal;
  v -= std::max(0.0, v.dot(contact.normal)) * contact.normal;
  distanceBound = clearance_;
}

}  // namespace figment
