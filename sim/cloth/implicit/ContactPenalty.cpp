#include "sim/cloth/implicit/ContactPenalty.h"

#include <algorithm>
#include <limits>

#include "sim/cloth/ContactResponse.h"

namespace figment {

namespace {
constexpr double kSearchMargin = 0.02;   // m a query looks beyond what it must, so later steps may skip
constexpr double kReleaseMargin = 0.05;  // a sticking node slides beyond (1 + this) mu f_n
constexpr int kNodesPerTask = 64;
constexpr double kForceChange = 0.1;  // a node's friction is solved again when its normal force moves more

Vec3 tangential(const Vec3& v, const Vec3& normal) {
  return v - v.dot(normal) * normal;
}
}  // namespace

ContactPenalty::ContactPenalty(std::shared_ptr<const Collider> body, const ClothParameters& parameters, size_t nodes)
    : body_(std::move(body)),
      clearance_(parameters.clearance),
      mu_(parameters.friction),
      rate_(parameters.implicitSolver.penaltyRate),
      stickSpeed_(parameters.implicitSolver.stickSpeed),
      distanceBound_(nodes, 0.0),
      contact_(nodes),
      touching_(nodes, 0) {}

void ContactPenalty::add(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const std::vector<double>& masses,
                         double dt, bool firstStep, BlockSparseMatrix& matrix, std::vector<Vec3>& rhs) {
  touches_.clear();
  if (!body_) return;
  const double search = firstStep ? std::numeric_limits<double>::infinity() : clearance_ + kSearchMargin;
  const int n = static_cast<int>(x.size());
  // Each node's query is its own: in parallel, in any order.
#pragma omp parallel for schedule(dynamic, kNodesPerTask)
  for (int i = 0; i < n; ++i) {
    touching_[i] = 0;
    if (distanceBound_[i] > clearance_) continue;
    touching_[i] = body_->contact(x[i], clearance_, search, contact_[i]);
    distanceBound_[i] = contact_[i].distance;
  }
  for (int i = 0; i < n; ++i) {
    if (!touching_[i]) continue;
    Touch t;
    t.node = i;
    t.normal = contact_[i].normal;
    t.stiffness = rate_ * masses[i];
    t.depth = clearance_ - contact_[i].distance;
    t.normalForce = t.stiffness * t.depth;  // until a solve tells the step's
    t.block = matrix.find(i, i);
    t.assembled = matrix.block(t.block);
    t.assembledRhs = rhs[i];
    const Vec3 vt = tangential(v[i], t.normal);
    t.slides = vt.norm() > stickSpeed_;
    if (t.slides) t.sliding = vt.normalized();
    apply(t, v[i], dt, matrix, rhs);
    touches_.push_back(t);
  }
}

void ContactPenalty::apply(const Touch& t, const Vec3& v, double dt, BlockSparseMatrix& matrix,
                           std::vector<Vec3>& rhs) const {
  // The spring f = k (clearance - d(x)) n, linearised: df/dx = -k n n^T.
  const Block3 nn = t.normal * t.normal.transpose();
  Block3& block = matrix.block(t.block);
  block = t.assembled + dt * dt * t.stiffness * nn;
  Vec3& b = rhs[t.node];
  b = t.assembledRhs + dt * t.stiffness * (t.depth - dt * t.normal.dot(v)) * t.normal;
  if (t.slides) {
    b -= dt * mu_ * t.normalForce * t.sliding;
  } else {
    const double damping = mu_ * t.normalForce / stickSpeed_;  // N s/m
    block += dt * damping * (Block3::Identity() - nn);
    b -= dt * damping * tangential(v, t.normal);
  }
}

bool ContactPenalty::update(const std::vector<Vec3>& v, const std::vector<Vec3>& y, double dt,
                            BlockSparseMatrix& matrix, std::vector<Vec3>& rhs) {
  bool switched = false;
  for (Touch& t : touches_) {
    const Vec3 vEnd = v[t.node] + y[t.node];
    // Friction goes with the spring's force over the step (its end, implicit), not the
    // start's: a node that arrives deep and is pushed out does not drag with the
    // arrival's force.
    const double force = std::max(0.0, t.stiffness * (t.depth - dt * t.normal.dot(vEnd)));
    const bool forceChanged = std::abs(force - t.normalForce) > kForceChange * std::max(force, t.normalForce);
    t.normalForce = force;
    const Vec3 vt = tangential(vEnd, t.normal);
    const double limit = mu_ * t.normalForce;
    const double stickForce = mu_ * t.normalForce / stickSpeed_ * vt.norm();
    if (!t.slides && stickForce > (1.0 + kReleaseMargin) * limit) {
      t.slides = true;  // the load leaves the cone
      t.sliding = vt.normalized();
    } else if (t.slides && vt.dot(t.sliding) < 0.0) {
      t.slides = false;  // friction turned it around: it stops
    } else if (!forceChanged) {
      continue;
    }
    switched = true;
    apply(t, v[t.node], dt, matrix, rhs);
  }
  return switched;
}

void ContactPenalty::finish(const std::vector<Vec3>& xStart, double dt, bool firstStep, std::vector<Vec3>& x,
                            std::vector<Vec3>& v) {
  if (!body_) return;
  for (const Touch& t : touches_) {
    if (!t.slides) continue;
    const double back = v[t.node].dot(t.sliding);
    if (back >= 0.0) continue;
    v[t.node] -= back * t.sliding;  // turned around after the last solve: it stops
    x[t.node] -= dt * back * t.sliding;
  }
  const double hard = 0.5 * clearance_;
  const int n = static_cast<int>(x.size());
#pragma omp parallel for schedule(dynamic, kNodesPerTask)
  for (int i = 0; i < n; ++i)
    respondIfTouching(*body_, hard, mu_, dt, firstStep, kSearchMargin, xStart[i], x[i], v[i], distanceBound_[i]);
}

}  // namespace figment
