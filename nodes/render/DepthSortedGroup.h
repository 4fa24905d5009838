#pragma once
// DepthSortedGroup: the pieces of one garment, drawn far to near (paper §5).

#include <Inventor/nodes/SoGroup.h>

/*!
  \class DepthSortedGroup nodes/render/DepthSortedGroup.h
  \brief A group whose children render from the farthest to the nearest.

  Paper §5: a garment made of several seamed meshes (the body of a shirt and its
  sleeves, each a ClothingLayer) cannot be drawn in a fixed order, since each
  ClothingLayer draws the facets that face the viewer over everything before it: a
  sleeve drawn after the body of the shirt would show through it from behind. When
  rendering, this group measures the distance from the eye to the centre of each
  child's bounding box (along the viewing direction for an orthographic camera), every
  render, and traverses the children in decreasing order of it, so a rotated view is
  drawn right. Every other action traverses the children in order, as a Group does.

  Each child should be a self-contained piece (a Separator with its own coordinates
  and material): the group changes their order, so state must not flow between them.
  Layers of clothing are not pieces: they go in scene order, inner first.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    DepthSortedGroup {
    }
  \endcode
*/
class DepthSortedGroup : public SoGroup {
  typedef SoGroup inherited;
  SO_NODE_HEADER(DepthSortedGroup);

 public:
  static void initClass();
  DepthSortedGroup();

  void GLRender(SoGLRenderAction* action) override;

 protected:
  ~DepthSortedGroup() override;
};
