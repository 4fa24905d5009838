#include "nodes/cloth/ClothEngineInputs.h"

#include <Inventor/fields/SoMFVec2f.h>
#include <Inventor/nodes/SoNode.h>

#include <cstddef>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "guard/CoordIndexFaces.h"
#include "nodes/body/CollisionBody.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/FieldValues.h"
#include "sim/cloth/MaterialPresets.h"
#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {

// One row per method: the engine field's value and the simulation's method (the value's name
// as a scene writes it is sim/drape/DrapeMethod.h's fieldName, which test_ClothEngineInputs
// checks against the field's enum names).
template <typename Method>
struct MethodRow {
  int field;
  Method method;
};

constexpr MethodRow<Integrator> kIntegrators[] = {
    {ClothEngine::EULER, Integrator::ExplicitEuler},
    {ClothEngine::SYMPLECTIC, Integrator::SymplecticEuler},
    {ClothEngine::HEUN, Integrator::Heun},
    {ClothEngine::IMPLICIT, Integrator::Implicit},
};
constexpr MethodRow<AccelerationLimiter> kLimiters[] = {
    {ClothEngine::NONE, AccelerationLimiter::None},
    {ClothEngine::CLAMP, AccelerationLimiter::Clamp},
    {ClothEngine::TANH, AccelerationLimiter::Tanh},
};
constexpr MethodRow<ContactModel> kContactModels[] = {
    {ClothEngine::CONSTRAINTS, ContactModel::Constraints},
    {ClothEngine::PENALTY, ContactModel::Penalty},
};

// The method of a field's value; `fallback` for a value outside the table.
template <typename Method, std::size_t N>
Method methodOfField(const MethodRow<Method> (&table)[N], int field, Method fallback) {
  for (const MethodRow<Method>& row : table)
    if (row.field == field) return row.method;
  return fallback;
}

std::string at(int index, int value) {
  std::ostringstream out;
  out << "coordIndex[" << index << "] = " << value;
  return out.str();
}

}  // namespace

std::optional<DrapeSewing> sewingFromFields(const SoMFVec2f& panelPoints, const SoMFInt32& seams, size_t restPoints) {
  if (seams.getNum() == 0) return std::nullopt;
  if (static_cast<size_t>(panelPoints.getNum()) != restPoints)
    throw std::invalid_argument("panelPoints has " + std::to_string(panelPoints.getNum()) + " points for " +
                                std::to_string(restPoints) + " restPoints");
  if (seams.getNum() % 2 != 0)
    throw std::invalid_argument("seams has " + std::to_string(seams.getNum()) + " indices, not pairs");
  DrapeSewing sewing;
  for (int i = 0; i < panelPoints.getNum(); ++i) sewing.flat.emplace_back(panelPoints[i][0], panelPoints[i][1]);
  for (int i = 0; i < seams.getNum(); i += 2) {
    for (int k = 0; k < 2; ++k)
      if (seams[i + k] < 0 || static_cast<size_t>(seams[i + k]) >= restPoints)
        throw std::invalid_argument("seams[" + std::to_string(i + k) + "] = " + std::to_string(seams[i + k]) +
                                    " is out of range [0, " + std::to_string(restPoints - 1) + "]");
    if (seams[i] == seams[i + 1])
      throw std::invalid_argument("seams[" + std::to_string(i) + "] sews point " + std::to_string(seams[i]) +
                                  " to itself");
    sewing.seams.push_back({seams[i], seams[i + 1]});
  }
  return sewing;
}

TriangleMesh garmentFromFields(const SoMFVec3f& restPoints, const SoMFInt32& coordIndex, const char* pointsName) {
  const int numPoints = restPoints.getNum();
  if (numPoints == 0) throw std::invalid_argument(std::string(pointsName) + " is empty");
  TriangleMesh mesh;
  mesh.vertices.reserve(numPoints);
  for (int i = 0; i < numPoints; ++i) {
    const SbVec3f& p = restPoints[i];
    mesh.vertices.emplace_back(p[0], p[1], p[2]);
  }

  // One face at a time, its corners checked before the index that ends it (only -1
  // may), then its corner count, so the first error along the list is the one reported.
  const int numIndices = coordIndex.getNum();
  const int32_t* index = coordIndex.getValues(0);
  auto notAVertex = [&](int i) {
    return std::invalid_argument(at(i, index[i]) + " is not a vertex: " + pointsName + " has " +
                                 std::to_string(numPoints) + " points");
  };
  for (const guard::CoordIndexFace& face : guard::coordIndexFaces(index, numIndices)) {
    for (int i = face.first; i < face.end; ++i)
      if (index[i] >= numPoints) throw notAVertex(i);
    if (face.end < numIndices && index[face.end] != -1) throw notAVertex(face.end);
    if (face.corners() > 0 && face.corners() < 3)
      throw std::invalid_argument("coordIndex: the face at [" + std::to_string(face.first) + "] has " +
                                  std::to_string(face.corners()) + " corners, fewer than 3");
    for (int k = face.first + 1; k + 1 < face.end; ++k)
      mesh.triangles.push_back({index[face.first], index[k], index[k + 1]});
  }
  if (mesh.triangles.empty()) throw std::invalid_argument("coordIndex has no faces");
  return mesh;
}

