#include "nodes/cloth/ClothEngine.h"

#include <Inventor/errors/SoDebugError.h>
#include <Inventor/lists/SoFieldList.h>

#include <algorithm>
#include <chrono>
#include <initializer_list>
#include <optional>
#include <utility>

#include "nodes/SceneFiles.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "nodes/cloth/DrapeContext.h"
#include "nodes/cloth/DrapeKey.h"
#include "nodes/cloth/EngineAsk.h"
#include "nodes/cloth/EngineCache.h"
#include "nodes/cloth/FieldValues.h"
#include "nodes/cloth/GarmentStartCheck.h"
#include "sim/drape/DrapePlan.h"

SO_ENGINE_SOURCE(ClothEngine);

struct ClothEngine::Impl {
  std::vector<std::string> sceneDirectories;  // where progressiveScript is looked up
  std::string error;
  std::string cacheMessage;
  figment::DrapeReport report;
  int evaluations = 0;
  std::shared_ptr<const figment::DrapeContext> givenContext;  // null: drape as with `none`
  const figment::DrapeContext none{};                         // no cache, no observers

  const figment::DrapeContext& drapeContext() const { return givenContext ? *givenContext : none; }

  // Plans the drape the fields ask for (sim/drape/DrapePlan.h) and runs it; throws naming
  // the field and value, or the file, that cannot be used.
  figment::GarmentDrape simulate(const ClothEngine& engine);
};

void ClothEngine::initClass() {
  if (classTypeId != SoType::badType()) return;
  SO_ENGINE_INIT_CLASS(ClothEngine, SoEngine, "Engine");
}

ClothEngine::ClothEngine() : impl_(std::make_unique<Impl>()) {
  SO_ENGINE_CONSTRUCTOR(ClothEngine);
  // The simulation's defaults, so a scene and a sim/ run agree, but the method: backward
  // Euler at 1/20 s, where sim/'s is the paper's explicit path (`integrator HEUN`).
  const figment::ClothParameters defaults;
  SO_ENGINE_ADD_INPUT(restPoints, (0.0f, 0.0f, 0.0f));
  SO_ENGINE_ADD_INPUT(coordIndex, (0));
  SO_ENGINE_ADD_INPUT(panelPoints, (0.0f, 0.0f));
  SO_ENGINE_ADD_INPUT(seams, (0));
  SO_ENGINE_ADD_INPUT(body, (nullptr));
  SO_ENGINE_ADD_INPUT(material, (""));
  SO_ENGINE_ADD_INPUT(thickness, (defaults.material.thickness));
  SO_ENGINE_ADD_INPUT(density, (defaults.material.density));
  SO_ENGINE_ADD_INPUT(youngsModulus, (defaults.material.youngsModulus));
  SO_ENGINE_ADD_INPUT(poissonRatio, (defaults.material.poissonRatio));
  SO_ENGINE_ADD_INPUT(timeStep, (kImplicitTimeStep));
  SO_ENGINE_ADD_INPUT(maxTimeStep, (defaults.implicitSolver.maxTimeStep));
  SO_ENGINE_ADD_INPUT(maxTime, (defaults.maxTime));
  SO_ENGINE_ADD_INPUT(restSpeed, (defaults.rest.speedThreshold));
  SO_ENGINE_ADD_INPUT(restWindow, (defaults.rest.window));
  SO_ENGINE_ADD_INPUT(gravity, (float(defaults.gravity.x()), float(defaults.gravity.y()), float(defaults.gravity.z())));
  SO_ENGINE_ADD_INPUT(airResistance, (defaults.airResistance));
  SO_ENGINE_ADD_INPUT(friction, (defaults.friction));
  SO_ENGINE_ADD_INPUT(clearance, (defaults.clearance));
  SO_ENGINE_ADD_INPUT(strainRateDamping, (defaults.strainRateDamping));
  SO_ENGINE_ADD_INPUT(integrator, (IMPLICIT));
  SO_ENGINE_DEFINE_ENUM_VALUE(Integrator, EULER);
  SO_ENGINE_DEFINE_ENUM_VALUE(Integrator, SYMPLECTIC);
  SO_ENGINE_DEFINE_ENUM_VALUE(Integrator, HEUN);
  SO_ENGINE_DEFINE_ENUM_VALUE(Integrator, IMPLICIT);
  SO_ENGINE_SET_SF_ENUM_TYPE(integrator, Integrator);
  SO_ENGINE_ADD_INPUT(contactModel, (CONSTRAINTS));
  SO_ENGINE_DEFINE_ENUM_VALUE(ContactModel, CONSTRAINTS);
  SO_ENGINE_DEFINE_ENUM_VALUE(ContactModel, PENALTY);
  SO_ENGINE_SET_SF_ENUM_TYPE(contactModel, ContactModel);
  SO_ENGINE_ADD_INPUT(strainLimit, (defaults.strainLimit));
  SO_ENGINE_ADD_INPUT(accelerationLimiter, (NONE));
  SO_ENGINE_DEFINE_ENUM_VALUE(AccelerationLimiter, NONE);
  SO_ENGINE_DEFINE_ENUM_VALUE(AccelerationLimiter, CLAMP);
  SO_ENGINE_DEFINE_ENUM_VALUE(AccelerationLimiter, TANH);
  SO_ENGINE_SET_SF_ENUM_TYPE(accelerationLimiter, AccelerationLimiter);
  SO_ENGINE_ADD_INPUT(accelerationLimit, (defaults.accelerationLimit));
  const figment::WindParameters& wind = defaults.wind;
  SO_ENGINE_ADD_INPUT(windDirection, (float(wind.direction.x()), float(wind.direction.y()), float(wind.direction.z())));
  SO_ENGINE_ADD_INPUT(windAmplitude, (wind.amplitude));
  SO_ENGINE_ADD_INPUT(windFrequency, (wind.frequency));
  SO_ENGINE_ADD_INPUT(windPhaseInterval, (wind.meanPhaseInterval));
  SO_ENGINE_ADD_INPUT(windSeed, (int32_t(wind.seed)));
  SO_ENGINE_ADD_INPUT(progressiveScript, (""));
  SO_ENGINE_ADD_INPUT(beginLevel, (0));
  SO_ENGINE_ADD_INPUT(endLevel, (-1));
  SO_ENGINE_ADD_INPUT(splitRate, (0.0));
  SO_ENGINE_ADD_INPUT(tolerance, (0.0));
  // The multiple-value inputs start empty ([ ]), not with the one value set above.
  for (SoMField* list : std::initializer_list<SoMField*>{&restPoints, &coordIndex, &panelPoints, &seams})
    list->setNum(0), list->setDefault(TRUE);
  SO_ENGINE_ADD_OUTPUT(positions, SoMFVec3f);
  SO_ENGINE_ADD_OUTPUT(levelCoordIndex, SoMFInt32);
}

