#include "nodes/cloth/ClothEngineInputs.h"

#include <Inventor/nodes/SoNode.h>

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

std::string at(int index, int value) {
  std::ostringstream out;
  out << "coordIndex[" << index << "] = " << value;
  return out.str();
}

}  // namespace

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

ClothParameters parametersFromFields(const ClothEngine& engine) {
  // The double fields hold what the scene wrote (see FieldValues.h); gravity is float.
  ClothParameters p;
  p.material = materialFromFields(engine);
  p.timeStep = engine.timeStepSeconds();
  p.maxTime = engine.maxTime.getValue();
  p.rest.speedThreshold = engine.restSpeed.getValue();
  p.rest.window = engine.restWindow.getValue();
  const SbVec3f& g = engine.gravity.getValue();
  p.gravity = Vec3(writtenValue(g[0]), writtenValue(g[1]), writtenValue(g[2]));
  p.airResistance = engine.airResistance.getValue();
  p.friction = engine.friction.getValue();
  p.clearance = engine.clearance.getValue();
  p.strainRateDamping = engine.strainRateDamping.getValue();
  switch (engine.integrator.getValue()) {
    case ClothEngine::EULER:
      p.integrator = Integrator::ExplicitEuler;
      break;
    case ClothEngine::SYMPLECTIC:
      p.integrator = Integrator::SymplecticEuler;
      break;
    case ClothEngine::IMPLICIT:
      p.integrator = Integrator::Implicit;
      break;
    default:
      p.integrator = Integrator::Heun;
      break;
  }
  p.implicitSolver.contacts =
      engine.contactModel.getValue() == ClothEngine::PENALTY ? ContactModel::Penalty : ContactModel::Constraints;
  p.strainLimit = engine.strainLimit.getValue();
  switch (engine.accelerationLimiter.getValue()) {
    case ClothEngine::CLAMP:
      p.accelerationLimiter = AccelerationLimiter::Clamp;
      break;
    case ClothEngine::TANH:
      p.accelerationLimiter = AccelerationLimiter::Tanh;
      break;
    default:
      p.accelerationLimiter = AccelerationLimiter::None;
      break;
  }
  p.accelerationLimit = engine.accelerationLimit.getValue();
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
