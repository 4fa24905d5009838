#include "sim/pattern/PatternCutting.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "sim/pattern/EdgeCurves.h"
#include "sim/pattern/PanelMesh.h"

namespace figment {

namespace {

std::string panelText(const Panel& panel, int index) {
  return "panel " + std::to_string(index) + " ('" + panel.name + "')";
}

void checkSpacing(double spacing) {
  if (!(spacing > 0.0) || !std::isfinite(spacing)) {
    throw std::invalid_argument("cutPattern: spacing " + std::to_string(spacing) + " m, must be positive");
  }
}

// Each panel's edges form one loop over its vertices: what sampling and meshing assume.
void checkPanel(const Panel& panel, int index) {
  const int vertexCount = static_cast<int>(panel.vertices.size());
  const int edgeCount = static_cast<int>(panel.edges.size());
  if (edgeCount < 2) {
    throw std::invalid_argument("cutPattern: " + panelText(panel, index) + " has " + std::to_string(edgeCount) +
                                " edges, needs a closed loop");
  }
  for (int k = 0; k < edgeCount; ++k) {
    const PanelEdge& edge = panel.edges[k];
    if (edge.from < 0 || edge.from >= vertexCount || edge.to < 0 || edge.to >= vertexCount) {
      throw std::invalid_argument("cutPattern: " + panelText(panel, index) + " edge " + std::to_string(k) +
                                  " joins vertices " + std::to_string(edge.from) + " and " + std::to_string(edge.to) +
                                  " of " + std::to_string(vertexCount));
    }
    if (edge.to != panel.edges[(k + 1) % edgeCount].from) {
      throw std::invalid_argument("cutPattern: " + panelText(panel, index) + " edge " + std::to_string(k) +
                                  " ends at vertex " + std::to_string(edge.to) + ", not where edge " +
                                  std::to_string((k + 1) % edgeCount) + " starts");
    }
  }
  // A reflection would turn the right side in; 1e-6 allows angles read from a file.
  const Eigen::Matrix3d& r = panel.rotation;
  if (!r.allFinite() || !(r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-6) || r.determinant() < 0.0) {
    throw std::invalid_argument("cutPattern: " + panelText(panel, index) + " placement is not a rotation");
  }
  if (!panel.translation.allFinite()) {
    throw std::invalid_argument("cutPattern: " + panelText(panel, index) + " translation is not finite");
  }
}

void checkStitch(const SewingPattern& pattern, int index) {
  const Stitch& stitch = pattern.stitches[index];
  for (const EdgeRef& ref : {stitch.first, stitch.second}) {
    if (ref.panel < 0 || ref.panel >= static_cast<int>(pattern.panels.size())) {
      throw std::invalid_argument("cutPattern: stitch " + std::to_string(index) + " names panel " +
                                  std::to_string(ref.panel) + " of " + std::to_string(pattern.panels.size()));
    }
    const Panel& panel = pattern.panels[ref.panel];
    if (ref.edge < 0 || ref.edge >= static_cast<int>(panel.edges.size())) {
      throw std::invalid_argument("cutPattern: stitch " + std::to_string(index) + " names edge " +
                                  std::to_string(ref.edge) + " of " + panelText(panel, ref.panel) + ", which has " +
                                  std::to_string(panel.edges.size()));
    }
  }
  if (stitch.first.panel == stitch.second.panel && stitch.first.edge == stitch.second.edge) {
    throw std::invalid_argument("cutPattern: stitch " + std::to_string(index) + " sews edge " +
                                std::to_string(stitch.first.edge) + " of " +
                                panelText(pattern.panels[stitch.first.panel], stitch.first.panel) + " to itself");
  }
}

void checkPattern(const SewingPattern& pattern) {
  for (int p = 0; p < static_cast<int>(pattern.panels.size()); ++p) checkPanel(pattern.panels[p], p);
  for (int s = 0; s < static_cast<int>(pattern.stitches.size()); ++s) checkStitch(pattern, s);
}

double signedArea(const std::vector<Vec2>& points, int count) {
  double twice = 0.0;
  for (int i = 0; i < count; ++i) {
    const Vec2& a = points[i];
    const Vec2& b = points[(i + 1) % count];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

}  // namespace

std::vector<std::vector<int>> edgeSegments(const SewingPattern& pattern, double spacing) {
  checkSpacing(spacing);
  checkPattern(pattern);
  // Edges numbered across panels; stitched edges joined into groups (union-find), so an
  // edge sewn to two others shares one count with both.
  std::vector<int> first(pattern.panels.size() + 1, 0);
  for (size_t p = 0; p < pattern.panels.size(); ++p) {
    first[p + 1] = first[p] + static_cast<int>(pattern.panels[p].edges.size());
  }
  std::vector<int> group(first.back());
  std::iota(group.begin(), group.end(), 0);
  auto root = [&](int e) {
    while (group[e] != e) e = group[e] = group[group[e]];
    return e;
  };
  for (const Stitch& stitch : pattern.stitches) {
    group[root(first[stitch.first.panel] + stitch.first.edge)] = root(first[stitch.second.panel] + stitch.second.edge);
  }

  std::vector<int> count(first.back());
  for (size_t p = 0; p < pattern.panels.size(); ++p) {
    for (size_t k = 0; k < pattern.panels[p].edges.size(); ++k) {
      const double length = edgeLength(pattern.panels[p], static_cast<int>(k));
      // 1e-9: an edge exactly n spacings long is n segments, whatever its rounding.
      count[first[p] + k] = std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
    }
  }
  std::vector<int> groupCount(first.back(), 0);
  for (int e = 0; e < first.back(); ++e) groupCount[root(e)] = std::max(groupCount[root(e)], count[e]);

  std::vector<std::vector<int>> segments(pattern.panels.size());
  for (size_t p = 0; p < pattern.panels.size(); ++p) {
    for (size_t k = 0; k < pattern.panels[p].edges.size(); ++k) {
      segments[p].push_back(groupCount[root(first[p] + static_cast<int>(k))]);
    }
  }
  return segments;
}

UnsewnGarment cutPattern(const SewingPattern& pattern, double spacing) {
  const std::vector<std::vector<int>> segments = edgeSegments(pattern, spacing);
  UnsewnGarment garment;
  std::vector<std::vector<std::vector<int>>> edgeNodes(pattern.panels.size());  // global node indices
  for (int p = 0; p < static_cast<int>(pattern.panels.size()); ++p) {
    const Panel& panel = pattern.panels[p];
    std::vector<std::vector<Vec2>> outline;
    for (int k = 0; k < static_cast<int>(panel.edges.size()); ++k)
      outline.push_back(sampleEdge(panel, k, segments[p][k]));
    PanelMesh mesh;
    try {
      mesh = meshPanel(outline, spacing);
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument("cutPattern: " + panelText(panel, p) + ": " + error.what());
    }

    const int offset = static_cast<int>(garment.flat.size());
    for (const Vec2& point : mesh.points) {
      garment.flat.push_back(point);
      garment.panelOf.push_back(p);
      garment.placed.vertices.push_back(panel.rotation * Vec3(point.x(), point.y(), 0.0) + panel.translation);
    }
    // meshPanel's triangles run counter-clockwise in (u, v); a clockwise outline has its
    // right side the other way (see the header).
    const bool flip = signedArea(mesh.points, mesh.outlineCount) < 0.0;
    for (const auto& t : mesh.triangles) {
      garment.placed.triangles.push_back(flip ? Triangle{offset + t[0], offset + t[2], offset + t[1]}
                                              : Triangle{offset + t[0], offset + t[1], offset + t[2]});
    }
    for (auto& nodes : mesh.edgeNodes) {
      for (int& node : nodes) node += offset;
      edgeNodes[p].push_back(std::move(nodes));
    }
    garment.panelNames.push_back(panel.name);
  }

  for (int s = 0; s < static_cast<int>(pattern.stitches.size()); ++s) {
    const Stitch& stitch = pattern.stitches[s];
    const std::vector<int>& a = edgeNodes[stitch.first.panel][stitch.first.edge];
    const std::vector<int>& b = edgeNodes[stitch.second.panel][stitch.second.edge];
    const int n = static_cast<int>(a.size()) - 1;  // == b.size() - 1: edgeSegments gave both one count
    for (int k = 0; k <= n; ++k) {
      const int partner = b[stitch.sameDirection ? k : n - k];
      if (a[k] == partner) continue;
      garment.seams.push_back({a[k], partner});
      garment.seamStitch.push_back(s);
    }
  }
  return garment;
}

}  // namespace figment
