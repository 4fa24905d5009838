#pragma once
// ClothEngine: drapes one garment on a body; its output feeds the garment's coordinates.

#include <Inventor/engines/SoSubEngine.h>
#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoMFVec2f.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <Inventor/fields/SoSFDouble.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFInt32.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/fields/SoSFString.h>
#include <Inventor/fields/SoSFVec3f.h>

#include <functional>
#include <memory>
#include <string>

namespace figment {
class ClothSolver;
struct DrapeContext;
struct DrapeReport;
struct ClothParameters;
struct TriangleMesh;
}  // namespace figment

/*!
  \class ClothEngine nodes/cloth/ClothEngine.h
  \brief Simulates a garment until it rests on a body; outputs the draped positions.

  Only a translator: the fields become a drape's ask (nodes/cloth/ClothEngineInputs.h:
  sim/cloth/ClothParameters.h, the garment, the body), sim/drape/DrapePlan.h plans and runs
  the drape from the rest shape until the cloth is at rest or maxTime has been simulated
  (or the drape cache has it), and the final node positions come out of `positions`. Like every Coin engine it is lazy:
  it simulates when its output is read after an input changed (on the first render, or when a bounding box is asked
  for), never once per render.

  Errors never escape: a field out of range, a coordIndex that does not index
  restPoints, a body that is not a collision body, or a simulation that blows up is
  stored as lastError() (one line naming the engine and the field and value, e.g.
  "ClothEngine 'Drape': thickness = -0.001 must be > 0"), posted through SoDebugError,
  and the output is the rest shape.

  In an .iv file an engine is written where its output is used. Coin 4 reads a field
  connection as `field = CONTAINER . name`, where CONTAINER is an engine written in
  place or `USE Name` of a node or engine defined earlier, and the value before `=` may
  be left out; `USE Pattern.point` and `USE Pattern . point` read the same:
  \code
    Switch { whichChild -1  DEF Pattern MeshFile { fileName "dress.obj" } }
    Coordinate3 {
      point = DEF Drape ClothEngine {
        restPoints = USE Pattern.point
        coordIndex = USE Pattern.coordIndex
        body USE Body
      } . positions
    }
    ClothingLayer { coordIndex = USE Pattern.coordIndex }
  \endcode
  The body's collision surface is taken in the body node's own coordinates and the
  garment's in the world frame: keep both under the same transform.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    ClothEngine {
        restPoints [ ]
        coordIndex [ ]
        panelPoints [ ]
        seams [ ]
        body NULL
        material ""
        thickness 0.0005
        density 300
        youngsModulus 1000000
        poissonRatio 0.3
        timeStep 0.05
        maxTimeStep 0
        maxTime 5
        restSpeed 0.01
        restWindow 0.25
        gravity 0 -9.81 0
        airResistance 1
        friction 0.4
        clearance 0.003
        strainRateDamping 0.0001
        integrator IMPLICIT
        contactModel CONSTRAINTS
        strainLimit 0
        accelerationLimiter NONE
        accelerationLimit 20
        windDirection 1 0 0
        windAmplitude 0
        windFrequency 1
        windPhaseInterval 0.5
        windSeed 1
        progressiveScript ""
        beginLevel 0
        endLevel -1
        splitRate 0
        tolerance 0
    }
  \endcode
*/
class ClothEngine : public SoEngine {
  typedef SoEngine inherited;
  SO_ENGINE_HEADER(ClothEngine);

 public:
  static void initClass();
  ClothEngine();

