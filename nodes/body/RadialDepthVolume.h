#pragma once
// RadialDepthVolume: the paper's radial depth volume as a scene node (§3.2).

#include <Inventor/fields/SoMFFloat.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFInt32.h>
#include <Inventor/fields/SoSFVec3f.h>

#include "nodes/body/CollisionVolumeNode.h"

namespace figment {
struct RadialDepthParameters;
}  // namespace figment

/*!
  \class RadialDepthVolume nodes/body/RadialDepthVolume.h
  \brief A body part as cross sections whose radial depth is a Fourier series.

  The fields of sim/collision/RadialDepth.h: an axis from `base` along `direction` for
  `length` metres; angles measured about it from `reference` towards direction x
  reference; n equally spaced sections (the first at base, the last at the far end),
  section j's radial depth r_j(a) = c0 + sum_k=1..K (c(2k-1) cos ka + c(2k) sin ka) in
  metres; linear between sections; flat caps. `coefficients` holds the sections one
  after another, 2K + 1 values each, so n = coefficients / (2K + 1) (at least 2).
  figment-fit writes these from the fit.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    RadialDepthVolume {
        part ""
        base 0 0 0
        direction 0 1 0
        reference 1 0 0
        length 1
        harmonics 0
        coefficients [ ]
    }
  \endcode
*/
class RadialDepthVolume : public CollisionVolumeNode {
  typedef CollisionVolumeNode inherited;
  SO_NODE_HEADER(RadialDepthVolume);

 public:
  static void initClass();
  RadialDepthVolume();

  SoSFVec3f base;          // m
  SoSFVec3f direction;     // the axis, any length (normalised)
  SoSFVec3f reference;     // angle 0, perpendicular to the axis (made so)
  SoSFFloat length;        // m, > 0
  SoSFInt32 harmonics;     // K >= 0
  SoMFFloat coefficients;  // m, (2K + 1) per section

  // The fields as parameters; throws std::invalid_argument naming the node and field
  // when they make no volume.
  figment::RadialDepthParameters parameters() const;
  void setParameters(const figment::RadialDepthParameters& p);

  std::shared_ptr<const figment::CollisionVolume> makeVolume(const figment::TriangleMesh&) const override;

 protected:
  ~RadialDepthVolume() override;
  std::vector<Polyline> wireframe() const override;
};
