#include "sim/cloth/ContactResponse.h"

#include <algorithm>
#include <limits>

namespace figment {

void respondToContact(const Contact& contact, double clearance, double friction, double dt, const Vec3& xPrevious,
                      Vec3& x, Vec3& v) {
  const Vec3& n = contact.normal;
  const Vec3 target = contact.surfacePoint + clearance * n;
  const double normalSpeedBefore = v.dot(n);
  const double removedNormalSpeed = std::max(0.0, -normalSpeedBefore);
  v += (target - x) / dt;
  const double normalSpeed = std::clamp(v.dot(n), 0.0, std::max(0.0, normalSpeedBefore));
  const Vec3 tangential = v - v.dot(n) * n;
  const double tangentialSpeed = tangential.norm();
  const double frictionLimit = friction * removedNormalSpeed;
  if (tangentialSpeed <= frictionLimit) {
    v = normalSpeed * n;
    x = xPrevious + (target - xPrevious).dot(n) * n;
  } else {
    v = normalSpeed * n + tangential * (1.0 - frictionLimit / tangentialSpeed);
    x = target;
  }
}

void respondIfTouching(const Collider& body, double clearance, double friction, double dt, bool firstStep,
                       double searchMargin, const Vec3& xPrevious, Vec3& x, Vec3& v, double& distanceBound) {
  const double moved = (x - xPrevious).norm();
  distanceBound -= moved;
  if (distanceBound > clearance) return;
  const double search = firstStep ? std::numeric_limits<double>::infinity() : clearance + 2.0 * moved + searchMargin;
  Contact contact;
  if (body.contact(x, clearance, search, contact)) {
    respondToContact(contact, clearance, friction, dt, xPrevious, x, v);
    distanceBound = clearance;
  } else {
    distanceBound = contact.distance;
  }
}

}  // namespace figment
