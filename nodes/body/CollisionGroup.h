#pragma once
// CollisionGroup: several collision bodies as one ClothEngine body.

#include <Inventor/fields/SoMFNode.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/nodes/SoSubNode.h>

#include "nodes/body/CollisionBody.h"

/*!
  \class CollisionGroup nodes/body/CollisionGroup.h
  \brief The union of collision bodies: a Mannequin and the garments draped on it.

  `body` and each node in `layers` is a collision body (Mannequin, MeshFile,
  GarmentSurface, another CollisionGroup); a cloth node is in contact when it touches
  any, and is pushed out of the deepest (sim/collision/CompositeCollider.h); a posed
  HumanBody among them moves into its pose as the drape runs, as it does alone. A garment
  over another names the body (usually `USE` of the scene's Mannequin) and the inner
  garments' GarmentSurfaces; the inner garment drapes first, because its surface's
  points are connected to its output. The bodies are referenced, not drawn: draws
  nothing. (The shared body has a field of its own: Coin writes a `USE` inside a list
  of nodes as `USE Name,`, which it cannot read back.)

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    CollisionGroup { body NULL  layers [ ] }
  \endcode
*/
class CollisionGroup : public SoNode, public figment::CollisionBody {
  typedef SoNode inherited;
  SO_NODE_HEADER(CollisionGroup);

 public:
  static void initClass();
  CollisionGroup();

  SoSFNode body;    // Default NULL; a collision body
  SoMFNode layers;  // Default [ ]; each a collision body (GarmentSurface: a garment beneath)

  // Throws std::invalid_argument naming this node, the field (layers[i]) and what is
  // wrong (not a collision body; its own error; nothing at all).
  std::shared_ptr<const figment::Collider> bodyCollider() const override;
  // The layers alone (the garments beneath, without `body`), which a garment put on over
  // them starts clean over (sim/drape/LayerStart.h); null when there are none. Throws as
  // bodyCollider().
  std::shared_ptr<const figment::Collider> layersCollider() const;
  // "group" with the number of "bodies" (body and layers).
  Description describeBody() const override;
  std::string label() const;  // "CollisionGroup 'Name'" or "CollisionGroup"

 protected:
  ~CollisionGroup() override;

 private:
  std::shared_ptr<const figment::Collider> collider(bool withBody) const;
};