ClothEngine::~ClothEngine() = default;

SbBool ClothEngine::readInstance(SoInput* in, unsigned short readFlags) {
  if (!inherited::readInstance(in, readFlags)) return FALSE;
  impl_->sceneDirectories = figment::sceneSearchDirectories(in);
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

void ClothEngine::setDrapeContext(std::shared_ptr<const figment::DrapeContext> context) {
  impl_->givenContext = std::move(context);
}

const std::shared_ptr<const figment::DrapeContext>& ClothEngine::drapeContext() const {
  return impl_->givenContext;
}

const std::string& ClothEngine::lastCacheMessage() const {
  return impl_->cacheMessage;
}

const std::string& ClothEngine::lastError() const {
  return impl_->error;
}

const figment::DrapeReport& ClothEngine::lastRun() const {
  return impl_->report;
}

int ClothEngine::evaluationCount() const {
  return impl_->evaluations;
}

double ClothEngine::timeStepSeconds() const {
  if (!timeStep.isDefault()) return timeStep.getValue();
  if (integrator.getValue() != IMPLICIT) return figment::ClothParameters{}.timeStep;
  // A run shorter than the default step is one step (a written timeStep must not exceed maxTime).
  const double run = maxTime.getValue();
  return run > 0.0 ? std::min(kImplicitTimeStep, run) : kImplicitTimeStep;
}

std::string ClothEngine::label() const {
  const SbName name = getName();
  return name.getLength() ? "ClothEngine '" + std::string(name.getString()) + "'" : "ClothEngine";
}

figment::TriangleMesh ClothEngine::restGarment() const {
  return figment::garmentFromFields(restPoints, coordIndex);
}

figment::ClothParameters ClothEngine::clothParameters() const {
  return figment::parametersFromFields(*this);
}

figment::GarmentDrape ClothEngine::Impl::simulate(const ClothEngine& engine) {
  const auto start = std::chrono::steady_clock::now();  // planning and the solver's set-up count too
  const figment::DrapeContext& context = drapeContext();
  std::optional<figment::MethodTable> table;
  figment::DrapeAsk ask = figment::drapeAskFromFields(engine, sceneDirectories, table);
  ask.parameters.broadPhase = context.broadPhase;
  figment::DrapePlan plan = figment::planDrape(std::move(ask));
  // Before any step: a garment in another unit or on its side is an error, one partly
  // inside the body or wound clockwise a warning in the verdict's line.
  figment::TriangleMesh started = plan.request.garment;  // where it starts: over the layers beneath, if any
  if (plan.request.start) started.vertices = *plan.request.start;
  plan.report.garmentWarning = figment::garmentStartWarning(engine, started, plan.request.body.get());
  const double maxTime = plan.request.parameters.maxTime;
  figment::DrapeObservers observers;
  if (context.stepObserver)
    observers.step = [&engine, &context](const figment::ClothSolver& s) { context.stepObserver(engine, s); };
  observers.progress = [&](const figment::DrapeProgress& p) {
    if (!context.progress) return;
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    context.progress(engine, Progress{p.iterations, p.simulatedTime, maxTime, p.maxSpeed, wall.count()});
  };
  observers.progressInterval = context.progressInterval;
  figment::GarmentDrape drape = figment::drape(std::move(plan), observers);
  drape.report.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return drape;
}

void ClothEngine::evaluate() {
  // Coin evaluates an engine once more while destroying it (SoEngine::destroy), as when the
  // scene it is read in fails to read: nothing reads that result, and draping there took the
  // whole maxTime before the read error came out (found by tests/fuzz/fuzz_scene). An engine
  // anything reads is referenced by that connection.
  if (getRefCount() == 0) return;
  Impl& d = *impl_;
  ++d.evaluations;
  d.error.clear();
  d.cacheMessage.clear();
  d.report = figment::reportBeforeDrape(*this);
  // Until a simulation succeeds the output is the rest shape and the given faces.
  const int numRest = restPoints.getNum();
  figment::EngineOutput out{{restPoints.getValues(0), restPoints.getValues(0) + numRest}, {}};
  const figment::DrapeContext& context = d.drapeContext();
  const figment::EngineCache cache(context.stepObserver ? nullptr : context.cache.get());  // an observed drape runs
  std::string key;
  if (cache) {
    const std::string script = progressiveScript.getValue().getString();
    key = figment::drapeKey(*this, script.empty() ? "" : figment::resolveSceneFile(script, d.sceneDirectories));
  }
  std::optional<figment::DrapeReport> cached = cache.read(key, numRest, out, d.cacheMessage);
  if (cached) {
    d.report = std::move(*cached);
  } else {
    try {
      figment::GarmentDrape drape = d.simulate(*this);
      out.take(drape);
      cache.keep(key, drape, d.cacheMessage);
      d.report = std::move(drape.report);
    } catch (const std::exception& e) {
      d.error = label() + ": " + e.what();
    } catch (...) {
      d.error = label() + ": unknown error while simulating";
    }
    if (!d.error.empty()) {
      out.positions.assign(restPoints.getValues(0), restPoints.getValues(0) + numRest);
      out.indices.assign(coordIndex.getValues(0), coordIndex.getValues(0) + coordIndex.getNum());
      SoDebugError::post("ClothEngine::evaluate", "%s", d.error.c_str());
    }
  }
  if (d.error.empty()) d.report.verdict = figment::verdictOf(d.report);
  const int n = static_cast<int>(out.positions.size());
  SO_ENGINE_OUTPUT(positions, SoMFVec3f, setNum(n));
  SO_ENGINE_OUTPUT(positions, SoMFVec3f, setValues(0, n, out.positions.data()));
  const int m = static_cast<int>(out.indices.size());
  SO_ENGINE_OUTPUT(levelCoordIndex, SoMFInt32, setNum(m));
  SO_ENGINE_OUTPUT(levelCoordIndex, SoMFInt32, setValues(0, m, out.indices.data()));
}
