#pragma once
// Everything that shapes one drape besides the garment and the body (SI units).

#include "sim/cloth/Material.h"
#include "sim/cloth/Wind.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

struct RestRule {
  double speedThreshold = 0.01;  // m/s: the cloth is at rest when every node is slower...
  double window = 0.25;          // s: ...for this long without interruption
};

// How a step advances positions and velocities from the accelerations (paper §2).
enum class Integrator {
  ExplicitEuler,    // x += dt v(t);  v += dt a(t)                         first order
  SymplecticEuler,  // v += dt a(t);  x += dt v(t+dt)                      first order
  Heun,             // improved Euler: mean of the slopes at t and at the
                    // explicit Euler prediction                            second order
  Implicit,         // backward Euler, linearised (Baraff & Witkin 1998): one Newton
                    // step on M dv = dt f(x + dt (v + dv), v + dv), solved by
                    // filtered PCG with the contacts as constraints
                    // (sim/cloth/implicit/ImplicitEuler.h)          first order,
                    // stable at any step; ignores the limiters and strainLimit
};
const char* integratorName(Integrator integrator);  // "explicit Euler", ...

// The paper's second stability measure (§2, Fig. 2.3): a limit on the acceleration each
// node gets from the cloth's elastic forces (membrane and bending), applied before
// gravity, air, wind and the strain-rate damping are added (sim/cloth/ClothModel.h).
enum class AccelerationLimiter {
  None,
  Clamp,  // |a| > a_max  ->  a_max a/|a|           (the paper's choice)
  Tanh,   // a -> a_max tanh(|a|/a_max) a/|a|       (smooth, a little dearer)
};

// The bending stiffness in the implicit integrator's matrix (sim/cloth/implicit/BendingHessian.h).
enum class BendingStiffness {
  Joints,    // a bound per joint (4 nodes): fewer blocks, cheaper steps
  Sections,  // the sections' exact Gauss-Newton form (6 nodes each)
};

// The implicit solve's preconditioner (sim/cloth/implicit/FilteredPcg.h).
enum class Preconditioner {
  BlockJacobi,  // each node's 3x3 block
  TwoLevel,     // plus a coarse correction over aggregates of nodes (CoarseCorrection.h)
};

// How the implicit integrator meets the body.
enum class ContactModel {
  Constraints,  // held nodes, velocity constraints of the solve (ContactConstraints.h)
  Penalty,      // springs and friction forces inside the solve (ContactPenalty.h)
};

// The linear solve of the implicit integrator (sim/cloth/implicit/FilteredPcg.h).
struct ImplicitSolverParameters {
  // PCG stops when |residual| <= tolerance |right-hand side|. At 1 % the dress rests
  // as far from the converged reference as at 1e-4, in a third of the wall time; at
  // 3 % it never rests at 1/20 s.
  double tolerance = 1e-2;
  int maxIterations = 300;  // PCG iterations per time step, at most
  // A step's first solve starts from the last step's velocity change, scaled along
  // itself to the least error energy (FilteredPcg.h, PcgStart::Guess), instead of from
  // zero. Off: at the 1 % stop the answer keeps what the start held in the garment's
  // smooth motions (the stop sees them poorly), and the last step's motion carried on
  // leaves drapes moving: warm, the T-shirt at 1/20 s never rests and the dress at 1/50 s
  // takes 56 PCG iterations a step instead of 36 (docs/results.md, issue 42).
  bool warmStart = false;
  // The step grows while the cloth is quiet: a step the step control kept whole
  // (ImplicitEuler.h) whose fastest node was slower than the step before's (the first
  // step has none before it: a garment let go is not quiet) makes the next
  // kStepGrowth times longer, up to maxTimeStep (s); any other step makes the next half as
  // long, never shorter than timeStep (a skirt still sliding on the hips, or contacts
  // chattering, go back to the scene's step). Backward Euler damps what it cannot
  // resolve, so long steps carry a garment that has stopped falling to its rest shape as
  // a Newton iteration on f = 0 would: the default dress rests in 9 steps instead of 40
  // (docs/results.md, issue 42). Each step's PCG stop tightens by timeStep / dt, so the
  // velocity's error stays the scene step's. 0 (the default): every step is timeStep.
  double maxTimeStep = 0.0;
  static constexpr double kStepGrowth = 1.5;
  // The largest step the size advice's and the service's drapes of cut styles grow to from
  // 0.05 s: on the dress, T-shirt, close fit and layered outfit 0.2 s is no closer to the
  // converged drape and up to twice as slow, 0.8 s no faster (docs/results.md, issue 42).
  static constexpr double kShippedMaxTimeStep = 0.4;
  // A node the contacts pushed out of the body into another side of it (a crease: an
  // armpit) is pushed out of that one too (ContactConstraints::leaveCrease). On for sewn
  // garments (sim/drape/GarmentDrape.cpp): the women's T-shirt 7XL and dress 6XL rested
  // with nodes up to 0.9 mm inside the arm without it, and sew clean with it. Off by
  // default: where an arm presses cloth against the torso (a shirt draped into arms
  // down) the node has no place outside both, and the pushes carried the shirt's side
  // round the arm (its waist girth 15 cm looser than standing; test_PosedBodyFit).
  bool leaveCreases = false;
  BendingStiffness bending = BendingStiffness::Joints;
  Preconditioner preconditioner = Preconditioner::TwoLevel;
  ContactModel contacts = ContactModel::Constraints;
  // Penalty contacts: spring k_i = penaltyRate m_i (1/s^2); a node slower than
  // stickSpeed (m/s) along the body sticks.
  double penaltyRate = 1e6;
  double stickSpeed = 1e-3;
};

struct ClothParameters {
  Material material;
  double timeStep = 1.5e-4;  // dt, s: stable for ~1.5 cm sections of 1 MPa cloth
  double maxTime = 5.0;      // s of simulated time, the run's upper bound
  RestRule rest;
  Vec3 gravity = Vec3(0.0, -9.81, 0.0);  // m/s^2
  double airResistance = 1.0;            // N*s/m^3: force per unit area per unit speed
  double friction = 0.4;                 // Coulomb coefficient against the body
  double clearance = 0.003;              // m kept between cloth nodes and the body surface
  double strainRateDamping = 1.0e-4;     // s: Kelvin-Voigt relaxation time of the membrane
  Integrator integrator = Integrator::Heun;
  // The paper's first stability measure: each section's Green strain components are
  // clamped into [-strainLimit, strainLimit] when its forces are computed; 0 = off.
  double strainLimit = 0.0;
  AccelerationLimiter accelerationLimiter = AccelerationLimiter::None;
  double accelerationLimit = 20.0;          // a_max in multiples of |g| (9.81 m/s^2 when g = 0)
  WindParameters wind;                      // paper §2 wind; amplitude 0 (the default) = none
  ImplicitSolverParameters implicitSolver;  // used by Integrator::Implicit only
  // Test only the body parts near the garment (sim/collision/BroadPhaseCollider.h). The
  // drape is the same either way; off only to measure what it saves.
  bool broadPhase = true;
  // a_max in m/s^2.
  double accelerationLimitSI() const;

  // A run takes at most this many steps (maxTime / timeStep): 10^7 steps of the smallest
  // garment take hours.
  static constexpr double kMaxSteps = 1e7;

  // Throws std::invalid_argument naming the field and value when out of range, or when
  // maxTime / timeStep exceeds kMaxSteps (then naming timeStep).
  void validate() const;
};

}  // namespace figment
