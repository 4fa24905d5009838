#include "sim/drape/LayerStart.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

namespace figment {

namespace {

constexpr int kSpreadRounds = 8;  // rings of neighbours a move reaches, fading

std::vector<std::vector<int>> neighboursOf(const TriangleMesh& mesh) {
  std::vector<std::set<int>> sets(mesh.vertices.size());
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      sets[size_t(t[size_t(k)])].insert(t[size_t((k + 1) % 3)]);
      sets[size_t(t[size_t((k + 1) % 3)])].insert(t[size_t(k)]);
    }
  std::vector<std::vector<int>> out;
  out.reserve(sets.size());
  for (const std::set<int>& s : sets) out.emplace_back(s.begin(), s.end());
  return out;
}

// The move that takes `p` out over `beneath` to `reach`, or zero where it is past it.
Vec3 moveOut(const Vec3& p, const Collider& beneath, double reach) {
  Contact contact;
  if (!beneath.contact(p, reach, kLayerStartSearch, contact) || contact.distance >= reach) return Vec3::Zero();
  return contact.surfacePoint + reach * contact.normal - p;
}

}  // namespace

LayerStart startOverLayers(const TriangleMesh& garment, const Collider& beneath, double clearance) {
  if (!(clearance > 0.0)) throw std::invalid_argument("layer start: clearance " + std::to_string(clearance));
  const double reach = clearance;
  const size_t n = garment.vertices.size();
  std::vector<Vec3> move(n, Vec3::Zero());
  std::vector<bool> pushed(n, false);
  LayerStart out;
  for (size_t i = 0; i < n; ++i) {
    move[i] = moveOut(garment.vertices[i], beneath, reach);
    pushed[i] = !move[i].isZero();
    out.moved += pushed[i] ? 1 : 0;
  }
  if (out.moved > 0) {
    // Spread: a node not pushed takes the mean of its neighbours' moves; rounds of it reach
    // kSpreadRounds rings out, each ring less.
    const std::vector<std::vector<int>> neighbours = neighboursOf(garment);
    for (int round = 0; round < kSpreadRounds; ++round) {
      std::vector<Vec3> next = move;
      for (size_t i = 0; i < n; ++i) {
        if (pushed[i] || neighbours[i].empty()) continue;
        Vec3 sum = Vec3::Zero();
        for (int j : neighbours[i]) sum += move[size_t(j)];
        next[i] = sum / double(neighbours[i].size());
      }
      move = std::move(next);
    }
  }
  out.positions.resize(n);
  for (size_t i = 0; i < n; ++i) {
    out.positions[i] = garment.vertices[i] + move[i];
    // A spread move may have carried a node near the layers: out over them too.
    out.positions[i] += moveOut(out.positions[i], beneath, reach);
    out.largestMove = std::max(out.largestMove, (out.positions[i] - garment.vertices[i]).norm());
  }
  return out;
}

}  // namespace figment
