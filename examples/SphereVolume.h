#pragma once
// SphereVolume: a collision volume of this project's own, a sphere the cloth collides
// with, added to FIGMENT's node kit from outside it.

#include <Inventor/fields/SoSFVec3f.h>
#include <Inventor/nodes/SoSphere.h>
#include <nodes/body/CollisionBody.h>

/*!
  A sphere at `center` (m, the node's own coordinates) of the inherited `radius` (m):
  drawn as Coin's Sphere there, and, as a ClothEngine's `body` (or one of a
  CollisionGroup's), a collision body. Written as
  \code
    DEF Ball SphereVolume { center 0 0.5 0  radius 0.25 }
    ... ClothEngine { body USE Ball ... }
  \endcode
  In the global namespace and in a library named after it (libSphereVolume.so), so a
  Coin program that has never heard of it, figment-view included, loads it when it
  reads a scene that uses it (the library on LD_LIBRARY_PATH).
*/
class SphereVolume : public SoSphere, public figment::CollisionBody {
  typedef SoSphere inherited;
  SO_NODE_HEADER(SphereVolume);

 public:
  static void initClass();
  SphereVolume();

  SoSFVec3f center;  // m. Default 0 0 0.

  // figment::CollisionBody: the sphere as the simulation sees it. Throws
  // std::invalid_argument when radius <= 0 (the engine reports it as one line).
  std::shared_ptr<const figment::Collider> bodyCollider() const override;
  // figment-view --stats: kind "sphere", no parts.
  Description describeBody() const override;

  // Drawing and bounds: the Sphere moved to `center`.
  void GLRender(SoGLRenderAction* action) override;
  void getBoundingBox(SoGetBoundingBoxAction* action) override;
  void rayPick(SoRayPickAction* action) override;
  void callback(SoCallbackAction* action) override;

 protected:
  ~SphereVolume() override;
};
