#include "nodes/cloth/ClothEngine.h"

#include "nodes/cloth/ClothEngineInputs.h"
#include "nodes/cloth/FieldValues.h"
#include "sim/cloth/ClothSolver.h"

#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/engines/SoNodeEngine.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/fields/SoMFNode.h>
#include <Inventor/lists/SoFieldList.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoNode.h>
#include <Inventor/SoFullPath.h>

#include <chrono>
#include <set>
#include <utility>

SO_ENGINE_SOURCE(ClothEngine);

struct ClothEngine::Impl {
  std::string error;
  RunStats stats;
  int evaluations = 0;
};

namespace {

ClothEngine::ProgressCallback& progressCallback() {
  static ClothEngine::ProgressCallback callback;
  return callback;
}

}  // namespace

void ClothEngine::initClass() {
  if (classTypeId != SoType::badType()) return;
  SO_ENGINE_INIT_CLASS(ClothEngine, SoEngine, "Engine");
}

ClothEngine::ClothEngine() : impl_(std::make_unique<Impl>()) {
  SO_ENGINE_CONSTRUCTOR(ClothEngine);
  // The defaults are the simulation's own, so a scene and a direct sim/ run agree.
  const figment::ClothParameters defaults;
  SO_ENGINE_ADD_INPUT(restPoints, (0.0f, 0.0f, 0.0f));
  SO_ENGINE_ADD_INPUT(coordIndex, (0));
  SO_ENGINE_ADD_INPUT(body, (nullptr));
  SO_ENGINE_ADD_INPUT(material, (""));
  SO_ENGINE_ADD_INPUT(thickness, (defaults.material.thickness));
  SO_ENGINE_ADD_INPUT(density, (defaults.material.density));
  SO_ENGINE_ADD_INPUT(youngsModulus, (defaults.material.youngsModulus));
  SO_ENGINE_ADD_INPUT(poissonRatio, (defaults.material.poissonRatio));
  SO_ENGINE_ADD_INPUT(timeStep, (defaults.timeStep));
  SO_ENGINE_ADD_INPUT(maxTime, (defaults.maxTime));
  SO_ENGINE_ADD_INPUT(restSpeed, (defaults.rest.speedThreshold));
  SO_ENGINE_ADD_INPUT(restWindow, (defaults.rest.window));
  SO_ENGINE_ADD_INPUT(gravity, (float(defaults.gravity.x()), float(defaults.gravity.y()),
                                float(defaults.gravity.z())));
  SO_ENGINE_ADD_INPUT(airResistance, (defaults.airResistance));
  SO_ENGINE_ADD_INPUT(friction, (defaults.friction));
  SO_ENGINE_ADD_INPUT(clearance, (defaults.clearance));
  SO_ENGINE_ADD_INPUT(strainRateDamping, (defaults.strainRateDamping));
  SO_ENGINE_ADD_INPUT(integrator, (HEUN));
  SO_ENGINE_DEFINE_ENUM_VALUE(Integrator, EULER);
  SO_ENGINE_DEFINE_ENUM_VALUE(Integrator, SYMPLECTIC);
  SO_ENGINE_DEFINE_ENUM_VALUE(Integrator, HEUN);
  SO_ENGINE_DEFINE_ENUM_VALUE(Integrator, IMPLICIT);
  SO_ENGINE_SET_SF_ENUM_TYPE(integrator, Integrator);
  SO_ENGINE_ADD_INPUT(strainLimit, (defaults.strainLimit));
  SO_ENGINE_ADD_INPUT(accelerationLimiter, (NONE));
  SO_ENGINE_DEFINE_ENUM_VALUE(AccelerationLimiter, NONE);
  SO_ENGINE_DEFINE_ENUM_VALUE(AccelerationLimiter, CLAMP);
  SO_ENGINE_DEFINE_ENUM_VALUE(AccelerationLimiter, TANH);
  SO_ENGINE_SET_SF_ENUM_TYPE(accelerationLimiter, AccelerationLimiter);
  SO_ENGINE_ADD_INPUT(accelerationLimit, (defaults.accelerationLimit));
  const figment::WindParameters& wind = defaults.wind;
  SO_ENGINE_ADD_INPUT(windDirection, (float(wind.direction.x()), float(wind.direction.y()),
                                      float(wind.direction.z())));
  SO_ENGINE_ADD_INPUT(windAmplitude, (wind.amplitude));
  SO_ENGINE_ADD_INPUT(windFrequency, (wind.frequency));
  SO_ENGINE_ADD_INPUT(windPhaseInterval, (wind.meanPhaseInterval));
  SO_ENGINE_ADD_INPUT(windSeed, (int32_t(wind.seed)));
  // The multiple-value inputs start empty ([ ]), not with the one value set above.
  restPoints.setNum(0);
  restPoints.setDefault(TRUE);
  coordIndex.setNum(0);
  coordIndex.setDefault(TRUE);
  SO_ENGINE_ADD_OUTPUT(positions, SoMFVec3f);
}

ClothEngine::~ClothEngine() = default;

SbBool ClothEngine::readInstance(SoInput* in, unsigned short readFlags) {
  if (!inherited::readInstance(in, readFlags)) return FALSE;
  figment::snapReadDoubles(*this);  // "0.0005" means 0.0005 (FieldValues.h)
  // A written input carries both a value and its connection ("restPoints [ ... ] =
  // USE Pattern.point"); Coin keeps the value as read, and floats written with 8
  // digits do not always read back exactly. Take the master's value instead, so a
  // scene written and read again drapes exactly as the original.
  SoFieldList inputs;
  getFields(inputs);
  for (int i = 0; i < inputs.getLength(); ++i) {
    SoField* master = nullptr;
    if (!inputs[i]->getConnectedField(master) || !master) continue;
    inputs[i]->setDirty(TRUE);
    inputs[i]->evaluate();
  }
  return TRUE;
}

