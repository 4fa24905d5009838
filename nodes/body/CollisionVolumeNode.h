#pragma once
// CollisionVolumeNode: the base of a body part's collision volume node (paper §3).

#include <Inventor/fields/SoSFString.h>
#include <Inventor/nodes/SoShape.h>
#include <Inventor/nodes/SoSubNode.h>

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace figment {
class CollisionVolume;
struct TriangleMesh;
}  // namespace figment

/*!
  \class CollisionVolumeNode nodes/body/CollisionVolumeNode.h
  \brief Abstract: one collision volume of one part of a Mannequin.

  A volume is given in the mannequin's rest frame (metres, the frame of its body mesh
  and joints) and belongs to the part named by `part` (a part of the humanoid skeleton,
  sim/body/Skeleton.h: head, neck, upperTorso, lowerTorso, hips, upperArmL, forearmL, handL,
  thighL, shinL, footL and the R side); the Mannequin that holds it moves it with that
  part when it is posed or sized. A part may have several volumes.

  Drawn, picked and counted as a wireframe of lines, in the current colour without
  lighting; a Mannequin draws its volumes only when its `showVolumes` is TRUE.
  Subclasses: CapsuleVolume, RadialDepthVolume, ExactVolume.
*/
class CollisionVolumeNode : public SoShape {
  typedef SoShape inherited;
  SO_NODE_ABSTRACT_HEADER(CollisionVolumeNode);

 public:
  static void initClass();

  // The skeleton part this volume belongs to. Default "".
  SoSFString part;

  // The volume for the simulation, in the rest frame. `partTriangles` are the body's
  // triangles that belong to `part` (what an ExactVolume is made of; the others ignore
  // them). Throws std::invalid_argument naming the node, the field and the value when
  // the fields do not make a volume.
  virtual std::shared_ptr<const figment::CollisionVolume> makeVolume(
      const figment::TriangleMesh& partTriangles) const = 0;
  // "CapsuleVolume 'Name'" or "CapsuleVolume": how messages name this node.
  std::string label() const;

  void GLRender(SoGLRenderAction* action) override;
  void notify(SoNotList* list) override;

 protected:
  CollisionVolumeNode();
  ~CollisionVolumeNode() override;

  using Polyline = std::vector<Eigen::Vector3f>;
  // The wireframe in the rest frame; empty when the fields make no volume.
  virtual std::vector<Polyline> wireframe() const = 0;

  void generatePrimitives(SoAction* action) override;
  void computeBBox(SoAction* action, SbBox3f& box, SbVec3f& center) override;

 private:
  // The wireframe, computed once per change of the fields (empty, with a warning, when
  // they make no volume).
  const std::vector<Polyline>& cachedWireframe() const;

  mutable std::vector<Polyline> wireframe_;
  mutable bool wireframeValid_ = false;
};
