// Uses the installed FIGMENT node kit from another project: registers a node type of
// its own beside FIGMENT's and reads a scene with both. Exits 0 when all is as written.

#include <nodes/cloth/ClothEngine.h>
#include <nodes/render/ClothingLayer.h>
#include <nodes/Init.h>
#include <nodes/body/MeshFile.h>

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/fields/SoSFString.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSubNode.h>

#include <cstdio>
#include <cstring>

// The project's own node, in the global namespace as Coin's type system expects.
class MarkerNode : public SoNode {
  typedef SoNode inherited;
  SO_NODE_HEADER(MarkerNode);

 public:
  static void initClass() { SO_NODE_INIT_CLASS(MarkerNode, SoNode, "Node"); }
  MarkerNode() {
    SO_NODE_CONSTRUCTOR(MarkerNode);
    SO_NODE_ADD_FIELD(label, (""));
  }
  SoSFString label;  // what the marker marks. Default "".

 protected:
  ~MarkerNode() override = default;
};

SO_NODE_SOURCE(MarkerNode);

template <class T>
static T* first(SoNode* root) {
  SoSearchAction search;
  search.setType(T::getClassTypeId());
  search.apply(root);
  return search.getPath() ? static_cast<T*>(search.getPath()->getTail()) : nullptr;
}

int main() {
  SoDB::init();
  figment::init();
  MarkerNode::initClass();

  static const char scene[] =
      "#Inventor V2.1 ascii\n"
      "Separator {\n"
      "  MarkerNode { label \"collar\" }\n"
      "  Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0 ] }\n"
      "  ClothingLayer { coordIndex [ 0 1 2 -1 ] masked TRUE }\n"
      "}\n";
  SoInput in;
  in.setBuffer(scene, std::strlen(scene));
  SoSeparator* root = SoDB::readAll(&in);
  if (!root) {
    std::fprintf(stderr, "figment_package_test: the scene did not read\n");
    return 1;
  }
  root->ref();
  MarkerNode* marker = first<MarkerNode>(root);
  ClothingLayer* layer = first<ClothingLayer>(root);
  const bool ok = marker && layer && marker->label.getValue() == "collar" && layer->masked.getValue() &&
                  layer->coordIndex.getNum() == 4 && MeshFile::getClassTypeId() != SoType::badType() &&
                  ClothEngine::getClassTypeId() != SoType::badType();
  root->unref();
  std::printf("figment_package_test: %s\n", ok ? "ok" : "FAILED");
  return ok ? 0 : 1;
}
