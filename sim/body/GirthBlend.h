#pragma once
// Where two torso parts of different girth factors meet (chest != waist, or waist !=
// hips), their sized volumes meet in a step: the wider part's end cap stands out of the
// narrower part as a sharp rim (the lower torso's top rim 5 mm proud of the bust with
// chest 0.98 and waist 1). Cloth resting on that rim is pushed up by the cap and out by
// the side in turn and never comes to rest (the posed dress with height, chest, hips and
// arm length all set). So near such a joint the narrower part's cross sections grow
// towards the wider one's factor: linearly over `length` from the joint's plane (across
// the bone) into the part, and fully at the plane and beyond it (where the volumes
// overlap). Only ever growing, so the body's skin (sized by its parts' own factors) stays
// inside; the cloth stands off it by at most the factors' difference there.

#include <vector>

#include "sim/body/Posing.h"

namespace figment {

class GirthBlend {
 public:
  // Throws as partTransforms for bad sizing factors; `length` (m) must be > 0.
  GirthBlend(const Skeleton& skeleton, const Sizing& sizing, double length);

  // The factor (>= 1) by which part `part`'s cross section through rest point p grows on
  // top of its sizing map; 1 away from the joints above and for parts without girth.
  double growth(int part, const Vec3& restPoint) const;

 private:
  struct Joint {
    Vec3 position, inward;  // rest frame; inward: unit, along the bone into the part
    double factor;          // the wider neighbour's girth factor
  };
  std::vector<double> own_;                 // per part: its girth factor (1 without)
  std::vector<std::vector<Joint>> joints_;  // per part: its joints with a wider girth neighbour
  double length_;
};

}  // namespace figment