  // --- inputs ---
  // Rest (unstressed) shape of the garment, which is also where it starts: one point
  // per cloth node, world frame, m. Default [ ]. Must not be empty.
  SoMFVec3f restPoints;
  // Faces of the garment as indices into restPoints, each face ended by -1; faces with
  // more than three corners are split into triangles as a fan. Default [ ].
  SoMFInt32 coordIndex;
  // A sewing pattern's garment (a SewingPattern's outputs): each rest point's panel
  // coordinates, m, and pairs of rest point indices its stitches pull together. Given
  // seams, the engine sews the panels shut around the body first (gravity off, until every
  // pair is within 2 mm: sim/pattern/Sewing.h), merges each closed pair into one node and
  // drapes what it sewed; the rest shape is then the flat panels (panelPoints, one per rest
  // point), not restPoints, which are only where the panels start. Default [ ] and [ ]
  // (nothing to sew).
  SoMFVec2f panelPoints;
  SoMFInt32 seams;
  // What the cloth collides with: a MeshFile (its triangles, exactly), a Mannequin (its
  // posed collision volumes), or NULL for nothing. Default NULL.
  SoSFNode body;
  // A named fabric (sim/cloth/MaterialPresets.h: cotton, silk, denim, jersey) that gives
  // thickness, density, youngsModulus and poissonRatio; any of those four written in
  // the scene overrides the preset's value. Default "" (the four fields as they are).
  SoSFString material;
  // Cloth thickness h, m. Default 0.0005. Must be > 0.
  SoSFDouble thickness;
  // Density of the cloth rho, kg/m^3 (areal density = rho * h). Default 300. Must be > 0.
  SoSFDouble density;
  // Effective membrane Young's modulus E of the fabric, Pa. Default 1e6. Must be > 0.
  SoSFDouble youngsModulus;
  // Poisson's ratio nu, dimensionless. Default 0.3. Must lie in (-1, 0.5).
  SoSFDouble poissonRatio;
  // Integration time step dt, s. Default 0.05 (IMPLICIT's; maxTime when that is shorter);
  // left unwritten with an explicit integrator (HEUN, EULER, SYMPLECTIC) it is the paper's
  // 1.5e-4 instead, stable for ~1.5 cm sections of 1 MPa cloth (timeStepSeconds()). Must be
  // > 0, at most maxTime, and maxTime / timeStep at
  // most 1e7 steps.
  SoSFDouble timeStep;
  // IMPLICIT only: the largest step, s, the step grows to while the cloth is quiet (a
  // step the step control keeps whole, its fastest node slower than the step before's,
  // makes the next 1.5 times longer; any other the next half as long, never under
  // timeStep). Default 0: every step is timeStep. Must be 0 or at least timeStep.
  SoSFDouble maxTimeStep;
  // Upper bound of simulated time, s. Default 5.
  SoSFDouble maxTime;
  // The cloth is at rest when every node is slower than this, m/s... Default 0.01.
  SoSFDouble restSpeed;
  // ...for this long without interruption, s. Default 0.25.
  SoSFDouble restWindow;
  // Acceleration of gravity, m/s^2. Default 0 -9.81 0.
  SoSFVec3f gravity;
  // Air drag per unit area per unit speed, N*s/m^3. Default 1.
  SoSFDouble airResistance;
  // Coulomb friction coefficient against the body, dimensionless. Default 0.4.
  SoSFDouble friction;
  // Distance kept between cloth nodes and the body surface, m. Default 0.003.
  SoSFDouble clearance;
  // Kelvin-Voigt relaxation time of the membrane (strain-rate damping), s. Default 1e-4.
  SoSFDouble strainRateDamping;
  // How a step advances the cloth: EULER (explicit), SYMPLECTIC (semi-implicit Euler),
  // HEUN (improved Euler, the paper's) or IMPLICIT (backward Euler with the contacts in
  // its solve, sim/cloth/implicit/ImplicitEuler.h: stable at steps of 1/100 s and more;
  // it ignores strainLimit and accelerationLimiter, which only explicit steps need; its
  // assembly and solve use OMP_NUM_THREADS threads). Default IMPLICIT: with the other fields
  // at their defaults it drapes the shipped dress to rest in 60 steps (well under a second
  // on one core). `integrator HEUN` alone gives the paper's explicit path (Heun at 1.5e-4 s:
  // 33,334 steps to maxTime on the dress).
  SoSFEnum integrator;
  // How IMPLICIT meets the body: CONSTRAINTS (held nodes, velocity constraints of its
  // solve, sim/cloth/implicit/ContactConstraints.h) or PENALTY (springs and Coulomb
  // friction forces inside the solve, ContactPenalty.h: nothing switches between held
  // and let go). PENALTY needs IMPLICIT. Default CONSTRAINTS.
  SoSFEnum contactModel;
  // Strain clamping (paper §2): each section's strain components are held within
  // [-strainLimit, strainLimit] when its forces are computed, dimensionless; 0 = off.
  // Default 0.
  SoSFDouble strainLimit;
  // Acceleration limiting (paper §2, Fig. 2.3) of each node's elastic acceleration
  // (gravity, air, wind and damping pass it): NONE,
  // CLAMP (hard) or TANH (smooth). Default NONE.
  SoSFEnum accelerationLimiter;
  // The acceleration cap, in multiples of |gravity|. Default 20. Must be > 0.
  SoSFDouble accelerationLimit;
  // Wind (paper §2, sim/cloth/Wind.h): a pressure p(t) = windAmplitude sin(2 pi windFrequency t
  // + phi(t)) whose phase phi jumps to a random value at random moments; each section
  // of area A and normal n is pushed along the wind by p A |n . w| (none when edge-on).
  // Direction the wind blows to, any length (normalised); 0 0 0 = no wind. Default 1 0 0.
  SoSFVec3f windDirection;
  // Pressure amplitude on a section face-on to the wind, Pa; 0 = no wind. Default 0.
  // Must be >= 0.
  SoSFDouble windAmplitude;
  // Frequency of the sinusoid, Hz. Default 1. Must be >= 0.
  SoSFDouble windFrequency;
  // Mean time between the random phase changes (a Poisson process), s; 0 = the phase
  // never changes. Default 0.5. Must be >= 0.
  SoSFDouble windPhaseInterval;
  // Seed of the phase changes: equal seeds repeat a run exactly. Default 1. Must be >= 0.
  SoSFInt32 windSeed;

