#pragma once
// MannequinSkin: draws a Mannequin's body mesh, posed and sized, or some of its parts.

#include <Inventor/fields/SoMFString.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/nodes/SoNode.h>
#include <Inventor/nodes/SoSubNode.h>

#include <memory>

class SoChildList;

/*!
  \class MannequinSkin nodes/body/MannequinSkin.h
  \brief The body mesh of a Mannequin, following its pose and size.

  Draws the triangles of `mannequin`'s body whose parts are listed in `parts` (all when
  empty), each vertex moved with its part and blended near the joints (sim/body/Skinning.h),
  as an indexed face set with the current state (Material, ShapeHints). Takes part in
  bounding-box, pick, callback and primitive count actions like a shape. A scene draws
  the arms apart from the torso this way, each in a StencilSeparator (paper §5).

  An unusable mannequin (see Mannequin) draws nothing; the error is posted once through
  SoDebugError, and the ClothEngine that uses the mannequin reports it. A `mannequin`
  that is not a Mannequin at all is a read error ("MannequinSkin 'Arms': mannequin is a
  Cube, not a Mannequin"): the file does not read.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    MannequinSkin {
        mannequin NULL
        parts [ ]
    }
  \endcode
*/
class MannequinSkin : public SoNode {
  typedef SoNode inherited;
  SO_NODE_HEADER(MannequinSkin);

 public:
  static void initClass();
  MannequinSkin();

  SoSFNode mannequin;  // a Mannequin. Default NULL (nothing drawn).
  SoMFString parts;    // part names (sim/body/Skeleton.h). Default [ ] (every part).

  // The error of the last update, one line; empty when it drew.
  const std::string& lastError() const;

  void doAction(SoAction* action) override;
  void callback(SoCallbackAction* action) override;
  void GLRender(SoGLRenderAction* action) override;
  void getBoundingBox(SoGetBoundingBoxAction* action) override;
  void pick(SoPickAction* action) override;
  void getPrimitiveCount(SoGetPrimitiveCountAction* action) override;
  void search(SoSearchAction* action) override;
  SoChildList* getChildren() const override;
  void notify(SoNotList* list) override;

 protected:
  ~MannequinSkin() override;
  SbBool readInstance(SoInput* in, unsigned short flags) override;

 private:
  void update();
  // "MannequinSkin 'Arms': " (the DEF name when it has one).
  std::string label() const;
  // "mannequin is a Cube, not a Mannequin"; "" when it is one (or NULL).
  std::string mannequinTypeError() const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};
