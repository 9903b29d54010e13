#pragma once
// Receptors: material points of a membrane, each fixed to (element, xi, eta) of the 6-node
// mesh, so it moves with the membrane whatever the deformation.
//
// Placement (deterministic from the seed): element e gets n_e = density x its reference
// area receptors, rounded down or up with probability the fractional part, so the expected
// total is density x area exactly; within the element they follow the R2 low-discrepancy
// sequence (Roberts 2018: x_k = frac(x_0 + k / phi_2), y_k = frac(y_0 + k / phi_2^2), phi_2
// the plastic number) with a random shift per element, folded onto the parametric triangle.
// That spreads them evenly in (xi, eta), hence evenly in area up to the variation of the
// metric h_s within one element (a few per cent on the icosphere levels). Positions use the
// REFERENCE shape parameters (alpha, beta, gamma) of each element, as the membrane mechanics
// do, so (xi, eta) is a material point in any configuration.
//
// A receptor is a point by default, its force on its element's six nodes with phi_k. Spread
// over patches (spreadOverPatches), receptor r is the weighted mean X_r = sum_i w_i x_i of
// the 7-point quadrature points within rho of its point on the unstressed shape, weights
// w_q h_s (1 - r^2 / rho^2)^2 normalised to 1 (the bump of a tether's foot,
// TetherPlacement.hpp): X_r = sum_k c_k x_k with c_k = sum_i w_i phi_k(i) summed per node, and
// a force F at X_r gives the nodal forces c_k F. Either way sum_k c_k = 1 and sum_k c_k x_k =
// X_r, so the nodal forces add up to F and have its torque about any point.
#include <capsula/mesh/ShapeFunctions.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace capsula::adhesion {

struct Receptor {
  int element;
  double xi;
  double eta;
};

/// A node that carries part of a receptor, and its share.
struct NodeWeight {
  int node;
  double weight;
};

class ReceptorSet {
public:
  /// Places receptors on `mesh` with the unstressed shape `referencePositions` (3 per node).
  /// `stream` tells cells apart (the cell index): two cells with one seed get different
  /// receptors. Throws core::InputError for a negative density or a wrong size.
  ReceptorSet(const mesh::SurfaceMesh& mesh, const std::vector<double>& referencePositions, double density,
              std::uint64_t seed, std::uint64_t stream);

  /// The given receptors (a restart, a test), with the reference shape parameters of `mesh`.
  ReceptorSet(const mesh::SurfaceMesh& mesh, const std::vector<double>& referencePositions,
              std::vector<Receptor> receptors);

  int size() const { return static_cast<int>(receptors_.size()); }
  const Receptor& operator[](int r) const { return receptors_[static_cast<std::size_t>(r)]; }
  const std::vector<Receptor>& receptors() const { return receptors_; }
  /// The reference shape parameters of element e.
  const mesh::ShapeParameters& shapeParameters(int e) const { return parameters_[static_cast<std::size_t>(e)]; }

  /// phi_k at receptor r, k = 0..5 (the weights of its element's nodes).
  void shapeFunctions(int r, double phi[6]) const;
  /// x of receptor r at node positions `positions` (3 per node, the mesh's numbering): its
  /// point, or the weighted mean of its patch.
  mesh::Vec3 position(const mesh::SurfaceMesh& mesh, const double* positions, int r) const;

  /// Makes every receptor the patch of radius `radius` around its point on `referencePositions`
  /// (see above). Throws core::InputError naming `key` for a radius whose patch holds fewer
  /// than three quadrature points for some receptor.
  void spreadOverPatches(const mesh::SurfaceMesh& mesh, const std::vector<double>& referencePositions, double radius,
                         const std::string& key);
  bool patched() const { return !patches_.empty(); }
  /// The nodes of receptor r with their shares c_k (sum 1): with `phi` of its point on its
  /// element's six nodes, or its patch's (see above). `out` is overwritten.
  void nodeWeights(const mesh::SurfaceMesh& mesh, int r, std::vector<NodeWeight>& out) const;

private:
  std::vector<mesh::ShapeParameters> parameters_;
  std::vector<Receptor> receptors_;
  std::vector<std::vector<NodeWeight>> patches_; // per receptor; empty: points
};

} // namespace capsula::adhesion
