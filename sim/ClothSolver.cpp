#include "ClothSolver.h"

#include "Validation.h"

#include <chrono>
#include <cmath>
#include <string>

namespace figment {

ClothSolver::ClothSolver(const TriangleMesh& garment, const ClothParameters& parameters,
                         std::shared_ptr<const Collider> body)
    : parameters_(parameters), body_(std::move(body)) {
  parameters_.validate();
  model_ = std::make_unique<ClothModel>(garment, parameters_);
  x_ = garment.vertices;
  v_.assign(x_.size(), Vec3::Zero());
  pinned_.assign(x_.size(), 0);
  bodyDistanceBound_.assign(x_.size(), 0.0);
}

ClothSolver::~ClothSolver() = default;

void ClothSolver::pin(int node) { pinned_.at(node) = 1; }

const std::vector<Vec3>& ClothSolver::positions() const { return x_; }
const std::vector<Vec3>& ClothSolver::velocities() const { return v_; }
double ClothSolver::time() const { return time_; }
int ClothSolver::iterations() const { return iterations_; }

double ClothSolver::maxSpeed() const {
  double fastest = 0.0;
  for (const Vec3& v : v_) fastest = std::max(fastest, v.norm());
  return fastest;
}

bool ClothSolver::atRest() const {
  return restSince_ >= 0.0 && time_ - restSince_ >= parameters_.rest.window - 1e-12;
}

namespace {
constexpr double kContactSearchMargin = 0.02;  // m beyond clearance and motion a query looks

// Contact response on one node that ended the step inside the body or within the
// clearance: place it on the surface plus clearance, and make its velocity the motion
// it actually made this step ((x - xPrevious) / dt), so that a node the body holds in
// place is at rest instead of carrying a velocity the projection keeps undoing. Any
// velocity left into the body is removed; friction then removes tangential velocity in
// proportion to the normal velocity the contact took away (Coulomb: static while
// |v_t| <= mu dv_n, sliding and slowed otherwise).
void respondToContact(const Contact& contact, double clearance, double friction, double dt, const Vec3& xPrevious,
                      Vec3& x, Vec3& v) {
  const Vec3 target = contact.surfacePoint + clearance * contact.normal;
  const double removedNormalSpeed = std::max(0.0, (target - x).dot(contact.normal)) / dt;
  x = target;
  v = (x - xPrevious) / dt;
  const double normalSpeed = v.dot(contact.normal);
  if (normalSpeed < 0.0) v -= normalSpeed * contact.normal;
  const Vec3 tangential = v - std::max(0.0, normalSpeed) * contact.normal;
  const double tangentialSpeed = tangential.norm();
  const double frictionLimit = friction * removedNormalSpeed;
  if (tangentialSpeed <= frictionLimit)
    v -= tangential;
  else
    v -= tangential * (frictionLimit / tangentialSpeed);
}
}  // namespace

void ClothSolver::step() {
  const double dt = parameters_.timeStep;
  const size_t n = x_.size();
  // Improved Euler (Heun): predictor with the slopes at t, corrector with their mean
  // and the slopes at the predicted state.
  model_->accelerations(x_, v_, a0_);
  xPredicted_.resize(n);
  vPredicted_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    xPredicted_[i] = x_[i] + dt * v_[i];
    vPredicted_[i] = v_[i] + dt * a0_[i];
  }
  model_->accelerations(xPredicted_, vPredicted_, a1_);
  double fastest = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (pinned_[i]) {
      v_[i].setZero();
      continue;
    }
    const Vec3 previous = x_[i];
    x_[i] += 0.5 * dt * (v_[i] + vPredicted_[i]);
    v_[i] += 0.5 * dt * (a0_[i] + a1_[i]);
    if (body_) {
      const double moved = (x_[i] - previous).norm();
      double& bound = bodyDistanceBound_[i];
      bound -= moved;
      if (bound <= parameters_.clearance) {
        // Look well beyond this step's motion so that the bound then lets the next
        // steps skip the query; on the first step look everywhere, since a garment may
        // start roughly placed with nodes inside the body (paper §3.3).
        const double searchRadius = iterations_ == 0 ? std::numeric_limits<double>::infinity()
                                                     : parameters_.clearance + 2.0 * moved + kContactSearchMargin;
        Contact contact;
        if (body_->contact(x_[i], parameters_.clearance, searchRadius, contact)) {
          respondToContact(contact, parameters_.clearance, parameters_.friction, dt, previous, x_[i], v_[i]);
          bound = parameters_.clearance;
        } else {
          bound = contact.distance;
        }
      }
    }
    const double speed = v_[i].norm();
    if (!std::isfinite(speed) || !x_[i].allFinite() || speed > kBlowUpSpeed)
      throw SimulationError("simulation blew up at step " + std::to_string(iterations_ + 1) + " (t = " +
                            formatNumber(time_ + dt) + " s): node " + std::to_string(i) + " speed " +
                            formatNumber(speed) + " m/s; timeStep = " + formatNumber(dt) +
                            " s, method improved Euler (Heun)");
    fastest = std::max(fastest, speed);
  }
  time_ += dt;
  ++iterations_;
  if (fastest < parameters_.rest.speedThreshold) {
    if (restSince_ < 0.0) restSince_ = time_;
  } else {
    restSince_ = -1.0;
  }
}

DrapeResult ClothSolver::run(const std::function<void(const DrapeProgress&)>& progress, double progressInterval) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto lastReport = start;
  const int firstIteration = iterations_;
  // Stop at maxTime, counted in steps so that rounding never adds or drops one.
  const int totalSteps = static_cast<int>(std::ceil(parameters_.maxTime / parameters_.timeStep - 1e-9));
  while (iterations_ < totalSteps && !atRest()) {
    step();
    if (progress && (iterations_ & 63) == 0) {
      const auto now = Clock::now();
      if (std::chrono::duration<double>(now - lastReport).count() >= progressInterval) {
        progress({iterations_, time_, maxSpeed()});
        lastReport = now;
      }
    }
  }
  DrapeResult result;
  result.iterations = iterations_ - firstIteration;
  result.simulatedTime = time_;
  result.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  result.atRest = atRest();
  return result;
}

}  // namespace figment