Material materialFromFields(const ClothEngine& engine) {
  Material m{engine.thickness.getValue(), engine.density.getValue(), engine.youngsModulus.getValue(),
             engine.poissonRatio.getValue()};
  const std::string name = engine.material.getValue().getString();
  if (name.empty()) return m;
  const std::optional<Material> preset = materialPreset(name);
  if (!preset) {
    std::string known;
    for (const std::string& n : materialPresetNames()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("material = \"" + name + "\" is not a preset (" + known + ")");
  }
  // The preset fills what the scene did not write.
  if (engine.thickness.isDefault()) m.thickness = preset->thickness;
  if (engine.density.isDefault()) m.density = preset->density;
  if (engine.youngsModulus.isDefault()) m.youngsModulus = preset->youngsModulus;
  if (engine.poissonRatio.isDefault()) m.poissonRatio = preset->poissonRatio;
  return m;
}

DrapeMethod methodFromFields(const ClothEngine& engine) {
  DrapeMethod m{methodOfField(kIntegrators, engine.integrator.getValue(), Integrator::Heun),
                methodOfField(kContactModels, engine.contactModel.getValue(), ContactModel::Constraints),
                engine.timeStepSeconds(),
                methodOfField(kLimiters, engine.accelerationLimiter.getValue(), AccelerationLimiter::None),
                engine.accelerationLimit.getValue()};
  m.maxTimeStep = engine.maxTimeStep.getValue();
  return m;
}

ClothParameters parametersFromFields(const ClothEngine& engine) {
  // The double fields hold what the scene wrote (see FieldValues.h); gravity is float.
  ClothParameters p;
  p.material = materialFromFields(engine);
  methodFromFields(engine).applyTo(p);
  p.maxTime = engine.maxTime.getValue();
  p.rest.speedThreshold = engine.restSpeed.getValue();
  p.rest.window = engine.restWindow.getValue();
  const SbVec3f& g = engine.gravity.getValue();
  p.gravity = Vec3(writtenValue(g[0]), writtenValue(g[1]), writtenValue(g[2]));
  p.airResistance = engine.airResistance.getValue();
  p.friction = engine.friction.getValue();
  p.clearance = engine.clearance.getValue();
  p.strainRateDamping = engine.strainRateDamping.getValue();
  p.strainLimit = engine.strainLimit.getValue();
  const SbVec3f& w = engine.windDirection.getValue();
  p.wind.direction = Vec3(writtenValue(w[0]), writtenValue(w[1]), writtenValue(w[2]));
  p.wind.amplitude = engine.windAmplitude.getValue();
  p.wind.frequency = engine.windFrequency.getValue();
  p.wind.meanPhaseInterval = engine.windPhaseInterval.getValue();
  const int32_t seed = engine.windSeed.getValue();
  requireNonNegative("windSeed", seed);
  p.wind.seed = static_cast<uint64_t>(seed);
  p.validate();  // the material's fields too; names the field and value it rejects
  return p;
}

std::shared_ptr<const Collider> colliderFromBody(const SoSFNode& body) {
  SoNode* node = body.getValue();
  if (!node) return nullptr;
  const CollisionBody* collisionBody = asCollisionBody(node);
  if (!collisionBody) {
    const std::string name = node->getName().getLength() ? " '" + std::string(node->getName().getString()) + "'" : "";
    throw std::invalid_argument(std::string("body: ") + node->getTypeId().getName().getString() + name +
                                " is not a collision body (use a MeshFile, a Mannequin or a CollisionGroup)");
  }
  try {
    return collisionBody->bodyCollider();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("body: ") + e.what());
  }
}

}  // namespace figment