  // Progressive meshes (paper §4, sim/progressive/ProgressiveDrape.h): the garment is
  // simulated from a decimated level of its progressive mesh and vertex splits bring it
  // back to detail as it drapes. The reconstruction script (written by figment-decimate
  // for this garment; looked up beside the .iv file, then on the model search path);
  // "" = the full garment from the start. Default "".
  SoSFString progressiveScript;
  // The level the drape begins at: splits applied before it starts. Default 0 (the
  // coarsest). Must be in [0, endLevel].
  SoSFInt32 beginLevel;
  // The level it ends at; -1 = every split (the full garment). Default -1. Vertices not
  // split in by then come out where the remaining splits would put them.
  SoSFInt32 endLevel;
  // Splits per second of simulated time; 0 = all remaining splits at once when the
  // current level has come to rest. Default 0. Must be >= 0.
  SoSFDouble splitRate;

  // Model no more than the scene needs: a deviation at rest the drape may have from a
  // converged one, % of the garment's height; the engine then drapes by the fastest
  // configuration the speed-against-accuracy study measured within it on every garment
  // it studied (integrator and step, limiter, contacts, collision body, progressive
  // schedule; sim/drape/MethodChoice.h), in place of those fields. 0 = the fields
  // as they are. Default 0. Must be >= 0.
  SoSFDouble tolerance;

  enum Integrator { EULER, SYMPLECTIC, HEUN, IMPLICIT };
  // timeStep's default, s: IMPLICIT's step on the shipped garments.
  static constexpr double kImplicitTimeStep = 0.05;
  enum AccelerationLimiter { NONE, CLAMP, TANH };
  enum ContactModel { CONSTRAINTS, PENALTY };

  // --- output ---
  // The draped positions, one per rest point, world frame, m (SoMFVec3f).
  SoEngineOutput positions;
  // The sections simulated last, as coordIndex (each ended by -1; SoMFInt32): with a
  // progressive script, the level the drape reached; without, the garment's triangles.
  SoEngineOutput levelCoordIndex;

  // Reported about once per second of wall time while a simulation runs
  // (DrapeContext::progress).
  struct Progress {
    int iterations = 0;
    double simulatedSeconds = 0.0;
    double maxTime = 0.0;      // s, the run's upper bound
    double maxSpeed = 0.0;     // m/s, fastest cloth node now
    double wallSeconds = 0.0;  // since the run began
  };
  using ProgressCallback = std::function<void(const ClothEngine&, const Progress&)>;

  // Called with the engine and its solver before a simulation's first step and after
  // every step (DrapeContext::stepObserver).
  using StepObserver = std::function<void(const ClothEngine&, const figment::ClothSolver&)>;

  // What this engine drapes with besides its fields: the drape cache, the observers, the
  // broad phase (nodes/cloth/DrapeContext.h). Its owner (a scene session) hands the same
  // one to each engine of its scene; null, the default, drapes with no cache and no
  // observers. Not for use while the engine is evaluating.
  void setDrapeContext(std::shared_ptr<const figment::DrapeContext> context);
  const std::shared_ptr<const figment::DrapeContext>& drapeContext() const;

  // What the cache had to say in the last evaluation (a damaged entry dropped, a drape
  // that could not be kept), one line; empty otherwise.
  const std::string& lastCacheMessage() const;

  // The last evaluation's error, one line; empty when it succeeded.
  const std::string& lastError() const;
  // What the last evaluation draped and how (sim/drape/DrapeReport.h: the method that ran
  // and why, the body, the run, its verdict; the method of the fields and zeros for the
  // rest when it failed before simulating). Include sim/drape/DrapeReport.h to read it.
  const figment::DrapeReport& lastRun() const;
  // How many times this engine has evaluated (each evaluation is one simulation).
  int evaluationCount() const;
  // The step the fields give, s: timeStep as written; left unwritten, IMPLICIT's 0.05 (or
  // maxTime, when shorter) and an explicit integrator's 1.5e-4, the paper's
  // (figment::ClothParameters' default).
  double timeStepSeconds() const;
  // "ClothEngine 'Name'", or "ClothEngine" when it has no name: how messages name it.
  std::string label() const;
  // What the fields give to drape, as the engine reads them, for a program that measures
  // a drape (session/EngineFit.h): the garment (restPoints, coordIndex's faces split into
  // triangles) and the material and run parameters, validated. Each throws
  // std::invalid_argument naming the field and value when an input cannot be used.
  figment::TriangleMesh restGarment() const;
  figment::ClothParameters clothParameters() const;

 protected:
  ~ClothEngine() override;
  SbBool readInstance(SoInput* in, unsigned short readFlags) override;

 private:
  void evaluate() override;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};
