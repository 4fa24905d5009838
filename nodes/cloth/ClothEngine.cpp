#include "nodes/cloth/ClothEngine.h"

#include <Inventor/errors/SoDebugError.h>
#include <Inventor/lists/SoFieldList.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <optional>
#include <utility>

#include "io/DrapeCache.h"
#include "io/ProgressiveScript.h"
#include "nodes/SceneFiles.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "nodes/cloth/DrapeContext.h"
#include "nodes/cloth/DrapeKey.h"
#include "nodes/cloth/FieldValues.h"
#include "nodes/cloth/GarmentStartCheck.h"
#include "nodes/cloth/RunStatsRecord.h"
#include "nodes/cloth/ToleranceChoice.h"
#include "sim/cloth/ClothSolver.h"
#include "sim/cloth/DrapeVerdict.h"
#include "sim/core/ParameterChecks.h"
#include "sim/drape/GarmentDrape.h"
#include "sim/progressive/Decimation.h"

SO_ENGINE_SOURCE(ClothEngine);

struct ClothEngine::Impl {
  std::vector<std::string> sceneDirectories;  // where progressiveScript is looked up
  std::string error;
  std::string cacheMessage;
  RunStats stats;
  int evaluations = 0;
  std::shared_ptr<const figment::DrapeContext> givenContext;  // null: drape as with `none`
  const figment::DrapeContext none{};                         // no cache, no observers

  const figment::DrapeContext& drapeContext() const { return givenContext ? *givenContext : none; }

  // Drapes from `engine`'s fields; returns every rest point's position and the sections
  // simulated last. Throws naming the field and value, or the file, that cannot be used.
  std::vector<figment::Vec3> simulate(const ClothEngine& engine, std::vector<figment::Triangle>& sections);
  void recordRun(const figment::DrapeResult& run, int triangles);
  // The configuration the tolerance picks (ToleranceChoice.h): its method onto
  // `parameters`, its progressive mesh and schedule when it drapes so, its name in the
  // statistics; returns the body to collide with.
  std::shared_ptr<const figment::Collider> pickForTolerance(const ClothEngine& engine,
                                                            const figment::TriangleMesh& garment,
                                                            figment::ClothParameters& parameters,
                                                            std::optional<figment::ProgressiveMesh>& mesh,
                                                            figment::ProgressiveSchedule& schedule);
  // A progressive drape's level, sections and settling in the statistics.
  void recordLevels(const figment::GarmentDrape& drape);
  void recordMethod(const figment::ClothParameters& parameters);
  // The context's drape cache: read an entry into the output, keep a new one.
  bool readCached(const std::string& key, int numRest, std::vector<SbVec3f>& result, std::vector<int32_t>& indices);
  void keep(const std::string& key, const std::vector<SbVec3f>& result, const std::vector<int32_t>& indices);
};

void ClothEngine::initClass() {
  if (classTypeId != SoType::badType()) return;
  SO_ENGINE_INIT_CLASS(ClothEngine, SoEngine, "Engine");
}

