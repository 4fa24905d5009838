#pragma once
// The explicit path's contact response (paper §3: push-out, velocity, friction), also
// used by the implicit path for a node that ends a step inside the body.

#include "sim/collision/Collider.h"

namespace figment {

// Contact response on one node that ended the step inside the body or within the
// clearance, at x with the integrator's end-of-step velocity v:
//  - the velocity takes in the push-out: v + (target - x) / dt, so a node the body
//    holds in a crease does not keep a velocity that every push-out undoes; its normal
//    part is then limited to what the node had away from the body (the push-out never
//    launches a node, and velocity into the body is removed);
//  - friction (Coulomb) acts on the tangential part, limited by mu times the normal
//    velocity into the body that the contact removed. Static (|v_t| <= mu dv_n): the
//    node stops and keeps its tangential place from the start of the step. Sliding:
//    v_t shrinks by mu dv_n.
//  - the node ends on the surface + clearance.
void respondToContact(const Contact& contact, double clearance, double friction, double dt, const Vec3& xPrevious,
                      Vec3& x, Vec3& v);

// The same after a step for a node that keeps `distanceBound`, a lower bound of its
// distance to the body (m): lowered by how far it moved; only when that comes within
// the clearance is the body queried (out to `searchMargin` beyond what the motion
// needs; everywhere on the first step), and the bound set again from the answer.
void respondIfTouching(const Collider& body, double clearance, double friction, double dt, bool firstStep,
                       double searchMargin, const Vec3& xPrevious, Vec3& x, Vec3& v, double& distanceBound);

}  // namespace figment
