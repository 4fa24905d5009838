#pragma once
// The body's contacts in a backward Euler step as penalty forces inside the solve, the
// alternative to constraints (ContactConstraints.h; ClothParameters::implicitSolver.contacts):
//
//  - normal: a node within the clearance of the body at the step's start is pushed out
//    by a spring k_i (clearance - d) along the body's normal, linearised in the solve
//    (dt^2 k_i n n^T on its diagonal block): a force, not a held state, so nothing
//    switches between held and let go, and a node that lifts off feels the spring fade
//    to zero. k_i = penaltyRate m_i: stiff against the step (dt^2 k_i / m_i = 2,500 at
//    1/20 s), so a node carrying the weight of the cloth below it rests a fraction of a
//    millimetre inside the clearance, and the same at every resolution (a progressive
//    mesh's coarse levels have heavier nodes).
//  - friction, Coulomb with the spring's force at the step's end (from the last solve;
//    the start's before the first, and the step solves again while it moves more than
//    10 % at a node): a node at rest sticks
//    by a stiff tangential damping mu f_n / stickSpeed (implicit: it creeps below
//    stickSpeed under any load inside the cone); a sliding node feels mu f_n against its
//    motion (explicit, in the right-hand side). After each solve a sticking node whose
//    damping force leaves the cone slides and a sliding node turned around sticks, and
//    the step solves again (ImplicitEuler.h); a node still turned around after the last
//    solve stops (its tangential velocity and motion are taken back).
//  - finish: a node that ends the step deeper than half the clearance (a fast one that
//    ran into the body) gets the explicit path's response (sim/cloth/ContactResponse.h)
//    to half the clearance; the spring does the rest.
// Far nodes skip the body's queries: each keeps a lower bound of its distance.

#include <memory>
#include <vector>

#include "sim/cloth/BlockSparseMatrix.h"
#include "sim/cloth/ClothParameters.h"
#include "sim/collision/Collider.h"

namespace figment {

class ContactPenalty {
 public:
  ContactPenalty(std::shared_ptr<const Collider> body, const ClothParameters& parameters, size_t nodes);

  // Finds the touching nodes at x and adds their springs and friction to the assembled
  // system: `matrix`'s diagonal blocks and `rhs` (dt times the forces, as ImplicitEuler's).
  void add(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const std::vector<double>& masses, double dt,
           bool firstStep, BlockSparseMatrix& matrix, std::vector<Vec3>& rhs);
  // After a solve of velocity change `y` from v: switches nodes between sticking and
  // sliding where the solve says so and rewrites their terms. True when any switched.
  bool update(const std::vector<Vec3>& v, const std::vector<Vec3>& y, double dt, BlockSparseMatrix& matrix,
              std::vector<Vec3>& rhs);
  // After the positions: stops sliding nodes friction turned around, and pushes nodes
  // that ran deep into the body back out.
  void finish(const std::vector<Vec3>& xStart, double dt, bool firstStep, std::vector<Vec3>& x, std::vector<Vec3>& v);

 private:
  struct Touch {
    int node = 0, block = 0;                                 // the node and its diagonal block in the matrix
    Vec3 normal, sliding;                                    // sliding: unit direction of its motion while it slides
    double stiffness = 0.0, depth = 0.0, normalForce = 0.0;  // N/m, m (at the start), N
    bool slides = false;
    Block3 assembled;  // the diagonal block and right-hand side before the contact's terms
    Vec3 assembledRhs;
  };
  void apply(const Touch& t, const Vec3& v, double dt, BlockSparseMatrix& matrix, std::vector<Vec3>& rhs) const;

  std::shared_ptr<const Collider> body_;
  double clearance_, mu_, rate_, stickSpeed_;
  std::vector<double> distanceBound_;  // m, per node
  std::vector<Contact> contact_;       // per node, at the step's start
  std::vector<char> touching_;
  std::vector<Touch> touches_;
};

}  // namespace figment
