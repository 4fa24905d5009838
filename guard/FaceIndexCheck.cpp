#include "guard/FaceIndexCheck.h"

#include <Inventor/VRMLnodes/SoVRMLGeometry.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/nodes/SoIndexedNurbsCurve.h>
#include <Inventor/nodes/SoIndexedNurbsSurface.h>
#include <Inventor/nodes/SoIndexedShape.h>
#include <Inventor/nodes/SoNonIndexedShape.h>
#include <Inventor/nodes/SoNurbsCurve.h>
#include <Inventor/nodes/SoNurbsSurface.h>

#include "guard/shapes/InventorShapeData.h"
#include "guard/shapes/NurbsShapeData.h"
#include "guard/shapes/VrmlShapeData.h"

namespace figment::guard {

namespace {

template <class Shape, std::string (*problemOf)(const Shape&, SoState*)>
SoCallbackAction::Response check(void* data, SoCallbackAction* action, const SoNode* node) {
  std::string problem = problemOf(*static_cast<const Shape*>(node), action->getState());
  if (problem.empty()) return SoCallbackAction::PRUNE;  // nothing to generate: no primitive callbacks
  *static_cast<std::string*>(data) = std::move(problem);
  return SoCallbackAction::ABORT;
}

std::string vrmlProblem(const SoVRMLGeometry& shape, SoState*) {
  return shapes::vrmlShapeProblem(shape);
}

}  // namespace

std::string checkShapes(SoNode* root) {
  std::string error;
  SoCallbackAction action;
  action.addPreCallback(SoIndexedShape::getClassTypeId(), check<SoIndexedShape, shapes::indexedShapeProblem>, &error);
  action.addPreCallback(SoNonIndexedShape::getClassTypeId(), check<SoNonIndexedShape, shapes::countedShapeProblem>,
                        &error);
  action.addPreCallback(SoVRMLGeometry::getClassTypeId(), check<SoVRMLGeometry, vrmlProblem>, &error);
  for (const SoType nurbs : {SoNurbsSurface::getClassTypeId(), SoIndexedNurbsSurface::getClassTypeId(),
                             SoNurbsCurve::getClassTypeId(), SoIndexedNurbsCurve::getClassTypeId()})
    action.addPreCallback(nurbs, check<SoShape, shapes::nurbsShapeProblem>, &error);
  action.apply(root);
  return error;
}

}  // namespace figment::guard
