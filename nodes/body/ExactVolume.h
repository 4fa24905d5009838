#pragma once
// ExactVolume: a body part that collides with its own triangles (the accuracy reference).

#include "nodes/body/CollisionVolumeNode.h"

/*!
  \class ExactVolume nodes/body/ExactVolume.h
  \brief A part of a Mannequin whose collision surface is the body mesh itself.

  The part's triangles of the mannequin's body (those the skeleton assigns to `part`),
  searched through a bounding-volume hierarchy: exact, and the slowest choice. A scene
  pays for it only in the parts that need it (a face, a hand). Draws nothing: its
  surface is the body.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    ExactVolume { part "" }
  \endcode
*/
class ExactVolume : public CollisionVolumeNode {
  typedef CollisionVolumeNode inherited;
  SO_NODE_HEADER(ExactVolume);

 public:
  static void initClass();
  ExactVolume();

  std::shared_ptr<const figment::CollisionVolume> makeVolume(const figment::TriangleMesh&) const override;

 protected:
  ~ExactVolume() override;
  std::vector<Polyline> wireframe() const override { return {}; }
};
