#pragma once
// CapsuleVolume: the paper's 12-parameter capsule as a scene node (§3.1).

#include <Inventor/fields/SoSFFloat.h>

#include "nodes/body/CollisionVolumeNode.h"

namespace figment {
struct CapsuleParameters;
}  // namespace figment

/*!
  \class CapsuleVolume nodes/body/CapsuleVolume.h
  \brief A body part's capsule: the 12 parameters of sim/collision/Capsule.h as fields.

  The unit capsule (y in [-1/2, 1/2], radius 1/2, ends rounded by r1 at the bottom and
  r2 at the top) is tapered by tx, tz, scaled by x, y, z, tilted by theta about the
  horizontal axis at phi from x towards z, and moved by (ox, oy, oz). Lengths in metres,
  angles in radians. figment-fit writes these from the genetic algorithm's fit.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    CapsuleVolume {
        part ""
        r1 1  r2 1  tx 0  tz 0
        x 1  y 1  z 1
        ox 0  oy 0  oz 0
        theta 0  phi 0
    }
  \endcode
*/
class CapsuleVolume : public CollisionVolumeNode {
  typedef CollisionVolumeNode inherited;
  SO_NODE_HEADER(CapsuleVolume);

 public:
  static void initClass();
  CapsuleVolume();

  SoSFFloat r1, r2;      // rounding of the bottom and top ends, [0, 1]
  SoSFFloat tx, tz;      // taper, (-2, 2)
  SoSFFloat x, y, z;     // dimensions, m, > 0
  SoSFFloat ox, oy, oz;  // offset of the centre, m
  SoSFFloat theta, phi;  // tilt and the tilt axis's direction, rad

  // The fields as parameters (not validated) and back.
  figment::CapsuleParameters parameters() const;
  void setParameters(const figment::CapsuleParameters& p);

  std::shared_ptr<const figment::CollisionVolume> makeVolume(const figment::TriangleMesh&) const override;

 protected:
  ~CapsuleVolume() override;
  std::vector<Polyline> wireframe() const override;
};
