#pragma once
// The body's contacts in a backward Euler step, as constraints of the solve (Baraff &
// Witkin 1998, §5), with Coulomb friction and a final push-out:
//
//  1. before the solve (constrain): a node within clearance + band of the body at the
//     step's start is held on the surface: its velocity change along the body's normal
//     is prescribed so that it ends the step at the clearance (an outward push for a
//     node inside; none for a node in the band above), and it moves freely along the
//     surface. A node whose constraint pulled it towards the body in the last step is
//     let go for one step (it is lifting off), unless it is inside the clearance.
//  2. after the solve (applyFriction): the constraint's impulse A y - b along the
//     normal, j >= 0, limits the tangential velocity change friction can make:
//     |v_t| <= mu j / m stops the node (static), else v_t shrinks by mu j / m (sliding).
//  3. after the positions (finish): a held node keeps no normal velocity beyond what it
//     had away from the body (the push-out never launches it); any node inside the
//     clearance at the end (a free node that ran into the body, a held one on a curved
//     surface) gets the explicit path's response (sim/cloth/ContactResponse.h): it ends
//     on the surface + clearance.
// Far nodes skip the body's queries, as in the explicit path: each keeps a lower bound
// of its distance, lowered by its motion.

#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/implicit/FilteredPcg.h"
#include "sim/collision/Collider.h"

#include <memory>
#include <vector>

namespace figment {

class ContactConstraints {
 public:
  ContactConstraints(std::shared_ptr<const Collider> body, const ClothParameters& parameters, size_t nodes);

  // Marks the held nodes Sliding in `filter` (Fixed nodes are left as they are).
  void constrain(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double dt, bool firstStep,
                 NodeFilter& filter);
  // `impulse`: A y - b per node, N s; `v`: the end-of-step velocities, changed in place.
  void applyFriction(const NodeFilter& filter, const std::vector<Vec3>& impulse, const std::vector<double>& masses,
                     std::vector<Vec3>& v);
  void finish(const NodeFilter& filter, const std::vector<Vec3>& xStart, const std::vector<Vec3>& vStart, double dt,
              bool firstStep, std::vector<Vec3>& x, std::vector<Vec3>& v);

  // m: how far beyond the clearance a node is still taken as touching.
  double band() const { return band_; }

 private:
  std::shared_ptr<const Collider> body_;
  double clearance_, friction_, band_;
  std::vector<double> distanceBound_;  // m, per node, at its current position
  std::vector<char> released_;
};

}  // namespace figment
