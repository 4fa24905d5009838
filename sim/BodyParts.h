#pragma once
// A body mesh cut into the parts of its skeleton (sim/Skeleton.h), and a radial depth
// volume fitted along each part's bone: the inputs of the collision volumes (§3).

#include "RadialDepthVolume.h"
#include "Skeleton.h"

#include <string>
#include <vector>

namespace figment {

struct PartMesh {
  std::string name;
  TriangleMesh mesh;  // the body's triangles whose centroid is nearest this part's bone
  Vec3 from, to;      // the bone
};

std::vector<PartMesh> splitIntoParts(const TriangleMesh& body, const Skeleton& skeleton);

// A radial depth volume along the part's bone, lengthened to span every vertex of the
// part, with sections about `sectionSpacing` (m) apart and K = `harmonics`.
RadialDepthVolume fitRadialPart(const PartMesh& part, int harmonics, double sectionSpacing);

}  // namespace figment