void ClothEngine::setProgressCallback(ProgressCallback callback) { progressCallback() = std::move(callback); }

const std::string& ClothEngine::lastError() const { return impl_->error; }

const ClothEngine::RunStats& ClothEngine::lastRun() const { return impl_->stats; }

int ClothEngine::evaluationCount() const { return impl_->evaluations; }

std::string ClothEngine::label() const {
  const SbName name = getName();
  return name.getLength() ? "ClothEngine '" + std::string(name.getString()) + "'" : "ClothEngine";
}

void ClothEngine::evaluate() {
  ++impl_->evaluations;
  impl_->error.clear();
  impl_->stats = {};

  // Until a simulation succeeds the output is the rest shape.
  const int numRest = restPoints.getNum();
  std::vector<SbVec3f> result(restPoints.getValues(0), restPoints.getValues(0) + numRest);
  try {
    const figment::TriangleMesh garment = figment::garmentFromFields(restPoints, coordIndex);
    const figment::ClothParameters parameters = figment::parametersFromFields(*this);
    std::shared_ptr<const figment::Collider> collider = figment::colliderFromBody(body);
    impl_->stats.triangles = static_cast<int>(garment.triangles.size());

    const auto start = std::chrono::steady_clock::now();  // the solver's set-up counts too
    figment::ClothSolver solver(garment, parameters, std::move(collider));
    const figment::DrapeResult run = solver.run([&](const figment::DrapeProgress& p) {
      if (!progressCallback()) return;
      const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
      progressCallback()(*this, Progress{p.iterations, p.simulatedTime, parameters.maxTime, p.maxSpeed,
                                         wall.count()});
    });
    impl_->stats.iterations = run.iterations;
    impl_->stats.simulatedSeconds = run.simulatedTime;
    impl_->stats.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    impl_->stats.atRest = run.atRest;
    impl_->stats.clampedSectionShare = run.clampedSectionShare;
    impl_->stats.limitedNodeShare = run.limitedNodeShare;
    impl_->stats.implicitSteps = run.implicitCosts.steps;
    impl_->stats.solverIterations = run.implicitCosts.solverIterations;
    impl_->stats.assemblySeconds = run.implicitCosts.assemblySeconds;
    impl_->stats.solveSeconds = run.implicitCosts.solveSeconds;
    impl_->stats.contactSeconds = run.implicitCosts.contactSeconds;
    const std::vector<figment::Vec3>& x = solver.positions();
    for (size_t i = 0; i < x.size() && i < result.size(); ++i)
      result[i].setValue(float(x[i].x()), float(x[i].y()), float(x[i].z()));
  } catch (const std::exception& e) {
    impl_->error = label() + ": " + e.what();
  } catch (...) {
    impl_->error = label() + ": unknown error while simulating";
  }
  if (!impl_->error.empty()) {
    result.assign(restPoints.getValues(0), restPoints.getValues(0) + numRest);
    SoDebugError::post("ClothEngine::evaluate", "%s", impl_->error.c_str());
  }

  const int n = static_cast<int>(result.size());
  SO_ENGINE_OUTPUT(positions, SoMFVec3f, setNum(n));
  SO_ENGINE_OUTPUT(positions, SoMFVec3f, setValues(0, n, result.data()));
}

// --- finding the engines of a scene ------------------------------------------------

namespace {

// Walks field connections backwards from every container it is given.
class EngineCollector {
 public:
  std::vector<ClothEngine*> engines;

  void visit(SoFieldContainer* container) {
    if (!container || !seen_.insert(container).second) return;
    if (container->isOfType(ClothEngine::getClassTypeId())) engines.push_back(static_cast<ClothEngine*>(container));
    SoFieldList fields;
    container->getFields(fields);
    for (int i = 0; i < fields.getLength(); ++i) visitField(fields[i]);
  }

 private:
  std::set<SoFieldContainer*> seen_;

  void visitField(SoField* field) {
    SoEngineOutput* output = nullptr;
    if (field->getConnectedEngine(output) && output)
      visit(output->isNodeEngineOutput() ? static_cast<SoFieldContainer*>(output->getNodeContainer())
                                         : static_cast<SoFieldContainer*>(output->getContainer()));
    SoField* master = nullptr;
    if (field->getConnectedField(master) && master) visit(master->getContainer());
    // Nodes held in fields (an IndexedFaceSet's vertexProperty) may be fed by engines too.
    if (field->isOfType(SoSFNode::getClassTypeId())) visit(static_cast<SoSFNode*>(field)->getValue());
    if (field->isOfType(SoMFNode::getClassTypeId())) {
      auto* nodes = static_cast<SoMFNode*>(field);
      for (int i = 0; i < nodes->getNum(); ++i) visit((*nodes)[i]);
    }
  }
};

}  // namespace

namespace figment {

std::vector<ClothEngine*> findClothEngines(SoNode* root) {
  if (!root) return {};
  root->ref();  // the search action must not free a graph nobody else holds
  SoSearchAction search;
  search.setType(SoNode::getClassTypeId(), TRUE);
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  EngineCollector collector;
  const SoPathList& paths = search.getPaths();
  for (int i = 0; i < paths.getLength(); ++i) collector.visit(static_cast<SoFullPath*>(paths[i])->getTail());
  search.reset();
  root->unrefNoDelete();
  return collector.engines;
}

}  // namespace figment
