#include "sim/progressive/Decimation.h"

#include <algorithm>
#include <queue>

namespace figment {

namespace {
struct QueuedCollapse {
  Collapse collapse;
  int stampKept, stampRemoved;
  bool operator>(const QueuedCollapse& other) const {
    // Ties broken by the vertices, so the order never depends on the queue's internals.
    if (collapse.cost != other.collapse.cost) return collapse.cost > other.collapse.cost;
    if (collapse.kept != other.collapse.kept) return collapse.kept > other.collapse.kept;
    return collapse.removed > other.collapse.removed;
  }
};

class CollapseQueue {
 public:
  CollapseQueue(CollapseNeighbourhood& mesh, CollapseEnergy& energy, size_t vertices)
      : mesh_(mesh), energy_(energy), stamps_(vertices, 0) {}

  void scoreEdgesOf(int v) {
    for (int n : mesh_.ring(v)) {
      const std::optional<Collapse> c = energy_.best(mesh_, std::min(v, n), std::max(v, n));
      if (c) queue_.push({*c, stampOf(c->kept), stampOf(c->removed)});
    }
  }

  // The cheapest collapse still valid, if any.
  std::optional<Collapse> pop() {
    while (!queue_.empty()) {
      const QueuedCollapse top = queue_.top();
      queue_.pop();
      const Collapse& c = top.collapse;
      if (mesh_.active(c.kept) && mesh_.active(c.removed) && top.stampKept == stampOf(c.kept) &&
          top.stampRemoved == stampOf(c.removed))
        return c;
    }
    return std::nullopt;
  }

  void touch(int v) { ++stamps_[v]; }

 private:
  int stampOf(int v) const { return stamps_[v]; }

  CollapseNeighbourhood& mesh_;
  CollapseEnergy& energy_;
  std::vector<int> stamps_;
  std::priority_queue<QueuedCollapse, std::vector<QueuedCollapse>, std::greater<>> queue_;
};

VertexSplit splitUndoing(const CollapseNeighbourhood& mesh, const Collapse& c) {
  VertexSplit split;
  split.kept = c.kept;
  split.added = c.removed;
  split.keptRest = mesh.rest(c.kept);
  split.addedRest = mesh.rest(c.removed);
  split.collapsedRest = c.position;
  for (int f : mesh.edgeFaces(c.kept, c.removed)) split.restored.push_back({f, mesh.corners(f)});
  return split;
}
}  // namespace

ProgressiveMesh decimate(const TriangleMesh& garment, const DecimationOptions& options) {
  ProgressiveMesh out{garment, {}};
  CollapseNeighbourhood mesh(garment);
  CollapseEnergy energy(garment, options);
  CollapseQueue queue(mesh, energy, garment.vertices.size());
  for (int v = 0; v < static_cast<int>(garment.vertices.size()); ++v) queue.scoreEdgesOf(v);
  std::vector<VertexSplit> collapses;  // finest first
  while (mesh.activeFaces() > options.targetFaces) {
    const std::optional<Collapse> c = queue.pop();
    if (!c) break;
    VertexSplit split = splitUndoing(mesh, *c);
    split.repointed = mesh.collapse(c->kept, c->removed, c->position);
    energy.merge(c->kept, c->removed);
    collapses.push_back(std::move(split));
    // Every edge whose candidates saw the changed faces: those of the kept vertex and
    // of its neighbours.
    const std::vector<int> ring = mesh.ring(c->kept);
    queue.touch(c->kept);
    for (int n : ring) queue.touch(n);
    queue.scoreEdgesOf(c->kept);
    for (int n : ring) queue.scoreEdgesOf(n);
  }
  out.splits.assign(collapses.rbegin(), collapses.rend());
  return out;
}

}  // namespace figment
