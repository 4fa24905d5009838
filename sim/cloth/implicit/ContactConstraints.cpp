#include "sim/cloth/implicit/ContactConstraints.h"

#include "sim/cloth/ContactResponse.h"

#include <algorithm>
#include <limits>

namespace figment {

namespace {
constexpr double kSearchMargin = 0.02;  // m a query looks beyond what it must, so later steps may skip
}

ContactConstraints::ContactConstraints(std::shared_ptr<const Collider> body, const ClothParameters& parameters,
                                       size_t nodes)
    : body_(std::move(body)),
      clearance_(parameters.clearance),
      friction_(parameters.friction),
      // A node resting on a curved surface drifts off it by a fraction of a millimetre
      // as it slides; within this band it is still held.
      band_(0.25 * parameters.clearance + 1e-5),
      distanceBound_(nodes, 0.0),
      released_(nodes, 0) {}

void ContactConstraints::constrain(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double dt,
                                   bool firstStep, NodeFilter& filter) {
  if (!body_) return;
  const double reach = clearance_ + band_;
  const double search = firstStep ? std::numeric_limits<double>::infinity() : reach + kSearchMargin;
  const int n = static_cast<int>(x.size());
  for (int i = 0; i < n; ++i) {
    if (filter.kind[i] == NodeFilter::Fixed || distanceBound_[i] > reach) continue;
    Contact contact;
    const bool touching = body_->contact(x[i], reach, search, contact);
    distanceBound_[i] = contact.distance;
    if (!touching || (released_[i] && contact.distance >= clearance_)) continue;
    const Vec3& normal = contact.normal;
    filter.kind[i] = NodeFilter::Sliding;
    filter.normal[i] = normal;
    // Out to the clearance by the step's end; a node in the band above it keeps its
    // height (pulled down, it would read as lifting off, a pull, and be let go).
    const double targetSpeed = std::max(0.0, clearance_ - contact.distance) / dt;
    filter.prescribed[i] = (targetSpeed - v[i].dot(normal)) * normal;
  }
}

void ContactConstraints::applyFriction(const NodeFilter& filter, const std::vector<Vec3>& impulse,
                                       const std::vector<double>& masses, std::vector<Vec3>& v) {
  const int n = static_cast<int>(v.size());
  for (int i = 0; i < n; ++i) {
    released_[i] = 0;  // a release lasts one step
    if (filter.kind[i] != NodeFilter::Sliding) continue;
    const Vec3& normal = filter.normal[i];
    const double push = impulse[i].dot(normal);
    released_[i] = push < 0.0;
    if (push <= 0.0 || masses[i] <= 0.0) continue;
    const Vec3 tangential = v[i] - v[i].dot(normal) * normal;
    const double speed = tangential.norm(), limit = friction_ * push / masses[i];
    v[i] -= speed <= limit ? tangential : Vec3(tangential * (limit / speed));
  }
}

void ContactConstraints::finish(const NodeFilter& filter, const std::vector<Vec3>& xStart,
                                const std::vector<Vec3>& vStart, double dt, bool firstStep, std::vector<Vec3>& x,
                                std::vector<Vec3>& v) {
  if (!body_) return;
  const int n = static_cast<int>(x.size());
  for (int i = 0; i < n; ++i) {
    if (filter.kind[i] == NodeFilter::Fixed) continue;
    if (filter.kind[i] == NodeFilter::Sliding) {
      const Vec3& normal = filter.normal[i];
      const double normalSpeed = v[i].dot(normal);
      v[i] += (std::min(normalSpeed, std::max(0.0, vStart[i].dot(normal))) - normalSpeed) * normal;
    }
    const double moved = (x[i] - xStart[i]).norm();
    double& bound = distanceBound_[i];
    bound -= moved;
    if (bound > clearance_) continue;
    const double search =
        firstStep ? std::numeric_limits<double>::infinity() : clearance_ + 2.0 * moved + kSearchMargin;
    Contact contact;
    if (body_->contact(x[i], clearance_, search, contact)) {
      respondToContact(contact, clearance_, friction_, dt, xStart[i], x[i], v[i]);
      bound = clearance_;
    } else {
      bound = contact.distance;
    }
  }
}

}  // namespace figment
