#pragma once
// Whether a VRML97 shape reads only the data it has. Coin trusts their indices as it does
// Inventor's: a VRMLIndexedFaceSet's colorIndex entry past its colors crashed figment-view
// (SIGSEGV), and coordIndex entries past the coordinates, or an ElevationGrid with fewer
// heights than its grid, drew with a warning what the scene did not say.

#include <string>

class SoVRMLGeometry;

namespace figment::guard::shapes {

// "" when `shape` (a VRMLIndexedFaceSet, VRMLIndexedLineSet, VRMLPointSet or
// VRMLElevationGrid; others have nothing to check) indexes and counts only the data its own
// fields hold, as the VRML97 specification (ISO/IEC 14772-1) requires: coordIndex the
// coord's points; colorIndex, normalIndex and texCoordIndex their nodes' entries, or
// coordIndex those too where they are empty and the data go per vertex; an index as long as what it runs along
// (coordIndex, or the faces); per face without an index, a color or normal for each face. Else one line naming node,
// field, entry and value.
std::string vrmlShapeProblem(const SoVRMLGeometry& shape);

}  // namespace figment::guard::shapes
