#include "session/SceneStaging.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoLight.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nodes/SceneSearch.h"

namespace figment::session {

namespace {

constexpr float kFieldOfView = 45.0f * std::numbers::pi_v<float> / 180.0f;  // vertical, radians

float radians(double degrees) {
  return float(degrees * std::numbers::pi / 180.0);
}

// Paths to the nodes of `type` under `root` (which the caller holds a reference to);
// `all` includes inactive Switch children.
void findAll(SoNode* root, SoType type, bool all, SoPathList& out) {
  SoSearchAction search;
  search.setType(type, TRUE);
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(all ? TRUE : FALSE);
  search.apply(root);
  out = search.getPaths();
}

// Takes every camera out of `scene`, so the framing camera decides the view.
void removeCameras(SoNode* scene) {
  SoPathList paths;
  findAll(scene, SoCamera::getClassTypeId(), true, paths);
  for (int i = 0; i < paths.getLength(); ++i) {
    SoNode* parent = fullTail(paths[i], 1);
    if (parent && parent->isOfType(SoGroup::getClassTypeId()))
      static_cast<SoGroup*>(parent)->replaceChild(fullTail(paths[i]), new SoGroup);
  }
}

// What a framing camera frames: `box`, the unit box about the origin when it is empty,
// and at least a unit-sized box about a single point.
void framedBounds(const SbBox3f& box, SbVec3f& low, SbVec3f& high) {
  low.setValue(-1.0f, -1.0f, -1.0f), high.setValue(1.0f, 1.0f, 1.0f);
  if (!box.isEmpty()) box.getBounds(low, high);
  if ((high - low).length() < 1e-6f) {  // a single point still needs a size to frame
    low -= SbVec3f(0.5f, 0.5f, 0.5f);
    high += SbVec3f(0.5f, 0.5f, 0.5f);
  }
}

// The camera's axes for `view`: towards the camera, right and up on the screen.
void viewAxes(const ViewDirection& view, SbVec3f& toCamera, SbVec3f& right, SbVec3f& up) {
  const float az = radians(view.azimuth), el = radians(view.elevation);
  toCamera.setValue(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
  right = SbVec3f(0.0f, 1.0f, 0.0f).cross(toCamera);
  right.normalize();
  up = toCamera.cross(right);
}

}  // namespace

float framingDistance(const SbBox3f& box, const ViewDirection& view, float aspect) {
  SbVec3f low, high, toCamera, right, up;
  framedBounds(box, low, high);
  viewAxes(view, toCamera, right, up);
  const SbVec3f centre = 0.5f * (low + high);
  // The nearest distance at which every corner of the box lies inside both fields of
  // view: a corner at (x, y) across and z towards the camera from the centre needs
  // d - z >= |x| / tan(horizontal / 2) and d - z >= |y| / tan(vertical / 2).
  constexpr float kMargin = 1.05f;
  const float tanVertical = std::tan(kFieldOfView / 2.0f) / kMargin;
  const float tanHorizontal = tanVertical * aspect;
  float distance = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const SbVec3f p((corner & 1) ? high[0] : low[0], (corner & 2) ? high[1] : low[1], (corner & 4) ? high[2] : low[2]);
    const SbVec3f v = p - centre;
    const float needed =
        v.dot(toCamera) + std::max(std::abs(v.dot(right)) / tanHorizontal, std::abs(v.dot(up)) / tanVertical);
    distance = std::max(distance, needed);
  }
  return distance;
}

SoPerspectiveCamera* framingCamera(const SbBox3f& box, const ViewDirection& view, float aspect, float distance) {
  SbVec3f low, high, toCamera, right, up;
  framedBounds(box, low, high);
  viewAxes(view, toCamera, right, up);
  const SbVec3f centre = 0.5f * (low + high);
  const float radius = 0.5f * (high - low).length();
  if (!(distance > 0.0f)) distance = framingDistance(box, view, aspect);

  auto* camera = new SoPerspectiveCamera;
  camera->position = centre + distance * toCamera;
  camera->pointAt(centre, SbVec3f(0.0f, 1.0f, 0.0f));
  camera->heightAngle = kFieldOfView;
  // The field of view is exactly as computed: Coin must not widen it for the viewport.
  camera->viewportMapping = SoCamera::LEAVE_ALONE;
  camera->aspectRatio = aspect;
  camera->focalDistance = distance;
  camera->nearDistance = std::max(distance - 1.05f * radius, 1e-3f * distance);
  camera->farDistance = distance + 1.05f * radius;
  return camera;
}

SbBox3f sceneBox(SoNode* scene, const ImageSize& size) {
  SoGetBoundingBoxAction boxAction(SbViewportRegion(short(size.width), short(size.height)));
  boxAction.apply(scene);  // evaluates the engines that feed shapes
  return boxAction.getBoundingBox();
}

SoSeparator* stageScene(SoNode* scene, const ImageSize& size, const std::optional<ViewDirection>& view) {
  return stageScene(scene, size, view, sceneBox(scene, size));
}

SoSeparator* stageScene(SoNode* scene, const ImageSize& size, const std::optional<ViewDirection>& view,
                        const SbBox3f& box, float distance) {
  auto* root = new SoSeparator;
  SbVec3f lookDirection(0.0f, 0.0f, -1.0f);
  SoPathList cameras;
  findAll(scene, SoCamera::getClassTypeId(), false, cameras);
  if (cameras.getLength() > 0 && !view) {
    const auto* own = static_cast<SoCamera*>(fullTail(cameras[0]));
    own->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), lookDirection);
  } else {
    removeCameras(scene);
    SoPerspectiveCamera* camera =
        framingCamera(box, view.value_or(ViewDirection{}), float(size.width) / float(size.height), distance);
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), lookDirection);
    root->addChild(camera);
  }

  SoPathList lights;
  findAll(scene, SoLight::getClassTypeId(), false, lights);
  if (lights.getLength() == 0) {
    auto* headlight = new SoDirectionalLight;
    headlight->direction = lookDirection;
    root->addChild(headlight);
  }
  root->addChild(scene);
  return root;
}

}  // namespace figment::session
