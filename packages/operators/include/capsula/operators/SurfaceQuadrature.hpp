#pragma once
// Everything the integral sums read, rebuilt once per geometry update: the regular
// quadrature points of every element of every cell in structure-of-arrays form (eq 3.39),
// and per element its map parameters and a bounding sphere for the near-singular test.
//
// Point q of global element m is q = m * pointsPerElement() + k for rule point k, so the
// points of cell c are one contiguous range. Weights absorb the surface metric:
// weight = w_k h_s, weightedNormal = n w_k h_s, so int_E f dS ~ sum_q weight_q f(x_q).
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/operators/CellSurfaces.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <array>
#include <vector>

namespace capsula::operators {

/// The regular quadrature points of all elements (structure of arrays).
struct QuadraturePoints {
  std::vector<double> x, y, z;    ///< position
  std::vector<double> weight;     ///< w_k h_s
  std::vector<double> nx, ny, nz; ///< n w_k h_s (outward normal)
  std::vector<double> phi;        ///< 6 shape-function values per point: phi[6 q + a]
};

/// Per-element data (structure of arrays where the near-singular test reads it).
struct ElementData {
  std::vector<double> cx, cy, cz; ///< centre of the bounding sphere (node mean)
  std::vector<double> radius;     ///< bounding-sphere radius
  std::vector<double> size;       ///< longest vertex-to-vertex edge
  std::vector<double> area;
  std::vector<mesh::ShapeParameters> shape; ///< alpha, beta, gamma of the current nodes (eq 3.17)
  std::vector<std::array<int, 6>> nodes;    ///< global node numbers
};

class SurfaceQuadrature {
public:
  /// Uses the N_Q-point symmetric rule; throws core::InputError if there is none.
  explicit SurfaceQuadrature(int numQuadraturePoints);

  /// Rebuilds every array from the current positions of `surfaces`.
  void update(const CellSurfaces& surfaces);

  const quadrature::TriangleRule& rule() const { return *rule_; }
  int pointsPerElement() const { return rule_->size(); }
  int numElements() const { return static_cast<int>(elements_.nodes.size()); }
  int numPoints() const { return static_cast<int>(points_.weight.size()); }

  const QuadraturePoints& points() const { return points_; }
  const ElementData& elements() const { return elements_; }
  /// Node positions (3 per node, global numbering) the arrays were built from.
  const std::vector<double>& nodePositions() const { return positions_; }

  /// The six node positions of global element m.
  mesh::ElementNodes elementNodes(int m) const
  {
    return mesh::gatherElementNodes(elements_.nodes[m], positions_.data());
  }

private:
  const quadrature::TriangleRule* rule_;
  QuadraturePoints points_;
  ElementData elements_;
  std::vector<double> positions_;
};

} // namespace capsula::operators
