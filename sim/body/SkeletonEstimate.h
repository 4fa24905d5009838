#pragma once
// Estimating the humanoid skeleton (sim/body/Skeleton.h) of a body mesh standing in A- or
// T-pose, by cross-section analysis, in any unit and with any up axis.
//
// 1. Up (sim/body/BodyStance.h): of the six axis directions spanning at least 80 % of the largest extent, the
//    one whose lowest slab (4 % of the extent) holds two separate clusters (the feet)
//    and whose highest holds one (the head). Forward: from each leg's centroid just
//    above the ankles towards its foot's centroid (the toes reach forward).
// 2. The mesh is turned so (up, forward) = (+y, +z), scaled to the default body's
//    height (1.66 m, where sim/body/BodySlices.h's thresholds hold) and centred in x.
// 3. Landmarks from horizontal sections: the crotch (highest height where the legs are
//    two clusters), the armpits and the neck (BodySlices), the waist (narrowest torso
//    section between them; 66 % of the way up from crotch to armpits, as on the default
//    body, where the torso narrows all the way up); joints at the torso sections'
//    centroids (spine), the leg clusters' centroids at anthropometric heights (hips just
//    above the crotch, knees at 28.5 %, ankles at 4.5 % of the height), the foot's front
//    point (toes), the shoulder 4 cm inside the shoulder's outline above the armpit, and
//    along the line from the shoulder to the arm's farthest point (fingertip: of the
//    arm's own sections, clear of the torso, and not any vertex beside the torso, which
//    on a body with hanging arms is a hip) at 42 % and 75 % (elbow, wrist:
//    the upper arm, forearm and hand are about 0.42 : 0.33 : 0.25 of that reach).
// 4. The joints go back into the mesh's own frame and unit.

#include "sim/body/Skeleton.h"

namespace figment {

// Throws std::invalid_argument when no up axis shows feet below and one head above, or
// a landmark is not found (the mesh is not a standing humanoid).
Skeleton estimateSkeleton(const TriangleMesh& body);

}  // namespace figment
