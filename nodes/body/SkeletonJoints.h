#pragma once
// SkeletonJoints: the rest positions of a mannequin's joints, as data in a scene.

#include <Inventor/fields/SoMFString.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <Inventor/nodes/SoNode.h>
#include <Inventor/nodes/SoSubNode.h>

namespace figment {
struct Skeleton;
}  // namespace figment

/*!
  \class SkeletonJoints nodes/body/SkeletonJoints.h
  \brief Names and rest positions of the humanoid skeleton's joints (sim/body/Skeleton.h).

  The skeleton of a Mannequin: its 25 joints by name (pelvis, waist, chest, neckBase,
  neckTop, headTop, hipL, kneeL, ankleL, toeL, shoulderBaseL, shoulderL, elbowL, wristL,
  fingertipL, the R side, pelvisFloor) in any order, at their rest positions in the
  body's frame (metres). The hierarchy and the parts are the humanoid skeleton's. The
  default body has no skeleton of its own: figment-fit estimates one from the mesh's
  cross sections (sim/body/SkeletonEstimate.h) and writes it here. Does nothing in actions.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    SkeletonJoints {
        names [ ]
        positions [ ]
    }
  \endcode
*/
class SkeletonJoints : public SoNode {
  typedef SoNode inherited;
  SO_NODE_HEADER(SkeletonJoints);

 public:
  static void initClass();
  SkeletonJoints();

  SoMFString names;
  SoMFVec3f positions;  // m, one per name

  // The skeleton; throws std::invalid_argument naming the field and value when a name
  // is unknown or repeated, a joint is missing, or the counts differ.
  figment::Skeleton skeleton() const;
  void setSkeleton(const figment::Skeleton& skeleton);

 protected:
  ~SkeletonJoints() override;
};
