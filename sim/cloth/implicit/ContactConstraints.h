#pragma once
// The body's contacts in a backward Euler step, as constraints of the solve (Baraff &
// Witkin 1998, §5), with Coulomb friction inside the solve and a final push-out:
//
//  1. before the solve (constrain): a node within clearance + band of the body at the
//     step's start is held on the surface: its velocity change along the body's normal
//     is prescribed so that it ends the step at the clearance (an outward push for a
//     node inside; none for a node in the band above). A node whose constraint pulled
//     it towards the body in the last step is let go for one step (it is lifting off),
//     unless it is inside the clearance.
//     A held node either sticks (held in all three directions: its tangential velocity
//     ends at zero) or slides (free along the surface, with a friction impulse of
//     mu j_n against its motion in the solve's right-hand side, friction()). Each
//     starts the step as it ended the last one.
//  2. after each solve (update): with the constraints' impulses J = A y - b (j_n along
//     the normal, J_t along the surface), a sticking node whose J_t leaves the cone
//     |J_t| <= mu j_n slides (friction along J_t); a sliding node whose friction turned
//     its tangential velocity around sticks; a sliding node with no friction yet gets
//     it. The step solves again while anything changed (ImplicitEuler.h), so the solve
//     sees each node's friction with the mass and stiffness it is coupled to: a strap
//     node pulled by a stretched neighbour slides, a rigid sheet on an incline sticks.
//  3. after the positions (finish): a held node keeps no normal velocity beyond what it
//     had away from the body (the push-out never launches it); any node inside the
//     clearance at the end (a free node that ran into the body, a held one on a curved
//     surface) gets the explicit path's response (sim/cloth/ContactResponse.h): it ends
//     on the surface + clearance. A held node pressing on the body that ended a little
//     above the clearance (sliding along its tangent plane over a curved surface) is
//     put back on it, so it stays held (followSurface). A node these moved that lies
//     inside the body again (pushed from one side of a crease into the other) is pushed
//     out again where the parameters ask (leaveCrease).
// Far nodes skip the body's queries, as in the explicit path: each keeps a lower bound
// of its distance, lowered by its motion.

#include <memory>
#include <vector>

#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/implicit/FilteredPcg.h"
#include "sim/collision/Collider.h"

namespace figment {

class ContactConstraints {
 public:
  ContactConstraints(std::shared_ptr<const Collider> body, const ClothParameters& parameters, size_t nodes);

  // Marks the held nodes Sliding or (sticking) Fixed in `filter` (Fixed nodes are left
  // as they are) and sets their friction impulses.
  void constrain(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double dt, bool firstStep, NodeFilter& filter);
  // N s per node: the friction impulses to add to the solve's right-hand side.
  const std::vector<Vec3>& friction() const { return friction_; }
  // After a solve: `impulse` = A y - b (b with the friction), `v` the velocities at the
  // step's start, `y` the solve's change. Each node changes between sticking and
  // sliding once a step at most. Returns the sum over the nodes that changed (or got
  // their first friction) of how much their tangential impulse changed, N s, as far
  // as the node alone tells (the step may solve again when it is large).
  double update(const std::vector<Vec3>& impulse, const std::vector<Vec3>& v, const std::vector<Vec3>& y,
                const std::vector<double>& masses, NodeFilter& filter);
  void finish(const NodeFilter& filter, const std::vector<Vec3>& xStart, const std::vector<Vec3>& vStart, double dt,
              bool firstStep, std::vector<Vec3>& x, std::vector<Vec3>& v);

  // m: how far beyond the clearance a node is still taken as touching.
  double band() const { return band_; }

 private:
  // A held node pressing on the body that ended the step just above the clearance (it
  // slid along its tangent plane over a curved surface) is put back on the clearance,
  // with no velocity away from the body.
  void followSurface(Vec3& x, Vec3& v, double& distanceBound) const;
  // A node the push-out moved, in a crease of the body (an armpit, where arm and torso
  // meet at a sharp angle), may have been pushed out of one side into the other: it is
  // pushed out along the nearest surface again, a few times at most, while it is inside
  // the body by less than a clearance; between two sides that face each other, along the
  // crease's bisector, out of both. Before, such nodes rested up to 0.9 mm inside the
  // arm (the women's 7XL T-shirt's back panel). Only nodes inside: pushing nodes out of
  // both sides' clearance tore the women's fitted shirt in 3XL and 4XL; and not deeper: a
  // node through the body (a sewing's first steps) would be torn from its neighbours.
  void leaveCrease(Vec3& x, Vec3& v) const;
  void stick(int i, const Vec3& v, NodeFilter& filter);
  void slide(int i, NodeFilter& filter);
  double updateNode(int i, const Vec3& impulse, const Vec3& vEnd, const Vec3& vStart, double mass, NodeFilter& filter);

  std::shared_ptr<const Collider> body_;
  double clearance_, mu_;
  bool leaveCreases_;  // ImplicitSolverParameters::leaveCreases
  double band_;
  std::vector<double> distanceBound_;  // m, per node, at its current position
  std::vector<char> released_, held_, switched_, sticking_;
  std::vector<double> normalImpulse_;  // N s, per node: j_n of the last solve
  std::vector<Vec3> normalChange_;     // the prescribed velocity change along the normal
  std::vector<Vec3> friction_;         // N s, per node
};

}  // namespace figment
