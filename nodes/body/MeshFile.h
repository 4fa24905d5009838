#pragma once
// MeshFile: a mesh read from a file (Collada, .zae, OBJ, PLY, ... through assimp),
// drawn in place and offered to the simulation as a collision body.

#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoMFString.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <Inventor/fields/SoSFBool.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFString.h>
#include <Inventor/fields/SoSFVec3f.h>
#include <Inventor/nodes/SoSubNode.h>

#include <memory>

#include "nodes/body/CollisionBody.h"

class SoChildList;

namespace figment {
struct TriangleMesh;
class MeshCollider;
}  // namespace figment

/*!
  \class MeshFile nodes/body/MeshFile.h
  \brief Reads a mesh file and draws it; the body a garment collides with.

  The file is read when the node is read from an .iv file and again whenever one of
  fileName, metresPerUnit, upAxis, exclude or collisionExclude changes. The mesh is
  brought into the scene frame (metres, y up) and welded along texture seams (merged
  by position). It is drawn as an indexed face set with the current state (Material,
  ShapeHints: give a creaseAngle for smooth shading), and it takes part in
  bounding-box, pick, callback and primitive count actions; its internal nodes are
  hidden from SoSearchAction.

  Its merged mesh is also offered as two read-only output fields, `point` and
  `coordIndex`, so a garment pattern read from a file can feed a ClothEngine:
  \code
    Switch { whichChild -1  DEF Pattern MeshFile { fileName "dress.obj" } }
    ... DEF Drape ClothEngine { restPoints = USE Pattern.point
                                coordIndex = USE Pattern.coordIndex } ...
  \endcode
  The output fields are never written to a file: a written MeshFile is as small as
  the one read.

  A load error while reading an .iv file is a read error (SoReadError, naming the
  file, the node and the field's value), so SoDB::readAll() fails; a load error later
  (a field set from code) is posted through SoDebugError and leaves the node empty.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    MeshFile {
        fileName ""
        metresPerUnit 1
        upAxis Y
        exclude [ ]
        collisionExclude [ ]
        cropMin 0 0 0
        cropMax 0 0 0
        reverseFaces FALSE
    }
  \endcode

  Example (scenes/examples/MeshFile.iv):
  \code
    DEF Body MeshFile {
      fileName "human.zae"
      collisionExclude "human-highpolyeyes"
    }
  \endcode
*/
class MeshFile : public SoNode, public figment::CollisionBody {
  typedef SoNode inherited;
  SO_NODE_HEADER(MeshFile);

 public:
  static void initClass();
  MeshFile();

  enum UpAxis { X, Y, Z, NEG_X, NEG_Y, NEG_Z };

  // The mesh file. A relative name is looked up, in this order: from the working
  // directory, in each folder of $FIGMENT_MODEL_PATH, in the folder of the .iv file
  // being read (and the other folders of SoInput's search list), then among Debian's
  // assimp test models (/usr/share/assimp/models). Default "" (no mesh).
  SoSFString fileName;
  // Metres per unit of the file's coordinates (0.01 for a file in centimetres).
  // Default 1. Must be > 0.
  SoSFFloat metresPerUnit;
  // The file's up axis, rotated onto +y: X, Y, Z, NEG_X, NEG_Y or NEG_Z. Default Y.
  SoSFEnum upAxis;
  // Names of meshes in the file to leave out entirely. Default [ ] (none).
  SoMFString exclude;
  // Names of meshes that are drawn but left out of the collision surface (a body's
  // eyes, hair). Each must name a mesh of the file. Default [ ] (none).
  SoMFString collisionExclude;
  // A box in the scene frame (m, after metresPerUnit and upAxis): when set, the node
  // keeps only the triangles whose centroid lies inside it, drawn and for collisions.
  // A body part, until the body has real ones: the default scene draws the default
  // body's arms (|x| > 0.2 m) apart from its torso. Default 0 0 0 and 0 0 0 (no crop);
  // otherwise cropMin must be below cropMax on every axis.
  SoSFVec3f cropMin;
  SoSFVec3f cropMax;
  // The file's faces wind clockwise seen from outside: reverse each one's corners, so they
  // wind counterclockwise as FIGMENT's nodes and renderers take a face's front (a garment
  // wound clockwise says so before it drapes, naming this field). Default FALSE.
  SoSFBool reverseFaces;

  // Read-only outputs: the drawn mesh, merged by position, in metres, y up.
  // Vertices (m). Set by the node; not written to files.
  SoMFVec3f point;
  // Triangles as vertex indices into `point`, each followed by -1. Set by the node;
  // not written to files.
  SoMFInt32 coordIndex;

  // The collision surface: the mesh without the collisionExclude meshes, merged by
  // position (metres, scene frame). Empty when no file is loaded. Include
  // "sim/core/TriangleMesh.h" to use it.
  const figment::TriangleMesh& collisionSurface() const;
  // The exact collider over collisionSurface(), built on first use and kept until the
  // mesh changes (building its bounding-volume hierarchy is not free). Null when the
  // collision surface is empty. Include "sim/collision/MeshCollider.h" to use it.
  std::shared_ptr<const figment::MeshCollider> collider() const;

  // As a ClothEngine's body (figment::CollisionBody): collider(); throws
  // std::invalid_argument ("MeshFile 'Body' has no mesh") when it is null. Described
  // as kind "mesh".
  std::shared_ptr<const figment::Collider> bodyCollider() const override;
  Description describeBody() const override;

  // Actions reach the hidden mesh the way SoFile reaches its children.
  void doAction(SoAction* action) override;
  void callback(SoCallbackAction* action) override;
  void GLRender(SoGLRenderAction* action) override;
  void getBoundingBox(SoGetBoundingBoxAction* action) override;
  void pick(SoPickAction* action) override;
  void getPrimitiveCount(SoGetPrimitiveCountAction* action) override;
  // Finds this node, never its internal nodes.
  void search(SoSearchAction* action) override;
  SoChildList* getChildren() const override;

  void notify(SoNotList* list) override;
  void copyContents(const SoFieldContainer* from, SbBool copyConnections) override;

 protected:
  ~MeshFile() override;
  SbBool readInstance(SoInput* in, unsigned short flags) override;

  // Reads the file named by the fields; `in` is the SoInput being read, or null.
  // Returns false (after reporting) on error; the node is then empty. A subclass that
  // makes its mesh instead (HumanBody) loads its own way.
  virtual bool load(SoInput* in);
  // Whether a change of `field` loads the mesh again.
  virtual bool isLoadOption(const SoField* field) const;
  // Sets the drawn mesh (and the outputs) and the collision surface.
  void setMesh(const figment::TriangleMesh& drawn, const figment::TriangleMesh& collision);
  void clearMesh();
  // Empties the node and says why in one line, "<kind> '<name>': <error>": a read error
  // (which fails the read; Coin adds file and line) while reading from `in`, else a posted
  // debug error. Returns false, for load() to return.
  bool failLoad(const char* kind, SoInput* in, const std::string& error);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