ClothEngine::ClothEngine() : impl_(std::make_unique<Impl>()) {
  SO_ENGINE_CONSTRUCTOR(ClothEngine);
  // The defaults are the simulation's own, so a scene and a direct sim/ run agree, but the
  // method: an engine left at its defaults drapes by backward Euler at 1/20 s (the shipped
  // dress's method), where the simulation's defaults are the paper's explicit path, which
  // `integrator HEUN` gives back (timeStepSeconds()).
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

const ClothEngine::RunStats& ClothEngine::lastRun() const {
  return impl_->stats;
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

namespace {

// What the run's ending says (sim/cloth/DrapeVerdict.h): "" when clean.
std::string verdictOf(const ClothEngine::RunStats& run) {
  figment::DrapeVerdict verdict;
  verdict.atRest = run.atRest;
  verdict.maxTime = run.maxTime;
  verdict.maxSpeed = run.maxSpeed;
  verdict.maxStretch = run.maxStretch;
  verdict.clampedSectionShareAtEnd = run.clampedSectionShareAtEnd;
  verdict.limitedNodeShareAtEnd = run.limitedNodeShareAtEnd;
  verdict.halvedSteps = run.halvedSteps;
  verdict.failedSteps = run.failedSteps;
  const std::string ending = verdict.describe();
  if (run.garmentWarning.empty()) return ending;
  return run.garmentWarning + (ending.empty() ? "" : "; " + ending);
}

// coordIndex for triangles, each ended by -1.
std::vector<int32_t> faceIndices(const std::vector<figment::Triangle>& triangles) {
  std::vector<int32_t> indices;
  for (const figment::Triangle& t : triangles) indices.insert(indices.end(), {t[0], t[1], t[2], -1});
  return indices;
}

}  // namespace

void ClothEngine::Impl::recordRun(const figment::DrapeResult& run, int triangles) {
  stats.triangles = triangles;
  stats.iterations = run.iterations;
  stats.simulatedSeconds = run.simulatedTime;
  stats.atRest = run.atRest;
  stats.clampedSectionShare = run.clampedSectionShare;
  stats.limitedNodeShare = run.limitedNodeShare;
  stats.implicitSteps = run.implicitCosts.steps;
  stats.solverIterations = run.implicitCosts.solverIterations;
  stats.assemblySeconds = run.implicitCosts.assemblySeconds;
  stats.solveSeconds = run.implicitCosts.solveSeconds;
  stats.contactSeconds = run.implicitCosts.contactSeconds;
  stats.halvedSteps = run.implicitCosts.halvedSteps;
  stats.failedSteps = run.implicitCosts.failedSteps;
  stats.maxSpeed = run.maxSpeed;
  stats.maxStretch = run.maxStretch;
  stats.clampedSectionShareAtEnd = run.clampedSectionShareAtEnd;
  stats.limitedNodeShareAtEnd = run.limitedNodeShareAtEnd;
}

void ClothEngine::Impl::recordMethod(const figment::ClothParameters& parameters) {
  stats.integrator = figment::fieldName(parameters.integrator);
  stats.contactModel = figment::fieldName(parameters.implicitSolver.contacts);
  stats.accelerationLimiter = figment::fieldName(parameters.accelerationLimiter);
  stats.timeStep = parameters.timeStep;
  stats.strainLimit = parameters.strainLimit;
  stats.accelerationLimit = parameters.accelerationLimit;
  stats.maxTime = parameters.maxTime;
}

std::shared_ptr<const figment::Collider> ClothEngine::Impl::pickForTolerance(
    const ClothEngine& engine, const figment::TriangleMesh& garment, figment::ClothParameters& parameters,
    std::optional<figment::ProgressiveMesh>& mesh, figment::ProgressiveSchedule& schedule) {
  const figment::ToleranceChoice choice = figment::chooseForTolerance(engine, garment, parameters);
  stats.picked = choice.picked.label();
  stats.pickedDeviation = choice.picked.worstMeanDeviation;
  stats.pickedBody = choice.picked.body;
  stats.passedOver = choice.passedOver;
  if (choice.picked.progressive != "off") {
    mesh = figment::decimate(
        garment, figment::DecimationOptions{.targetFaces = static_cast<int>(
                                                std::lround(figment::kStudyCoarseShare * garment.triangles.size()))});
    const figment::ScheduleText s = figment::parseScheduleText(choice.picked.progressive);
    schedule = {static_cast<int>(std::lround(s.beginShare * mesh->levels())), -1, s.rate};
  }
  return choice.body;
}

void ClothEngine::Impl::recordLevels(const figment::GarmentDrape& drape) {
  stats.level = drape.level;
  stats.levels = drape.levels;
  stats.sections = static_cast<int>(drape.sections.size());
  stats.endLevelSeconds = drape.settling.arrival;
  stats.meanMoveAfterEndLevel = drape.settling.meanMove;
  stats.maxMoveAfterEndLevel = drape.settling.maxMove;
}

std::vector<figment::Vec3> ClothEngine::Impl::simulate(const ClothEngine& engine,
                                                       std::vector<figment::Triangle>& sections) {
  const figment::TriangleMesh garment = figment::garmentFromFields(engine.restPoints, engine.coordIndex);
  figment::ClothParameters parameters = figment::parametersFromFields(engine);
  const figment::DrapeContext& context = drapeContext();
  parameters.broadPhase = context.broadPhase;
  figment::requireNonNegative("tolerance", engine.tolerance.getValue());
  const auto start = std::chrono::steady_clock::now();  // choosing and the solver's set-up count too
  std::shared_ptr<const figment::Collider> collider;
  std::string script = engine.progressiveScript.getValue().getString();
  figment::ProgressiveSchedule schedule{engine.beginLevel.getValue(), engine.endLevel.getValue(),
                                        engine.splitRate.getValue()};
  std::optional<figment::ProgressiveMesh> mesh;  // the garment's progressive mesh, when draped so
  if (engine.tolerance.getValue() > 0.0) {
    collider = pickForTolerance(engine, garment, parameters, mesh, schedule);
    script.clear();
  } else {
    collider = figment::colliderFromBody(engine.body);
  }
  recordMethod(parameters);
  // Before any step: a garment in another unit or on its side is an error, one partly
  // inside the body or wound clockwise a warning in the verdict's line. A body that moves
  // into its pose is checked as the drape starts on it: at its first keyframe.
  if (collider && collider->moves()) collider->advanceTo(0.0);
  stats.garmentWarning = figment::garmentStartWarning(engine, garment, collider.get());
  if (!script.empty()) {
    const std::string path = figment::resolveSceneFile(script, sceneDirectories);
    if (path.empty()) throw std::runtime_error("progressiveScript \"" + script + "\" not found");
    mesh = figment::readProgressiveScript(path, garment);
  }
  figment::DrapeRequest request{.garment = garment,
                                .parameters = parameters,
                                .body = std::move(collider),
                                .progressive = std::move(mesh),
                                .schedule = schedule};
  request.sewing = figment::sewingFromFields(engine.panelPoints, engine.seams, garment.vertices.size());
  if (request.sewing && engine.tolerance.getValue() > 0.0)
    throw std::invalid_argument("tolerance: a sewn garment drapes by the engine's own fields (tolerance 0)");
  if (context.stepObserver)
    request.stepObserver = [&engine, &context](const figment::ClothSolver& s) { context.stepObserver(engine, s); };
  // A body that moves into its pose (a posed HumanBody, alone or in a CollisionGroup)
  // follows the drape's clock.
  if (request.body && request.body->moves())
    request.bodyClock = [moving = request.body](double time) { moving->advanceTo(time); };
  request.progress = [&](const figment::DrapeProgress& p) {
    if (!context.progress) return;
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    context.progress(engine, Progress{p.iterations, p.simulatedTime, parameters.maxTime, p.maxSpeed, wall.count()});
  };
  request.progressInterval = context.progressInterval;
  figment::GarmentDrape drape = figment::drapeGarment(request);
  stats.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  recordRun(drape.run, static_cast<int>(garment.triangles.size()));
  recordLevels(drape);
  sections = std::move(drape.sections);
  return drape.positions;
}

// The drape kept under `key`, when it fits this engine's rest points: the output and
// the statistics set from it. An entry whose record this build cannot read (another
// version, damaged) is removed and said; the drape is then made again and kept anew.
bool ClothEngine::Impl::readCached(const std::string& key, int numRest, std::vector<SbVec3f>& result,
                                   std::vector<int32_t>& indices) {
  const auto start = std::chrono::steady_clock::now();
  const figment::DrapeCache& cache = *drapeContext().cache;
  const std::optional<figment::CachedDrape> cached = cache.find(key, cacheMessage);
  if (!cached || static_cast<int>(cached->positions.size()) != numRest) return false;
  std::string problem;
  std::optional<RunStats> kept = figment::readRunStats(cached->stats, problem);
  if (!kept) {
    cache.remove(key);
    cacheMessage = cache.entryPath(key).string() + ": " + problem + ", removed; draped again";
    return false;
  }
  result.clear();
  for (const auto& p : cached->positions) result.emplace_back(p[0], p[1], p[2]);
  indices = cached->sectionIndices;
  stats = std::move(*kept);
  stats.fromCache = true;
  stats.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

void ClothEngine::Impl::keep(const std::string& key, const std::vector<SbVec3f>& result,
                             const std::vector<int32_t>& indices) {
  figment::CachedDrape drape;
  for (const SbVec3f& p : result) drape.positions.push_back({p[0], p[1], p[2]});
  drape.sectionIndices = indices;
  drape.stats = figment::writeRunStats(stats);
  const std::string problem = drapeContext().cache->store(key, drape);
  if (!problem.empty()) cacheMessage = "drape cache: " + problem;
}

void ClothEngine::evaluate() {
  // Coin evaluates an engine once more while destroying it (SoEngine::destroy), as when the
  // scene it is read in fails to read: nothing reads that result, and draping there took the
  // whole maxTime before the read error came out (found by tests/fuzz/fuzz_scene). An engine
  // anything reads is referenced by that connection.
  if (getRefCount() == 0) return;
  ++impl_->evaluations;
  impl_->error.clear();
  impl_->cacheMessage.clear();
  impl_->stats = {};
  // Until a simulation succeeds the output is the rest shape and the given faces.
  const int numRest = restPoints.getNum();
  std::vector<SbVec3f> result(restPoints.getValues(0), restPoints.getValues(0) + numRest);
  std::vector<int32_t> indices;
  std::string key;
  if (impl_->drapeContext().cache && !impl_->drapeContext().stepObserver) {  // an observed drape runs its steps
    const std::string script = progressiveScript.getValue().getString();
    key = figment::drapeKey(*this, script.empty() ? "" : figment::resolveSceneFile(script, impl_->sceneDirectories));
  }
  if (key.empty() || !impl_->readCached(key, numRest, result, indices)) {
    std::vector<figment::Triangle> sections;
    try {
      const std::vector<figment::Vec3> x = impl_->simulate(*this, sections);
      for (size_t i = 0; i < x.size() && i < result.size(); ++i)
        result[i].setValue(float(x[i].x()), float(x[i].y()), float(x[i].z()));
    } catch (const std::exception& e) {
      impl_->error = label() + ": " + e.what();
    } catch (...) {
      impl_->error = label() + ": unknown error while simulating";
    }
    if (!impl_->error.empty()) {
      result.assign(restPoints.getValues(0), restPoints.getValues(0) + numRest);
      indices.assign(coordIndex.getValues(0), coordIndex.getValues(0) + coordIndex.getNum());
      SoDebugError::post("ClothEngine::evaluate", "%s", impl_->error.c_str());
    } else {
      indices = faceIndices(sections);
      if (!key.empty()) impl_->keep(key, result, indices);
    }
  }
  if (impl_->error.empty()) impl_->stats.verdict = verdictOf(impl_->stats);
  const int n = static_cast<int>(result.size());
  SO_ENGINE_OUTPUT(positions, SoMFVec3f, setNum(n));
  SO_ENGINE_OUTPUT(positions, SoMFVec3f, setValues(0, n, result.data()));
  const int m = static_cast<int>(indices.size());
  SO_ENGINE_OUTPUT(levelCoordIndex, SoMFInt32, setNum(m));
  SO_ENGINE_OUTPUT(levelCoordIndex, SoMFInt32, setValues(0, m, indices.data()));
}
