#pragma once
// GarmentSurface: another garment's draped surface as something cloth collides with.

#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/nodes/SoSubNode.h>

#include "nodes/body/CollisionBody.h"

/*!
  \class GarmentSurface nodes/cloth/GarmentSurface.h
  \brief A draped garment's surface, thickened, for a garment draped over it.

  `point` is connected to the inner garment's ClothEngine output, so the outer garment's
  drape waits for the inner one's (Coin evaluates the connection); `coordIndex` is that
  garment's faces. The surface is its triangles, searched through a bounding-volume
  hierarchy, moved out by `thickness` along its outward normal (the side its faces
  are counter-clockwise from, as FIGMENT's garment generators make them); a point
  nearest an open edge (a hem, a neckline) is never behind it. The inner garment feels
  nothing of the outer one: layers drape once each, inside out. Draws nothing: put it in
  a CollisionGroup with the body, as a ClothEngine's `body`:
  \code
    body CollisionGroup { body USE Model
                          layers GarmentSurface { point = USE InnerDrape.positions
                                                  coordIndex = USE InnerPattern.coordIndex } }
  \endcode

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    GarmentSurface { point [ ]  coordIndex [ ]  thickness 0.001 }
  \endcode
*/
class GarmentSurface : public SoNode, public figment::CollisionBody {
  typedef SoNode inherited;
  SO_NODE_HEADER(GarmentSurface);

 public:
  static void initClass();
  GarmentSurface();

  SoMFVec3f point;       // the draped garment's nodes, m
  SoMFInt32 coordIndex;  // its faces, -1 separated
  SoSFFloat thickness;   // m the surface stands out by (the cloth's own thickness and some). Default 0.001; >= 0.

  // Throws std::invalid_argument naming this node, the field and the value.
  std::shared_ptr<const figment::Collider> bodyCollider() const override;
  // "garment surface" with its "points".
  Description describeBody() const override;
  std::string label() const;  // "GarmentSurface 'Name'" or "GarmentSurface"

  void notify(SoNotList* list) override;

 protected:
  ~GarmentSurface() override;

 private:
  mutable std::shared_ptr<const figment::Collider> collider_;
};
