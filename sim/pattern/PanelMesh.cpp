// Based on:
// - A. Ogre, CDT: constrained Delaunay triangulation (github.com/artem-ogre/CDT, 2.0.1):
//   the triangulation with the outline as constraint edges, and the even-odd erasure of
//   the triangles outside it.
// - DistMesh's initial points (P.-O. Persson & G. Strang, "A simple mesh generator in
//   MATLAB", SIAM Review 46(2), 2004): an equilateral lattice, the points outside the
//   region dropped; here also those within h/2 of the outline, and no smoothing after (the
//   outline's points must stay where they are, and the lattice is equilateral already).
#include "sim/pattern/PanelMesh.h"

#include <CDT.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace figment {

namespace {

// m: two outline points closer than this are one point (edges' shared ends, which
// sampling computes from the same vertex).
constexpr double kJoinTolerance = 1e-9;

std::string pointText(const Vec2& p) {
  std::ostringstream text;
  text << "(" << p.x() << ", " << p.y() << ")";
  return text.str();
}

double squaredDistanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).squaredNorm();
}

// The outline as one loop of points, and each edge's nodes along it.
void joinEdges(const std::vector<std::vector<Vec2>>& edges, PanelMesh& mesh) {
  mesh.edgeNodes.resize(edges.size());
  for (size_t k = 0; k < edges.size(); ++k) {
    const std::vector<Vec2>& edge = edges[k];
    if (edge.size() < 2) {
      throw std::invalid_argument("meshPanel: edge " + std::to_string(k) + " has " + std::to_string(edge.size()) +
                                  " points, needs at least 2");
    }
    const std::vector<Vec2>& next = edges[(k + 1) % edges.size()];
    if (next.empty() || (edge.back() - next.front()).norm() > kJoinTolerance) {
      throw std::invalid_argument("meshPanel: edge " + std::to_string(k) + " ends at " + pointText(edge.back()) +
                                  ", not where edge " + std::to_string((k + 1) % edges.size()) + " starts");
    }
    for (size_t i = 0; i + 1 < edge.size(); ++i) {
      mesh.edgeNodes[k].push_back(static_cast<int>(mesh.points.size()));
      mesh.points.push_back(edge[i]);
    }
  }
  const int count = static_cast<int>(mesh.points.size());
  for (size_t k = 0; k < edges.size(); ++k) {
    mesh.edgeNodes[k].push_back(k + 1 < edges.size() ? mesh.edgeNodes[k + 1].front() : 0);
  }
  if (count < 3) {
    throw std::invalid_argument("meshPanel: the outline has " + std::to_string(count) + " points, needs at least 3");
  }
  mesh.outlineCount = count;
}

// Lattice nodes inside the outline (points[0, n) as a closed loop) and at least h/2 from
// it: rows h sqrt(3)/2 apart, every other row shifted by h/2. Each row is cut by the
// outline (even-odd crossings) and measured against only the segments within h/2 of it.
void addLattice(double h, PanelMesh& mesh) {
  const int n = mesh.outlineCount;
  Vec2 low = mesh.points[0], high = mesh.points[0];
  for (int i = 0; i < n; ++i) {
    low = low.cwiseMin(mesh.points[i]);
    high = high.cwiseMax(mesh.points[i]);
  }
  const double rowStep = h * std::sqrt(3.0) / 2.0;
  const double clearance2 = 0.25 * h * h;
  std::vector<double> crossings;
  std::vector<int> near;
  for (int row = 0; low.y() + row * rowStep <= high.y(); ++row) {
    const double y = low.y() + row * rowStep;
    crossings.clear();
    near.clear();
    for (int i = 0; i < n; ++i) {
      const Vec2& a = mesh.points[i];
      const Vec2& b = mesh.points[(i + 1) % n];
      if ((a.y() <= y) != (b.y() <= y)) crossings.push_back(a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
      if (std::min(a.y(), b.y()) - 0.5 * h <= y && y <= std::max(a.y(), b.y()) + 0.5 * h) near.push_back(i);
    }
    std::sort(crossings.begin(), crossings.end());
    const double shift = (row % 2) * 0.5 * h;
    for (size_t c = 0; c + 1 < crossings.size(); c += 2) {
      for (double x = low.x() + shift + std::ceil((crossings[c] - low.x() - shift) / h) * h; x < crossings[c + 1];
           x += h) {
        const Vec2 p(x, y);
        const bool clear = std::all_of(near.begin(), near.end(), [&](int i) {
          return squaredDistanceToSegment(p, mesh.points[i], mesh.points[(i + 1) % n]) >= clearance2;
        });
        if (clear) mesh.points.push_back(p);
      }
    }
  }
}

}  // namespace

PanelMesh meshPanel(const std::vector<std::vector<Vec2>>& edges, double spacing) {
  if (!(spacing > 0.0) || !std::isfinite(spacing)) {
    throw std::invalid_argument("meshPanel: spacing " + std::to_string(spacing) + " m, must be positive");
  }
  if (edges.empty()) throw std::invalid_argument("meshPanel: the outline has no edges");
  PanelMesh mesh;
  joinEdges(edges, mesh);
  addLattice(spacing, mesh);

  // AsProvided would be slower on large panels; CDT keeps the vertices' indices whatever
  // the order it inserts them in. NotAllowed: an outline that crosses itself is an error,
  // never a point CDT adds.
  CDT::Triangulation<double> cdt(CDT::VertexInsertionOrder::Auto, CDT::IntersectingConstraintEdges::NotAllowed, 0.0);
  std::vector<CDT::Edge> outline;
  const int n = mesh.outlineCount;
  for (int i = 0; i < n; ++i) outline.emplace_back(i, (i + 1) % n);
  try {
    cdt.insertVertices(
        mesh.points.begin(), mesh.points.end(), [](const Vec2& p) { return p.x(); },
        [](const Vec2& p) { return p.y(); });
    cdt.insertEdges(outline);
    cdt.eraseOuterTrianglesAndHoles();
  } catch (const CDT::Error& error) {
    throw std::invalid_argument("meshPanel: the outline touches or crosses itself (" + error.description() + ")");
  }
  // A segment CDT had to split (an outline point lying on another segment) is no longer a
  // triangle's edge: the outline touches itself there.
  if (cdt.vertices.size() != mesh.points.size()) {
    throw std::invalid_argument("meshPanel: the outline touches itself (" +
                                std::to_string(cdt.vertices.size() - mesh.points.size()) + " points added)");
  }
  const CDT::EdgeUSet triangleEdges = CDT::extractEdgesFromTriangles(cdt.triangles);
  for (const CDT::Edge& segment : outline) {
    if (!triangleEdges.count(segment)) {
      throw std::invalid_argument("meshPanel: the outline touches itself at " + pointText(mesh.points[segment.v1()]));
    }
  }
  if (cdt.triangles.empty()) throw std::invalid_argument("meshPanel: the outline encloses no area");
  mesh.triangles.reserve(cdt.triangles.size());
  for (const CDT::Triangle& triangle : cdt.triangles) {  // counter-clockwise, as CDT makes them
    mesh.triangles.push_back({static_cast<int>(triangle.vertices[0]), static_cast<int>(triangle.vertices[1]),
                              static_cast<int>(triangle.vertices[2])});
  }
  return mesh;
}

}  // namespace figment
