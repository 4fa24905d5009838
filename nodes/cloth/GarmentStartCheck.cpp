#include "nodes/cloth/GarmentStartCheck.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoNode.h>

#include <cmath>
#include <optional>
#include <stdexcept>

#include "io/UpAxis.h"
#include "nodes/body/CollisionGroup.h"
#include "nodes/body/Mannequin.h"
#include "nodes/body/MeshFile.h"
#include "nodes/cloth/ClothEngine.h"
#include "sim/core/ParameterChecks.h"
#include "sim/drape/GarmentStart.h"

namespace figment {

namespace {

std::string named(const SoNode& node) {
  const SbName name = node.getName();
  return std::string(node.getTypeId().getName().getString()) +
         (name.getLength() ? " '" + std::string(name.getString()) + "'" : "");
}

std::string fieldText(const SoField& field) {
  SbString text;
  const_cast<SoField&>(field).get(text);  // Coin's get() is not const, though it reads only
  return text.getString();
}

// The body's box in its node's frame: a Mannequin's and a CollisionGroup's that of the
// body they wrap (a Mannequin draws its volumes only when asked to); none when empty.
std::optional<Bounds> bodyBounds(SoNode* node) {
  for (int hops = 0; node && hops < 8; ++hops) {
    if (node->isOfType(Mannequin::getClassTypeId()))
      node = static_cast<Mannequin*>(node)->body.getValue();
    else if (node->isOfType(CollisionGroup::getClassTypeId()))
      node = static_cast<CollisionGroup*>(node)->body.getValue();
    else
      break;
  }
  if (!node) return std::nullopt;
  SoGetBoundingBoxAction action{SbViewportRegion()};
  action.apply(node);
  const SbBox3f box = action.getBoundingBox();
  if (box.isEmpty()) return std::nullopt;
  Bounds bounds;
  bounds.extend(Vec3(box.getMin()[0], box.getMin()[1], box.getMin()[2]));
  bounds.extend(Vec3(box.getMax()[0], box.getMax()[1], box.getMax()[2]));
  return bounds;
}

// Where the garment's points come from: the MeshFile restPoints is connected to, or null.
const MeshFile* patternOf(const ClothEngine& engine) {
  SoField* master = nullptr;
  if (!engine.restPoints.getConnectedField(master) || !master) return nullptr;
  SoFieldContainer* container = master->getContainer();
  return container && container->isOfType(MeshFile::getClassTypeId()) ? static_cast<const MeshFile*>(container)
                                                                      : nullptr;
}

// "(MeshFile 'Pattern', metresPerUnit 1, upAxis Y)" or "(restPoints)".
std::string garmentSource(const MeshFile* pattern, bool unit, bool axis) {
  if (!pattern) return "(restPoints)";
  std::string text = "(";  // appended, not "(" + ...: GCC 12 warns falsely (-Wrestrict) on that
  text += named(*pattern);
  if (unit) text += ", metresPerUnit " + fieldText(pattern->metresPerUnit);
  if (axis) text += ", upAxis " + fieldText(pattern->upAxis);
  return text + ")";
}

// "+x", "-z": an axis direction as the scene's frame names it.
std::string directionName(const Vec3& d) {
  int axis = 0;
  d.cwiseAbs().maxCoeff(&axis);
  return std::string(d[axis] > 0 ? "+" : "-") + "xyz"[axis];
}

std::string percent(double share) {
  return formatNumber(std::round(share * 1000) / 10) + " %";
}

// The fixes for a garment in another unit or on its side, for the MeshFile it comes from,
// else in words for the points themselves.
std::string frameFix(const MeshFile* pattern, const GarmentStart& start) {
  std::string fix;
  if (start.tooLarge()) {
    const double unit = pattern ? pattern->metresPerUnit.getValue() * start.unitFactor : start.unitFactor;
    fix += pattern ? "metresPerUnit " + formatNumber(unit) : "restPoints in metres (times " + formatNumber(unit) + ")";
  }
  if (start.up) {
    const UpAxis applied = pattern ? parseUpAxis(fieldText(pattern->upAxis)).value_or(UpAxis::Y) : UpAxis::Y;
    const std::string axis = upAxisName(fileUpAxis(*start.up, applied).value_or(UpAxis::Y));
    const std::string between = fix.empty() ? "" : pattern ? " " : ", ";  // fields after fields; words after words
    fix += between + (pattern ? "upAxis " + axis : "restPoints turned so their file's " + axis + " axis is up");
  }
  return fix;
}

// The error for a garment in another unit or lying on its side.
std::string frameProblem(const MeshFile* pattern, const GarmentStart& start, bool haveBody) {
  std::string problem = "the garment " + garmentSource(pattern, start.tooLarge(), start.up.has_value()) + " ";
  if (start.tooLarge())
    problem += "is " + formatNumber(std::round(start.extent * 10) / 10) + " m across, " +
               formatNumber(std::round(start.sizeRatio())) + " times " +
               (haveBody ? "the body's " + formatNumber(std::round(start.bodyExtent * 100) / 100) + " m"
                         : "a body's " + formatNumber(GarmentStart::kTypicalStature) + " m") +
               ": in another unit";
  if (start.up)
    problem += std::string(start.tooLarge() ? ", and " : "") +
               "lies on its side: it stands round the body only with its " + directionName(*start.up) + " direction up";
  return problem + ": try " + frameFix(pattern, start);
}

}  // namespace

std::string garmentStartWarning(const ClothEngine& engine, const TriangleMesh& garment, const Collider* body) {
  SoNode* bodyNode = engine.body.getValue();
  const std::optional<Bounds> box = bodyNode ? bodyBounds(bodyNode) : std::nullopt;
  const GarmentStart start = checkGarmentStart(garment, box, body);
  const MeshFile* pattern = patternOf(engine);
  if (start.tooLarge() || start.up) throw std::invalid_argument(frameProblem(pattern, start, box.has_value()));
  const std::string bodyName = bodyNode ? named(*bodyNode) : "";
  const std::string inside = percent(start.insideShare) + " of the garment's nodes start inside the body (" + bodyName +
                             "): try a garment made for this body, or move it out of the body";
  std::string warning;
  if (start.insideShare >= GarmentStart::kInsideWarningShare) warning = inside;
  if (start.clockwise())
    warning += std::string(warning.empty() ? "" : "; ") + "the garment's faces " +
               garmentSource(pattern, false, false) + " wind clockwise seen from outside (" +
               percent(*start.inwardShare) + " of its area near the body faces into it): try " +
               (pattern ? "reverseFaces TRUE" : "each face's indices in coordIndex reversed");
  return warning;
}

}  // namespace figment
