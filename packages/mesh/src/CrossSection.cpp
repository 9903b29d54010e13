#include <capsula/mesh/CrossSection.hpp>
#include "EdgeKey.hpp"
#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementGeometry.hpp>

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace capsula::mesh {

namespace {

/// Sample points of all elements, each with one global id so that points shared by
/// neighbouring elements (vertices, points along a shared edge) are evaluated and
/// classified once: a shared point can then never be "above" the plane for one
/// element and "below" it for the other, and the cut is a closed curve.
class SampleGrid {
public:
  SampleGrid(const SurfaceMesh& mesh, int k)
      : mesh_(mesh),
        k_(k),
        edgeBase_(mesh.numNodes()),
        interiorBase_(edgeBase_ + mesh.numEdges() * (k - 1)),
        interiorPerElement_((k - 1) * (k - 2) / 2)
  {}

  int size() const { return interiorBase_ + mesh_.numElements() * interiorPerElement_; }

  /// Id of parametric sample (xi, eta) = (i/k, j/k), i + j <= k, of element e.
  int id(int e, int i, int j) const
  {
    const auto& el = mesh_.element(e);
    if (j == 0 && i == 0)
      return el[0];
    if (j == 0 && i == k_)
      return el[1];
    if (i == 0 && j == k_)
      return el[2];
    if (j == 0)
      return alongEdge(e, 0, el[0], i); // edge v0-v1, i steps from v0
    if (i + j == k_)
      return alongEdge(e, 1, el[1], j); // edge v1-v2, j steps from v1
    if (i == 0)
      return alongEdge(e, 2, el[2], k_ - j); // edge v2-v0, k-j steps from v2
    // interior: rows j = 1..k-2, each with i = 1..k-1-j
    int index = 0;
    for (int row = 1; row < j; ++row)
      index += k_ - 1 - row;
    return interiorBase_ + e * interiorPerElement_ + index + (i - 1);
  }

private:
  /// Points along an edge are numbered from the edge's first vertex, the same from
  /// both elements (the quadratic edge curve is the same seen from either side).
  int alongEdge(int e, int localEdge, int from, int steps) const
  {
    const int edgeIndex = mesh_.elementEdge(e, localEdge);
    const int s = mesh_.edge(edgeIndex).vertices[0] == from ? steps : k_ - steps;
    return edgeBase_ + edgeIndex * (k_ - 1) + (s - 1);
  }

  const SurfaceMesh& mesh_;
  int k_;
  int edgeBase_;
  int interiorBase_;
  int interiorPerElement_;
};

double boundingDiameter(const SurfaceMesh& mesh)
{
  const auto x = Eigen::Map<const Eigen::Matrix3Xd>(mesh.positionData(), 3, mesh.numNodes());
  return (x.rowwise().maxCoeff() - x.rowwise().minCoeff()).norm();
}

} // namespace

std::vector<Polyline> crossSection(const SurfaceMesh& mesh, const Vec3& planePoint, const Vec3& planeNormal,
                                   int subdivisions)
{
  core::require<core::InputError>(subdivisions >= 1, "crossSection: subdivisions = ", subdivisions,
                                  " must be at least 1");
  core::require<core::InputError>(planeNormal.norm() > 0.0, "crossSection: the plane normal is zero");
  const Vec3 normal = planeNormal.normalized();
  const int k = subdivisions;
  const SampleGrid grid(mesh, k);

  std::vector<Vec3> samples(grid.size());
  std::vector<double> height(grid.size());
  std::vector<char> evaluated(grid.size(), 0);

  // Crossings of the plane with sample-to-sample segments, and the cut segments
  // joining them (each crossing has at most two neighbours).
  std::unordered_map<std::uint64_t, int> crossingOf;
  std::vector<Vec3> crossings;
  std::vector<std::array<int, 2>> links;
  const auto crossing = [&](int a, int b) {
    const int next = static_cast<int>(crossings.size());
    const auto [it, inserted] = crossingOf.try_emplace(detail::edgeKey(a, b), next);
    if (inserted) {
      // Interpolate from the lower id so both elements compute the same point.
      const int lo = std::min(a, b), hi = std::max(a, b);
      const double t = height[lo] / (height[lo] - height[hi]);
      // A sample on the plane is the crossing itself.
      crossings.push_back(t == 1.0 ? samples[hi] : samples[lo] + t * (samples[hi] - samples[lo]));
      links.push_back({-1, -1});
    }
    return it->second;
  };
  const auto link = [&](int c, int d) {
    for (auto [from, to] : {std::pair{c, d}, std::pair{d, c}}) {
      auto& slot = links[from];
      (slot[0] < 0 ? slot[0] : slot[1]) = to;
    }
  };

  std::vector<int> ids((k + 1) * (k + 1));
  const auto at = [&](int i, int j) { return ids[i * (k + 1) + j]; };
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes x = mesh.elementNodes(e);
    const ShapeParameters p = shapeParameters(x);
    for (int i = 0; i <= k; ++i) {
      for (int j = 0; i + j <= k; ++j) {
        const int id = grid.id(e, i, j);
        ids[i * (k + 1) + j] = id;
        if (!evaluated[id]) {
          samples[id] = surfacePosition(x, p, double(i) / k, double(j) / k);
          height[id] = (samples[id] - planePoint).dot(normal);
          evaluated[id] = 1;
        }
      }
    }
    const auto cut = [&](int a, int b, int c) {
      const int tri[3] = {a, b, c};
      int ends[2];
      int found = 0;
      for (int m = 0; m < 3; ++m) {
        const int u = tri[m], v = tri[(m + 1) % 3];
        // A sample exactly on the plane counts as above it, so every sign change is strict.
        if ((height[u] >= 0.0) != (height[v] >= 0.0)) {
          ends[found++] = crossing(u, v);
        }
      }
      if (found == 2)
        link(ends[0], ends[1]);
    };
    for (int i = 0; i < k; ++i) {
      for (int j = 0; i + j < k; ++j) {
        cut(at(i, j), at(i + 1, j), at(i, j + 1));
        if (i + j < k - 1)
          cut(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
    }
  }

  // Chain the segments: open pieces from their ends first, then the closed loops.
  // Points closer than round-off of the body size are one point.
  const double samePoint = 1e-12 * boundingDiameter(mesh);
  std::vector<Polyline> pieces;
  std::vector<char> used(crossings.size(), 0);
  const auto walk = [&](int start) {
    Polyline line;
    int previous = -1, current = start;
    while (current >= 0 && !used[current]) {
      used[current] = 1;
      const Vec3& point = crossings[current];
      // A sample on (or within round-off of) the plane makes several crossings at one
      // point: keep one.
      if (line.points.empty() || (point - line.points.back()).norm() > samePoint) {
        line.points.push_back(point);
      }
      const auto& next = links[current];
      const int step = next[0] != previous ? next[0] : next[1];
      previous = current;
      current = step;
    }
    line.closed = current == start;
    if (line.closed && line.points.size() > 1 && (line.points.front() - line.points.back()).norm() <= samePoint) {
      line.points.pop_back();
    }
    // Counter-clockwise about the plane normal.
    Vec3 twiceArea = Vec3::Zero();
    for (std::size_t m = 0; m < line.points.size(); ++m) {
      twiceArea += line.points[m].cross(line.points[(m + 1) % line.points.size()]);
    }
    if (twiceArea.dot(normal) < 0.0)
      std::reverse(line.points.begin(), line.points.end());
    pieces.push_back(std::move(line));
  };
  const int numCrossings = static_cast<int>(crossings.size());
  for (int c = 0; c < numCrossings; ++c) {
    if (!used[c] && links[c][1] < 0)
      walk(c);
  }
  for (int c = 0; c < numCrossings; ++c) {
    if (!used[c])
      walk(c);
  }
  return pieces;
}

} // namespace capsula::mesh
