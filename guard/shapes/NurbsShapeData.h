#pragma once
// Whether a NURBS shape reads only the control points there are. Coin takes its control
// points from the coordinates by count (or by coordIndex) without a look: a NurbsSurface
// counting more control points than the coordinates, or an IndexedNurbsSurface's coordIndex
// past them, crashed figment-view (SIGSEGV); a knot vector shorter than its control points
// plus two ended in std::bad_array_new_length.

#include <string>

class SoShape;
class SoState;

namespace figment::guard::shapes {

// "" when `shape` (a NurbsSurface, IndexedNurbsSurface, NurbsCurve or IndexedNurbsCurve;
// others have nothing to check), drawn with `state`, has its control points among the
// coordinates (its coordIndex entries vertices, with one for each control point) and each
// knot vector as long as its control points plus an order of at least 2; else one line
// naming node, field and counts.
std::string nurbsShapeProblem(const SoShape& shape, SoState* state);

}  // namespace figment::guard::shapes
