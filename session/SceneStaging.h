#pragma once
// What figment-view adds around a scene so it can be seen: a camera and a light.

#include <Inventor/SbBox3f.h>
#include <Inventor/SbVec3f.h>

#include <optional>

#include "session/SessionOptions.h"

class SoNode;
class SoPerspectiveCamera;
class SoSeparator;

namespace figment::session {

// A perspective camera with a 45 degree vertical field of view looking at the centre of
// `box` from direction `view` (camera at centre + d * (sin AZ cos EL, sin EL,
// cos AZ cos EL), y up), at the nearest distance d where all eight corners of the box
// lie inside both fields of view (horizontal from `aspect` = width/height), with a 5%
// margin (framingDistance), or at `distance` when it is positive. An empty box frames the
// unit cube around the origin.
SoPerspectiveCamera* framingCamera(const SbBox3f& box, const ViewDirection& view, float aspect, float distance = 0.0f);
// The distance framingCamera() keeps from the centre of `box` for `view`: the nearest at
// which all eight corners lie inside both fields of view, with a 5% margin. Views that
// must show the scene at one size (a turntable) frame it from the largest of theirs.
float framingDistance(const SbBox3f& box, const ViewDirection& view, float aspect);

// A new root holding `scene` and what it lacks, ready for SoOffscreenRenderer:
//  - the scene's own camera when it has one and `view` is not given; otherwise a
//    framingCamera() (the scene's cameras are then taken out of the scene);
//  - a directional light shining along the view direction (a headlight) when the
//    scene has no light of its own.
// Its bounding-box pass reads every shape's coordinates, so the ClothEngines feeding
// them are evaluated here, before anything is drawn. The root is not referenced.
SoSeparator* stageScene(SoNode* scene, const ImageSize& size, const std::optional<ViewDirection>& view);
// The same, framing `box`, the scene's bounding box (sceneBox) already computed, from
// `distance` when it is positive (see framingCamera).
SoSeparator* stageScene(SoNode* scene, const ImageSize& size, const std::optional<ViewDirection>& view,
                        const SbBox3f& box, float distance = 0.0f);

// The bounding box of `scene` in a viewport of `size`. Reading every shape's
// coordinates evaluates the ClothEngines that feed them.
SbBox3f sceneBox(SoNode* scene, const ImageSize& size);

}  // namespace figment::session
