#pragma once
// CollisionBody: what a ClothEngine's `body` must be. MeshFile and Mannequin provide it.

#include <memory>
#include <string>
#include <utility>
#include <vector>

class SoNode;

namespace figment {

class Collider;

// A node that cloth can collide with. A plain C++ interface beside the Coin node class
// (class MeshFile : public SoNode, public figment::CollisionBody), so the cloth engine
// and the statistics ask the body itself instead of switching on node types.
class CollisionBody {
 public:
  virtual ~CollisionBody();

  // The collider, in the body node's own coordinates (built on first use and kept
  // until the body changes). Throws std::invalid_argument with one line naming the node
  // and what is wrong ("MeshFile 'Body' has no mesh") when it cannot be used.
  virtual std::shared_ptr<const Collider> bodyCollider() const = 0;

  // What figment-view --stats says about the body: its kind ("mesh", "mannequin") and,
  // by name, how many of each kind of part it is made of (e.g. "capsule_volumes").
  // (sim/drape/DrapeBody.h's BodyDescription holds the same for a drape's report; node
  // headers stay free of sim/ types.)
  struct Description {
    std::string kind;
    std::vector<std::pair<std::string, int>> counts;
  };
  virtual Description describeBody() const = 0;
};

// `node` as a collision body, or null when it is none (or null). The one place that
// asks a node whether it is a collision body.
const CollisionBody* asCollisionBody(const SoNode* node);

}  // namespace figment
