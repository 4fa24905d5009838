#include "guard/shapes/NurbsShapeData.h"

#include <Inventor/elements/SoCoordinateElement.h>
#include <Inventor/nodes/SoIndexedNurbsCurve.h>
#include <Inventor/nodes/SoIndexedNurbsSurface.h>
#include <Inventor/nodes/SoNurbsCurve.h>
#include <Inventor/nodes/SoNurbsSurface.h>

#include <algorithm>
#include <cstdint>

#include "guard/shapes/IndexProblem.h"

namespace figment::guard::shapes {

namespace {

// A count of control points a NURBS shape draws, and the knot vector that goes with it.
struct ControlPoints {
  const char* field;  // "numUControlPoints"
  std::int64_t count;
  const char* knotField;  // "uKnotVector"
  int knots;
};

std::string knotProblem(const SoShape& shape, const ControlPoints& points) {
  if (points.count < 0)
    return nodeLabel(shape) + ": " + points.field + " = " + std::to_string(points.count) + " must not be negative";
  if (points.knots - points.count >= 2) return "";
  return nodeLabel(shape) + ": " + points.knotField + " has " + counted(points.knots, "knot") + " for " +
         counted(points.count, "control point") + ": it needs the control points plus the order, at least 2";
}

// Control points taken in order from the coordinates (NurbsSurface, NurbsCurve), or through
// `coordIndex` (the Indexed ones).
std::string controlPointProblem(const SoShape& shape, std::int64_t controlPoints, const char* counts,
                                const SoMFInt32* coordIndex, int coordinates) {
  const std::string has = "the coordinates have " + counted(coordinates, "point");
  if (!coordIndex) {
    if (controlPoints <= coordinates) return "";
    return nodeLabel(shape) + ": " + counts + " make " + counted(controlPoints, "control point") + ": " + has;
  }
  for (int i = 0; i < coordIndex->getNum(); ++i)
    if ((*coordIndex)[i] < 0 || (*coordIndex)[i] >= coordinates)
      return nodeLabel(shape) + ": coordIndex[" + std::to_string(i) + "] = " + std::to_string((*coordIndex)[i]) +
             " is not a vertex: " + has;
  return shortIndexProblem(shape, "coordIndex", *coordIndex,
                           static_cast<int>(std::min<std::int64_t>(controlPoints, INT32_MAX)),
                           counts + std::string(" = ") + counted(controlPoints, "control point"));
}

template <class Surface>
std::string surfaceProblem(const Surface& surface, const SoMFInt32* coordIndex, int coordinates) {
  const ControlPoints u{"numUControlPoints", surface.numUControlPoints.getValue(), "uKnotVector",
                        surface.uKnotVector.getNum()};
  const ControlPoints v{"numVControlPoints", surface.numVControlPoints.getValue(), "vKnotVector",
                        surface.vKnotVector.getNum()};
  std::string problem = knotProblem(surface, u);
  if (problem.empty()) problem = knotProblem(surface, v);
  if (problem.empty())
    problem = controlPointProblem(surface, u.count * v.count, "numUControlPoints x numVControlPoints", coordIndex,
                                  coordinates);
  return problem;
}

template <class Curve>
std::string curveProblem(const Curve& curve, const SoMFInt32* coordIndex, int coordinates) {
  const ControlPoints points{"numControlPoints", curve.numControlPoints.getValue(), "knotVector",
                             curve.knotVector.getNum()};
  std::string problem = knotProblem(curve, points);
  if (problem.empty()) problem = controlPointProblem(curve, points.count, "numControlPoints", coordIndex, coordinates);
  return problem;
}

}  // namespace

std::string nurbsShapeProblem(const SoShape& shape, SoState* state) {
  const int coordinates = SoCoordinateElement::getInstance(state)->getNum();
  if (shape.isOfType(SoNurbsSurface::getClassTypeId()))
    return surfaceProblem(static_cast<const SoNurbsSurface&>(shape), nullptr, coordinates);
  if (shape.isOfType(SoIndexedNurbsSurface::getClassTypeId())) {
    const auto& surface = static_cast<const SoIndexedNurbsSurface&>(shape);
    return surfaceProblem(surface, &surface.coordIndex, coordinates);
  }
  if (shape.isOfType(SoNurbsCurve::getClassTypeId()))
    return curveProblem(static_cast<const SoNurbsCurve&>(shape), nullptr, coordinates);
  if (shape.isOfType(SoIndexedNurbsCurve::getClassTypeId())) {
    const auto& curve = static_cast<const SoIndexedNurbsCurve&>(shape);
    return curveProblem(curve, &curve.coordIndex, coordinates);
  }
  return "";
}

}  // namespace figment::guard::shapes
