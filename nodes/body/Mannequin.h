#pragma once
// Mannequin: the jointed body as collision volumes, posed and sized (paper §3).

#include <Inventor/fields/SoMFRotation.h>
#include <Inventor/fields/SoMFString.h>
#include <Inventor/fields/SoSFBool.h>
#include <Inventor/fields/SoSFColor.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSubNode.h>

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "nodes/body/CollisionBody.h"

namespace figment {
class Collider;
struct SkinWeights;
struct Skeleton;
struct TriangleMesh;
}  // namespace figment

/*!
  \class Mannequin nodes/body/Mannequin.h
  \brief A body's skeleton and collision volumes; poses and sizes them; a ClothEngine body.

  Its children hold the mannequin's data, at any depth (a File node included): one
  SkeletonJoints and the CollisionVolumeNode nodes (CapsuleVolume, RadialDepthVolume,
  ExactVolume), one or more per part, all in the rest frame of `body`. figment-fit
  writes them for a body once; a scene includes the file:
  \code
    Switch { whichChild -1  DEF Body MeshFile { fileName "human.zae" } }
    DEF Model Mannequin {
      body USE Body
      rotatedJoints [ "shoulderL", "shoulderR" ]
      rotations [ 0 0 1 0.3, 0 0 1 -0.3 ]
      height 1.05
      File { name "human-volumes.iv" }
    }
    MannequinSkin { mannequin USE Model }
    ... ClothEngine { body USE Model ... }
  \endcode
  Posing and sizing are geometric transformations of the parts (sim/body/Posing.h): each
  joint in `rotatedJoints` turns by its rotation about its rest position, carrying the
  parts below it; `height` scales the whole body about the floor, `armLength` the arms
  along their bones, `chest`, `waist` and `hips` the girth of the upper torso, lower
  torso and hips. The volumes follow their parts' transformations (no reshaping) and
  MannequinSkin draws the body mesh following them, blended within `blendRadius` of
  each joint.

  As a ClothEngine's body, the collider is the set of posed volumes: a cloth node inside
  several (they overlap at the joints) is put outside all of them. The parts named in
  `exactParts` collide with their own triangles of `body` instead of their volumes (as
  an ExactVolume would, without editing the fitted volumes file): exact where a garment
  rests, the cheaper volumes elsewhere.

  Draws nothing unless `showVolumes` is TRUE: then its volumes, posed, as wireframes in
  `volumeColor` (figment-view --show-volumes sets it). Other actions reach the volumes
  only then; search and write see the children as a Group's.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    Mannequin {
        body NULL
        rotatedJoints [ ]
        rotations [ ]
        height 1
        chest 1
        waist 1
        hips 1
        armLength 1
        blendRadius 0.04
        exactParts [ ]
        showVolumes FALSE
        volumeColor 0.1 0.85 0.25
    }
  \endcode
*/
class Mannequin : public SoGroup, public figment::CollisionBody {
  typedef SoGroup inherited;
  SO_NODE_HEADER(Mannequin);

 public:
  static void initClass();
  Mannequin();

  // The body mesh (a MeshFile) in the rest frame: drawn by MannequinSkin, and the
  // triangles of ExactVolume parts. Default NULL (volumes only; MannequinSkin draws
  // nothing and ExactVolume is an error).
  SoSFNode body;
  // Joints to turn, by name (SkeletonJoints), and their rotations, one each (axis and
  // angle in radians, in the rest frame). Default [ ] and [ ] (the rest pose).
  SoMFString rotatedJoints;
  SoMFRotation rotations;
  // Sizing factors, 1 = as fitted; each in [0.5, 2]. Default 1.
  SoSFFloat height, chest, waist, hips, armLength;
  // Distance from a joint within which the skin blends between its two parts, m.
  // Default 0.04. Must be > 0.
  SoSFFloat blendRadius;
  // Parts (by name) that collide with their own triangles of `body` instead of their
  // volumes. Default [ ]. Needs `body`.
  SoMFString exactParts;
  SoSFBool showVolumes;   // Default FALSE.
  SoSFColor volumeColor;  // Default 0.1 0.85 0.25.

  // The posed volumes as one collider (built on first use, kept until a field or child
  // changes). Throws std::invalid_argument with one line naming this node, the field
  // and the value when the data or the fields are unusable.
  std::shared_ptr<const figment::Collider> collider() const;
  // The same with the parts in `alsoExact` (skeleton part indices) colliding with their
  // own triangles too (a tolerance's per-part mix, sim/drape/MethodChoice.h); built
  // anew on each call. Throws as collider(), and when `body` is NULL.
  std::shared_ptr<const figment::Collider> colliderWithExactParts(const std::vector<int>& alsoExact) const;
  // As a ClothEngine's body (figment::CollisionBody): collider(). Described as kind
  // "mannequin" with its capsule_volumes, radial_volumes and exact_parts (all 0 when
  // the volumes cannot be read).
  std::shared_ptr<const figment::Collider> bodyCollider() const override { return collider(); }
  Description describeBody() const override;
  // The skeleton of the SkeletonJoints child (rest frame); throws as collider().
  const figment::Skeleton& skeleton() const;
  // Rest frame -> posed frame, one per skeleton part; throws as collider().
  const std::vector<Eigen::Affine3d>& partTransforms() const;
  // The body's drawn mesh (MeshFile point/coordIndex), posed and sized, and the part
  // of each of its triangles; throws as collider(), and when `body` is NULL.
  const figment::TriangleMesh& posedBody() const;
  const std::vector<int>& triangleParts() const;
  // How each vertex of the drawn mesh follows the parts (its own part as the volumes
  // were fitted to it: sim/body/BodyParts.h assignTriangles); throws as posedBody().
  const figment::SkinWeights& skinWeights() const;
  // The volumes and the part each belongs to, in the order found.
  struct VolumeEntry {
    class CollisionVolumeNode* node;
    int part;
  };
  const std::vector<VolumeEntry>& volumes() const;

  // "Mannequin 'Name'", or "Mannequin": how messages name it.
  std::string label() const;

  void GLRender(SoGLRenderAction* action) override;
  void getBoundingBox(SoGetBoundingBoxAction* action) override;
  void callback(SoCallbackAction* action) override;
  void pick(SoPickAction* action) override;
  void getPrimitiveCount(SoGetPrimitiveCountAction* action) override;
  void handleEvent(SoHandleEventAction* action) override;
  void getMatrix(SoGetMatrixAction* action) override;
  void notify(SoNotList* list) override;

 protected:
  ~Mannequin() override;
  SbBool readInstance(SoInput* in, unsigned short flags) override;

 private:
  struct Model;
  const Model& model() const;  // built on demand; throws std::invalid_argument
  // The posed volumes, parts marked in `exact` (one flag per skeleton part) by their triangles.
  std::shared_ptr<const figment::Collider> buildCollider(const std::vector<char>& exact) const;
  // The volumes, each under its part's transformation, when showVolumes is TRUE.
  void traverseVolumes(SoAction* action);

  mutable std::shared_ptr<Model> model_;
  mutable std::shared_ptr<const figment::Collider> collider_;
  mutable std::unique_ptr<figment::TriangleMesh> posedBody_;
  mutable std::vector<int> triangleParts_;
  mutable std::unique_ptr<figment::SkinWeights> skinWeights_;
};
